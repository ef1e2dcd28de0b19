#include "support/diagnostics.h"

#include <fmt/format.h>

#include <algorithm>

namespace clpost {

void Diagnostics::error(SourceLoc loc, std::string_view line_text, std::string message) {
  add(Severity::kError, loc, line_text, std::move(message));
}
void Diagnostics::warning(SourceLoc loc, std::string_view line_text, std::string message) {
  add(Severity::kWarning, loc, line_text, std::move(message));
}
void Diagnostics::note(SourceLoc loc, std::string_view line_text, std::string message) {
  add(Severity::kNote, loc, line_text, std::move(message));
}

void Diagnostics::add(Severity severity, SourceLoc loc, std::string_view line_text,
                      std::string message) {
  if (severity == Severity::kWarning && werror_) severity = Severity::kError;
  if (severity == Severity::kError) ++errors_;
  if (severity == Severity::kWarning) ++warnings_;
  if (kept_.size() >= kMaxKept) {
    ++dropped_;
    return;
  }
  // A caret display of a huge line is useless and costly: keep a window of kMaxExcerpt
  // characters, with the column about 80 characters into it when it lies further out.
  size_t start = 0;
  bool cut_after = false;
  if (line_text.size() > kMaxExcerpt) {
    constexpr size_t kLeadIn = 80;
    if (loc.col > kLeadIn + 1 && !binary_records_)  // binary: col is a byte offset
      start = std::min<size_t>(loc.col - 1 - kLeadIn, line_text.size() - kMaxExcerpt);
    cut_after = start + kMaxExcerpt < line_text.size();
    line_text = line_text.substr(start, kMaxExcerpt);
  }
  kept_.push_back(Diagnostic{severity, loc, std::move(message), std::string(line_text),
                             static_cast<uint32_t>(start + 1), cut_after});
}

std::string_view severity_name(Severity s) {
  switch (s) {
    case Severity::kNote:
      return "note";
    case Severity::kWarning:
      return "warning";
    case Severity::kError:
      return "error";
  }
  return "error";
}

std::string Diagnostics::render(const Diagnostic& d) const {
  std::string out;
  if (binary_records_ && d.loc.line != 0) {
    out = d.loc.col == 0
              ? fmt::format("{}: record {}: ", file_, d.loc.line)
              : fmt::format("{}: record {} (byte {}): ", file_, d.loc.line, d.loc.col - 1);
    out += fmt::format("{}: {}\n", severity_name(d.severity), d.message);
    if (!d.line_text.empty()) out += fmt::format("  {}{}\n", d.line_text, d.cut_after ? "..." : "");
    return out;
  }
  if (d.loc.line == 0) {
    out = fmt::format("{}: {}: {}\n", file_, severity_name(d.severity), d.message);
  } else if (d.loc.col == 0) {
    out = fmt::format("{}:{}: {}: {}\n", file_, d.loc.line, severity_name(d.severity), d.message);
  } else {
    out = fmt::format("{}:{}:{}: {}: {}\n", file_, d.loc.line, d.loc.col, severity_name(d.severity),
                      d.message);
  }
  if (!d.line_text.empty()) {
    // A window of a long line is marked "..." at the end it was cut.
    const std::string_view before = d.first_col > 1 ? "..." : "";
    out += "  ";
    out += before;
    // Tabs stay tabs so that the caret line lines up under them.
    for (char c : d.line_text) out += (c == '\r' || c == '\n' || c == '\0') ? ' ' : c;
    if (d.cut_after) out += "...";
    out += '\n';
    if (d.loc.col >= d.first_col) {
      out += "  ";
      out.append(before.size(), ' ');
      for (uint32_t i = 1; i < d.loc.col - d.first_col + 1 && i <= d.line_text.size(); ++i)
        out += d.line_text[i - 1] == '\t' ? '\t' : ' ';
      out += "^\n";
    }
  }
  return out;
}

std::string Diagnostics::render_all() const {
  std::string out;
  for (const Diagnostic& d : kept_) out += render(d);
  if (dropped_ > 0)
    out += fmt::format("{}: note: {} more diagnostics not shown\n", file_, dropped_);
  return out;
}

}  // namespace clpost

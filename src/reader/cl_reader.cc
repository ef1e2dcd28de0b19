#include "reader/cl_reader.h"

#include <fmt/format.h>

#include <algorithm>
#include <vector>

#include "reader/cldata_reader.h"
#include "reader/continuation.h"
#include "reader/lexer.h"
#include "reader/line_source.h"
#include "reader/plain_line.h"

namespace clpost {

using reader::LineSource;
using reader::StatementLexer;
using Status = LineSource::Status;

namespace {

// NX "Information listing" output: a header of tab-separated lines up to a blank line, and a
// last line `Tool Path Listing has N lines.`.
constexpr std::string_view kNxHeader = "Information listing created by";
constexpr std::string_view kNxTrailer = "Tool Path Listing has ";

bool is_nx_trailer(std::string_view line) {
  while (!line.empty() && reader::is_blank_char(line.back())) line.remove_suffix(1);
  return line.starts_with(kNxTrailer) && line.ends_with(" lines.");
}

uint32_t first_column(std::string_view line) {
  size_t i = 0;
  while (i < line.size() && reader::is_blank_char(line[i])) ++i;
  return static_cast<uint32_t>(i == line.size() ? 1 : i + 1);
}

}  // namespace

struct ClReader::Impl {
  Impl(std::FILE* in, Diagnostics& d) : src(in), diags(d), in(in) {}
  Impl(std::string_view text, Diagnostics& d) : src(text), diags(d), text(text) {}

  bool next(Statement& out);
  bool read_statement(Statement& out);
  bool skip_non_statement(const LineSource::Line& first, Status s);
  bool lex_statement(Statement& out, bool is_text);
  bool read_continuations(const LineSource::Line& first, bool continues, bool is_text);
  void skip_comment(bool continues);
  void skip_statement(bool continues, bool is_text);
  void skip_header(const LineSource::Line& info);
  void too_long(const LineSource::Line& first);
  void error(SourceLoc loc, std::string_view line, std::string message);
  void fail(Status s);
  bool to_binary();
  bool stray_nul(const LineSource::Line& l);

  LineSource src;
  Diagnostics& diags;
  StatementLexer lexer;
  std::vector<LineSource::Line> lines;  // of the statement being read
  size_t errors = 0;
  bool done = false;
  bool gave_up = false;  // done before the end of the input
  bool at_start = true;  // no non-blank line seen yet
  // Binary CLDATA (cldata_reader.h), detected from the first bytes, is read by `binary`.
  std::FILE* in = nullptr;
  std::string_view text;
  std::unique_ptr<CldataReader> binary;
};

void ClReader::Impl::error(SourceLoc loc, std::string_view line, std::string message) {
  diags.error(loc, line, std::move(message));
  if (++errors >= kMaxErrors && !done) {
    diags.note(SourceLoc{}, {}, "too many errors, stopping");
    done = true;
    gave_up = true;
  }
}

// Binary CLDATA, known from the input's first bytes: `binary` reads it from the start.
bool ClReader::Impl::to_binary() {
  const cldata::Layout* layout = nullptr;
  if (src.line_number() > 1 || (layout = cldata::detect_layout(src.head())) == nullptr)
    return false;
  binary = in ? std::make_unique<CldataReader>(*layout, src.head(), in, diags)
              : std::make_unique<CldataReader>(*layout, text, diags);
  done = true;
  return true;
}

// A NUL byte in a line of a text file: an error at its line and column, the statement skipped.
bool ClReader::Impl::stray_nul(const LineSource::Line& l) {
  const std::string_view t = src.text(l);
  const size_t at = t.find('\0');
  if (at == std::string_view::npos) return false;
  error(SourceLoc{l.number, static_cast<uint32_t>(at + 1)}, t,
        "NUL byte in a text file; the statement is skipped");
  return true;
}

void ClReader::Impl::fail(Status s) {
  if (s == Status::kBinary && to_binary()) return;
  if (s == Status::kBinary) {
    error(SourceLoc{}, {},
          fmt::format("not a CL text file (binary data at byte {})", src.binary_offset()));
  } else if (s == Status::kReadError) {
    error(SourceLoc{}, {}, "error reading input: " + src.read_error());
  }
  done = true;
  gave_up = true;
}

bool ClReader::Impl::next(Statement& out) {
  while (!done) {
    src.mark();
    // Most lines: a plain record, read and lexed in one pass (the same result as below).
    if (!at_start) {
      reader::PlainLine plain;
      if (reader::lex_plain_line(src.buffered(), src.line_number() + 1, out, plain) &&
          plain.size <= kMaxStatementBytes) {
        src.consume_line(plain.size, plain.terminator);
        return true;
      }
    }
    if (read_statement(out)) return true;
  }
  return false;
}

// The line by line path: the input's start, comments, continuation lines, errors. False when
// what was read is no statement (skipped, reported, or the end of the input: `done`).
bool ClReader::Impl::read_statement(Statement& out) {
  LineSource::Line first;
  const Status s = src.next_line(kMaxStatementBytes, first);
  if (s == Status::kEnd) {
    done = true;
    return false;
  }
  if (s != Status::kLine && s != Status::kTooLong) {
    fail(s);
    return false;
  }
  if (skip_non_statement(first, s)) return false;
  out.first_line = first.number;
  const std::string_view text = src.text(first);
  const bool is_text = StatementLexer::is_text_statement(text);
  bool continues = false;
  if (is_text) {
    continues = reader::comment_continues(text);
  } else {
    reader::code_part(text, &continues);
  }
  if (!read_continuations(first, continues, is_text)) return false;
  if (std::any_of(lines.begin(), lines.end(), [&](const auto& l) { return stray_nul(l); }))
    return false;
  return lex_statement(out, is_text);
}

// True when the first line starts no statement, and it (with what belongs to it) has been dealt
// with: a blank line, binary CLDATA, the NX header or trailer, a comment and its continuations,
// a statement too long (reported).
bool ClReader::Impl::skip_non_statement(const LineSource::Line& first, Status s) {
  const std::string_view text = src.text(first);      // kTooLong: its first bytes
  if (first.number == 1 && to_binary()) return true;  // binary CLDATA that looks like text
  if (at_start && s == Status::kLine) {
    if (reader::is_blank_line(text)) return true;
    at_start = false;
    if (first.number <= 2 && text.starts_with(kNxHeader)) {
      skip_header(first);
      return true;
    }
  }
  at_start = false;
  if (reader::is_comment_line(text)) {
    skip_comment(s == Status::kTooLong ? src.skip_line().comment_continues()
                                       : reader::comment_continues(text));
    return true;
  }
  if (s == Status::kTooLong) {
    too_long(first);
    return true;
  }
  return reader::is_blank_line(text) || is_nx_trailer(text);
}

// The statement's lines (`lines`) lexed into `out`; false for an empty statement or an error
// (reported).
bool ClReader::Impl::lex_statement(Statement& out, bool is_text) {
  out.lines.clear();
  for (const LineSource::Line& l : lines) out.lines.push_back(src.text(l));
  if (is_text) {
    lexer.lex_text(out);
    return true;
  }
  StatementLexer::Error err;
  switch (lexer.lex_code(out, err)) {
    case StatementLexer::Result::kOk:
      return true;
    case StatementLexer::Result::kEmpty:
      break;
    case StatementLexer::Result::kError:
      error(err.loc, out.line_text(err.loc.line), std::move(err.message));
      break;
  }
  return false;
}

// Collects the statement's lines in `lines`. False when it cannot be used (too long, input
// failed), already reported.
bool ClReader::Impl::read_continuations(const LineSource::Line& first, bool continues,
                                        bool is_text) {
  lines.clear();
  lines.push_back(first);
  size_t used = first.size;
  while (continues) {
    LineSource::Line l;
    const Status s = src.next_line(kMaxStatementBytes - used, l);
    if (s == Status::kEnd) break;
    if (s == Status::kTooLong) {
      too_long(first);
      return false;
    }
    if (s != Status::kLine) {
      fail(s);
      return false;
    }
    lines.push_back(l);
    used += l.size;
    if (is_text) {
      continues = reader::comment_continues(src.text(l));
    } else {
      reader::code_part(src.text(l), &continues);
    }
  }
  return true;
}

// Reports a statement longer than kMaxStatementBytes at its first line and skips the rest of
// it, from the line the reader stopped at (not yet consumed), without keeping it.
void ClReader::Impl::too_long(const LineSource::Line& first) {
  const std::string_view text = src.text(first);
  error(SourceLoc{first.number, first_column(text)}, text,
        fmt::format("statement too long (more than {} bytes)", kMaxStatementBytes));
  const bool is_text = StatementLexer::is_text_statement(text);
  const reader::LineTail tail = src.skip_line();
  skip_statement(is_text ? tail.comment_continues() : tail.code_continues(), is_text);
}

void ClReader::Impl::skip_statement(bool continues, bool is_text) {
  while (continues && !done) {
    src.mark();
    LineSource::Line l;
    const Status s = src.next_line(0, l);  // any line but an empty one is "too long"
    if (s == Status::kEnd) return;
    if (s == Status::kLine) return;  // an empty line ends the statement
    if (s != Status::kTooLong) return fail(s);
    const reader::LineTail tail = src.skip_line();
    continues = is_text ? tail.comment_continues() : tail.code_continues();
  }
}

void ClReader::Impl::skip_comment(bool continues) {
  while (continues && !done) {
    src.mark();
    LineSource::Line l;
    const Status s = src.next_line(kMaxStatementBytes, l);
    if (s == Status::kEnd) return;
    if (s == Status::kTooLong) {
      continues = src.skip_line().comment_continues();
    } else if (s == Status::kLine) {
      continues = reader::comment_continues(src.text(l));
    } else {
      return fail(s);
    }
  }
}

void ClReader::Impl::skip_header(const LineSource::Line& info) {
  uint32_t last = info.number;
  while (!done) {
    src.mark();
    LineSource::Line l;
    const Status s = src.next_line(kMaxStatementBytes, l);
    if (s == Status::kEnd) break;
    if (s == Status::kTooLong) {
      src.skip_line();
      last = l.number;
      continue;
    }
    if (s != Status::kLine) return fail(s);
    const std::string_view text = src.text(l);
    if (!reader::is_blank_line(text) && text.find('\t') == std::string_view::npos) {
      src.unread(l);  // not a header line: CL starts here
      break;
    }
    last = l.number;
    if (reader::is_blank_line(text)) break;
  }
  diags.note(SourceLoc{info.number, 0}, {},
             fmt::format("skipped NX information listing header ({} lines)", last));
}

ClReader::ClReader(std::FILE* in, Diagnostics& diags) : impl_(std::make_unique<Impl>(in, diags)) {}
ClReader::ClReader(std::string_view text, Diagnostics& diags)
    : impl_(std::make_unique<Impl>(text, diags)) {}
ClReader::~ClReader() = default;

bool ClReader::next(Statement& out) {
  if (!impl_->binary && impl_->next(out)) return true;
  return impl_->binary && impl_->binary->next(out);
}
size_t ClReader::bytes_read() const {
  return impl_->binary ? impl_->binary->bytes_read() : impl_->src.bytes_read();
}
uint32_t ClReader::line() const {
  return impl_->binary ? impl_->binary->record() : impl_->src.line_number();
}
bool ClReader::gave_up() const {
  return impl_->binary ? impl_->binary->gave_up() : impl_->gave_up;
}

}  // namespace clpost

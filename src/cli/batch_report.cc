#include "cli/batch_report.h"

#include <fmt/format.h>

#include <iterator>

#include "support/json_text.h"

namespace clpost {

namespace {

// {"seconds": total, "rapids_timed": bool, "tools": [{"tool", "offset", "seconds", "text"}]}
std::string cycle_time_json(const CycleTime& t) {
  std::string o = fmt::format("{{\"seconds\": {:.3f}, \"rapids_timed\": {}, \"tools\": [",
                              t.total(), t.rapids_untimed ? "false" : "true");
  bool first = true;
  for (const ToolTime& tt : t.tools) {
    if (tt.tool < 0 && tt.seconds == 0) continue;
    o += fmt::format("{}{{\"tool\": {}, \"offset\": {}, \"seconds\": {:.3f}, \"text\": {}}}",
                     first ? "" : ", ", tt.tool, tt.offset, tt.seconds, json_string(tt.text));
    first = false;
  }
  return o + "]}";
}

}  // namespace

const char* status_name(FileStatus s) {
  switch (s) {
    case FileStatus::kOk:
      return "ok";
    case FileStatus::kWarnings:
      return "warnings";
    case FileStatus::kError:
      return "error";
    case FileStatus::kNotPosted:
      return "not-posted";
  }
  return "error";
}

std::string batch_report_json(const BatchReportInfo& info, const BatchSummary& s,
                              const std::vector<FileResult>& results) {
  std::string o;
  auto out = std::back_inserter(o);
  fmt::format_to(out, "{{\n  \"machine\": {},\n  \"output_dir\": {},\n  \"jobs\": {},\n",
                 json_string(info.machine), json_string(info.output_dir), info.jobs);
  fmt::format_to(
      out,
      "  \"summary\": {{\"files\": {}, \"ok\": {}, \"with_warnings\": {}, \"failed\": {}, "
      "\"not_posted\": {}, \"errors\": {}, \"warnings\": {}, \"bytes_in\": {}, "
      "\"bytes_out\": {}, \"seconds\": {:.6f}}},\n",
      s.files, s.ok, s.with_warnings, s.failed, s.not_posted, s.errors, s.warnings, s.bytes_in,
      s.bytes_out, s.seconds);
  o += "  \"files\": [";
  for (size_t i = 0; i < results.size(); ++i) {
    const FileResult& r = results[i];
    const PostOutcome& p = r.outcome;
    const bool written = r.status == FileStatus::kOk || r.status == FileStatus::kWarnings;
    fmt::format_to(out,
                   "{}\n    {{\"input\": {}, \"output\": {}, \"status\": \"{}\", \"errors\": {}, "
                   "\"warnings\": {}, \"statements\": {}, \"motions\": {}, \"threads\": {}, "
                   "\"passes\": {}, \"bytes_in\": {}, \"bytes_out\": {}, \"seconds\": {:.6f}, "
                   "\"cycle_time\": {}, \"sheet\": {}, \"diagnostics\": [",
                   i ? "," : "", json_string(r.item.input),
                   written ? json_string(r.item.output) : std::string("null"),
                   status_name(r.status), p.errors, p.warnings, p.stats.statements, p.stats.motions,
                   p.stats.threads, p.stats.passes, p.bytes_in, written ? p.bytes_out : 0,
                   r.seconds, written ? cycle_time_json(p.cycle_time) : std::string("null"),
                   written && !r.sheet.empty() ? json_string(r.sheet) : std::string("null"));
    for (size_t k = 0; k < p.kept.size(); ++k) {
      const Diagnostic& d = p.kept[k];
      fmt::format_to(out,
                     "{}\n      {{\"severity\": \"{}\", \"line\": {}, \"column\": {}, "
                     "\"message\": {}}}",
                     k ? "," : "", severity_name(d.severity), d.loc.line, d.loc.col,
                     json_string(d.message));
    }
    o += p.kept.empty() ? "]}" : "\n    ]}";
  }
  o += results.empty() ? "]\n}\n" : "\n  ]\n}\n";
  return o;
}

}  // namespace clpost

// The library's entry point (post.h).
#include "interpreter/post.h"

#include <fmt/format.h>

#include <algorithm>
#include <filesystem>

#include "interpreter/interpreter.h"
#include "writer/nc_program.h"

namespace clpost {

namespace {

// The machine's program_header: the header lines, the template once per line.
std::string header_text(const Machine& m, const PostSummary& summary, std::string_view program,
                        Diagnostics& diags) {
  std::string text;
  for (const std::string& line :
       header_lines(summary.cycle_time, program, m.name, summary.units, m.diameter_output)) {
    for (const std::string& piece : NcWriter::comment_lines(m, line)) {
      TemplateValues v(tmpl::kProgramHeader);
      v.set_text(0, piece);
      for (const std::string& t : m.templates.at(std::string(tmpl::kProgramHeader.name))) {
        const TemplateValues::Line l = v.format(t);
        if (!l.ok) {
          diags.error({}, {},
                      fmt::format("machine '{}': template 'program_header' cannot be written: {}",
                                  m.name, l.error));
          return {};
        }
        text += l.text + m.line_ending;
      }
    }
  }
  return text;
}

// The program's name in its header: PARTNO's, else the CL file's stem.
std::string program_name(const std::string& partno, const std::string& file) {
  if (!partno.empty()) return partno;
  std::string name = std::filesystem::path(file).filename().string();
  const size_t dot = name.rfind('.');
  return dot == std::string::npos || dot == 0 ? name : name.substr(0, dot);
}

// Opens the spool in `dir`: empty, or why it cannot be.
std::string open_spool(SpoolFile& spool, const std::string& dir) {
  std::string error;
  spool.open(dir, error);
  return error;
}

}  // namespace

PostRun::PostRun(const Machine& m, Sink& out, Diagnostics& diags, const PostOptions& opts,
                 const std::function<void(const ThreadPlan&)>& on_thread)
    : m_(m),
      machine_(m),
      out_(out),
      diags_(diags),
      header_(writes_program_header(m)),
      spool_error_(header_ ? open_spool(body_, opts.spool_dir) : std::string()),
      // A header needs the whole program's times: the program waits on disk for it.
      prog_(machine_, header_ ? static_cast<Sink&>(body_) : out),
      interp_(machine_, prog_, diags, opts) {
  prog_.follow_units(machine_, m_);
  if (on_thread) interp_.on_thread(on_thread);
}

PostSummary PostRun::end(bool reader_gave_up, uint32_t last_line, size_t bytes_in) {
  if (interp_.stats().statements == 0 && !diags_.has_errors()) {
    diags_.error({}, {}, "no CL statements in the file");
  } else if (!reader_gave_up) {
    interp_.end_of_input(last_line);
  }
  PostSummary summary;
  summary.stats = interp_.stats();
  summary.units = interp_.units();
  summary.bytes_in = bytes_in;
  summary.holes = interp_.take_holes();
  summary.mill = interp_.take_mill();
  summary.outputs = interp_.take_outputs();
  summary.partno = interp_.partno();
  summary.cycle_time = interp_.cycle_time();
  summary.path = interp_.take_path();
  if (header_) write_with_header(summary);
  return summary;
}

void PostRun::write_with_header(PostSummary& summary) {
  // The header after the program start's lines; the tools' NC lines move down by its lines.
  const std::string header =
      header_text(m_, summary, program_name(summary.partno, diags_.file()), diags_);
  shift_nc_lines(summary.cycle_time,
                 static_cast<size_t>(std::count(header.begin(), header.end(), '\n')));
  // A machine file without a program_start has the header at the top.
  const auto start = m_.templates.find(std::string(tmpl::kProgramStart.name));
  const size_t lines = start == m_.templates.end() ? 0 : start->second.size();
  std::string error = spool_error_;
  if (error.empty() && body_.copy_to(out_, lines, header, error)) return;
  diags_.error({}, {}, error);
}

PostedText post_text(std::string_view cl, const Machine& m, std::string file_name,
                     const PostOptions& opts) {
  PostedText r{{}, Diagnostics(std::move(file_name)), {}, {}};
  StringSink sink;
  ClReader reader(cl, r.diags);
  r.summary =
      post(reader, m, sink, r.diags, opts, [&r](const ThreadPlan& p) { r.plans.push_back(p); });
  r.program = std::move(sink.out);
  return r;
}

}  // namespace clpost

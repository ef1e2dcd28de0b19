// The library's entry point (post.h).
#include "interpreter/post.h"

#include <fmt/format.h>

#include <algorithm>

#include "interpreter/interpreter.h"
#include "writer/nc_program.h"

namespace clpost {

namespace {

// The machine's program_header: the tool list and cycle time, the template once per line.
std::string header_text(const Machine& m, const PostSummary& summary, Diagnostics& diags) {
  std::string text;
  for (const std::string& line :
       cycle_time_lines(summary.cycle_time, summary.units, m.diameter_output)) {
    TemplateValues v(tmpl::kProgramHeader);
    v.set_text(0, NcWriter::comment_text(m, line));
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
  return text;
}

// `body` with the header after the program start's lines.
void write_with_header(const Machine& m, const std::string& body, const std::string& header,
                       Sink& out) {
  size_t at = 0;
  const size_t lines = m.templates.at(std::string(tmpl::kProgramStart.name)).size();
  for (size_t i = 0; i < lines && at != std::string::npos; ++i) {
    at = body.find('\n', at);
    if (at != std::string::npos) ++at;
  }
  if (at == std::string::npos) at = body.size();
  out.write(std::string_view(body).substr(0, at));
  out.write(header);
  out.write(std::string_view(body).substr(at));
}

// Whether the machine writes a program_header (an empty list writes none).
bool has_header(const Machine& m) {
  auto h = m.templates.find(std::string(tmpl::kProgramHeader.name));
  return h != m.templates.end() && !h->second.empty();
}

}  // namespace

PostRun::PostRun(const Machine& m, Sink& out, Diagnostics& diags, const PostOptions& opts,
                 const std::function<void(const ThreadPlan&)>& on_thread)
    : m_(m),
      machine_(m),
      out_(out),
      diags_(diags),
      header_(has_header(m)),
      // A header needs the whole program's times: the program waits in memory for it.
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
  summary.outputs = interp_.take_outputs();
  summary.partno = interp_.partno();
  summary.cycle_time = interp_.cycle_time();
  summary.path = interp_.take_path();
  if (header_) {
    const std::string header = header_text(m_, summary, diags_);
    shift_nc_lines(summary.cycle_time,
                   static_cast<size_t>(std::count(header.begin(), header.end(), '\n')));
    write_with_header(m_, body_.out, header, out_);
  }
  return summary;
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

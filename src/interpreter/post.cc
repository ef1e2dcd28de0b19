// The library's entry point (post.h).
#include "interpreter/post.h"

#include "interpreter/interpreter.h"
#include "writer/nc_program.h"

namespace clpost {

PostSummary post(ClReader& reader, const Machine& m, Sink& out, Diagnostics& diags,
                 const PostOptions& opts, const std::function<void(const ThreadPlan&)>& on_thread) {
  PostSummary summary;
  NcProgram prog(m, out);
  Interpreter interp(m, prog, diags, opts);
  if (on_thread) interp.on_thread(on_thread);
  Statement st;
  while (reader.next(st)) interp.statement(st);
  if (interp.stats().statements == 0 && !diags.has_errors()) {
    diags.error({}, {}, "no CL statements in the file");
  } else if (!reader.gave_up()) {
    interp.end_of_input(reader.line());
  }
  summary.stats = interp.stats();
  summary.units = interp.units();
  summary.bytes_in = reader.bytes_read();
  summary.holes = interp.take_holes();
  summary.cycle_time = interp.cycle_time();
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

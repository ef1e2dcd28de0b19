// The library's entry point (post.h).
#include "interpreter/post.h"

#include "interpreter/interpreter.h"
#include "writer/nc_program.h"

namespace clpost {

PostSummary end_post(Interpreter& interp, Diagnostics& diags, bool reader_gave_up,
                     uint32_t last_line, size_t bytes_in) {
  if (interp.stats().statements == 0 && !diags.has_errors()) {
    diags.error({}, {}, "no CL statements in the file");
  } else if (!reader_gave_up) {
    interp.end_of_input(last_line);
  }
  return PostSummary{interp.stats(), interp.units(), bytes_in};
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

#pragma once
// The library's entry point: a CL input and a machine in; the NC program, its diagnostics and its
// thread plans out. The CLI (post, check, plan, verify, plot, batches), the fuzzers, the
// benchmark and the tests all post through here, so that how a file is read to its end is said
// once.
#include <functional>
#include <string>
#include <string_view>
#include <vector>

#include "interpreter/interpreter.h"
#include "interpreter/post_state.h"
#include "machine/machine.h"
#include "planner/thread_plan.h"
#include "reader/cl_reader.h"
#include "support/diagnostics.h"
#include "support/sink.h"
#include "support/spool_file.h"
#include "writer/nc_program.h"

namespace clpost {

// What a post saw besides the program and the diagnostics.
struct PostSummary {
  PostStats stats;
  LengthUnit units = LengthUnit::kMm;  // of the CL file (its last UNITS/, else the machine's)
  size_t bytes_in = 0;
  std::vector<Hole> holes;          // every hole on the spindle axis written, in order (verify)
  std::vector<MillSegment> mill;    // a live tool's milling, in the part frame (verify)
  std::vector<OutputUsed> outputs;  // the output each thread, hole and undercut is written by
  std::string partno;               // PARTNO's text
  CycleTime cycle_time;             // the tool list and estimated cycle time (cycle_time.h)
  ClPath path;                      // with PostOptions::keep_motions (verify)
};

// One post in progress, the part of post() that does not depend on the reader: the program, the
// interpreter, and how the input ended, said once. A machine with a program_header (the tool
// list and the cycle time, known at the end) gets its program in two passes: the body is spooled
// to an unnamed temporary file (PostOptions::spool_dir, support/spool_file.h), then the header
// and the body are written to `out` at the end; memory does not grow with the program.
class PostRun {
 public:
  PostRun(const Machine& m, Sink& out, Diagnostics& diags, const PostOptions& opts,
          const std::function<void(const ThreadPlan&)>& on_thread);
  void statement(const Statement& st) { interp_.statement(st); }
  // A file without a statement is an error; one that ends without FINI is closed with a warning,
  // unless the reader gave up before its end. Then the header, if any, and the program.
  PostSummary end(bool reader_gave_up, uint32_t last_line, size_t bytes_in);

 private:
  // The program start's lines from the spool, the header, then the rest of the spool.
  void write_with_header(PostSummary& summary);

  const Machine& m_;
  Machine machine_;  // m_ as this program writes it: its formats follow the program's units
  Sink& out_;
  Diagnostics& diags_;
  bool header_;
  SpoolFile body_;
  std::string spool_error_;  // the spool could not be created (reported at end())
  NcProgram prog_;
  Interpreter interp_;
};

// Posts every statement `reader` delivers on machine `m`: the program to `out`, the diagnostics
// to `diags` (the reader's own among them), every thread plan to `on_thread` as it is planned.
// `out` gets a program even when there are errors: the caller decides what to keep
// (diags.has_errors()). `Reader` is ClReader (text or binary CL, detected), or any reader with
// its next(), gave_up(), line() and bytes_read() (the binary fuzz target records what it reads).
template <class Reader = ClReader>
PostSummary post(Reader& reader, const Machine& m, Sink& out, Diagnostics& diags,
                 const PostOptions& opts = {},
                 const std::function<void(const ThreadPlan&)>& on_thread = {}) {
  PostRun run(m, out, diags, opts, on_thread);
  Statement st;
  while (reader.next(st)) run.statement(st);
  return run.end(reader.gave_up(), reader.line(), reader.bytes_read());
}

// post() of CL text in memory, collected: the program, the diagnostics and every plan.
struct PostedText {
  std::string program;
  Diagnostics diags;
  std::vector<ThreadPlan> plans;
  PostSummary summary;
};
PostedText post_text(std::string_view cl, const Machine& m, std::string file_name = "<cl>",
                     const PostOptions& opts = {});

}  // namespace clpost

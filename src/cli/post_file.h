#pragma once
// Posting one CL file: read, interpret, write the NC program atomically (nothing is written when
// the file has an error). Used by the CLI's post, check and plan commands and by the batch.
#include <functional>
#include <memory>
#include <string>
#include <vector>

#include "interpreter/post.h"
#include "machine/machine.h"
#include "support/output_file.h"

namespace clpost {

struct PostRequest {
  std::string input;   // path, or "-" for standard input
  std::string output;  // path, "-" for standard output, empty: write nothing (check, plan)
  const Machine* machine = nullptr;
  PostOptions options;
  std::function<void(const ThreadPlan&)> on_thread;  // every thread plan
  // --verify: read the program back through the control simulation and compare it with the
  // plan (verify_command.h); a program that does not cut the plan is an error (no output).
  bool verify = false;
  double verify_tolerance = 0;     // 0: the machine's
  std::string* program = nullptr;  // when set, gets a copy of the program (clpost plot)
  Sink* program_sink = nullptr;    // when set, gets the program as it is written (clpost plot)
  // A batch publishes its programs in groups (OutputFile::publish_all: one syncfs for many
  // fsyncs). When set, a good output is written out (OutputFile::finish) and handed here instead
  // of being committed: it is not under its name until the caller has published it.
  std::function<void(std::unique_ptr<OutputFile>)> publish_later = nullptr;
};

struct PostOutcome {
  bool ok = false;  // no errors (output written when one was asked for)
  size_t errors = 0;
  size_t warnings = 0;
  std::string diagnostics;       // rendered, ready for stderr
  std::vector<Diagnostic> kept;  // the same as data (batch report); at most kMaxKept
  PostStats stats;
  LengthUnit units = LengthUnit::kMm;
  size_t bytes_in = 0;
  size_t bytes_out = 0;
  std::string verify_report;        // with PostRequest::verify
  std::vector<Hole> holes;          // the holes written (CYCLE/DRILL …), for verify
  std::vector<MillSegment> mill;    // a live tool's milling (docs/millturn.md), for verify
  std::vector<OutputUsed> outputs;  // the output of each thread, hole, undercut (clpost sheet)
  std::string partno;               // PARTNO's text (clpost sheet)
  CycleTime cycle_time;             // the tool list and estimated cycle time
  ClPath path;                      // every motion and its state (with --verify, plans_of)
};

PostOutcome post_file(const PostRequest& req);

// The thread plans of the CL file `cl` on machine `m`, nothing written; `program`, when given,
// gets the NC program it posts (clpost verify, clpost plot).
PostOutcome plans_of(const std::string& cl, const Machine& m, std::vector<ThreadPlan>& plans,
                     std::string* program = nullptr);

// The name a file is shown by in diagnostics ("<stdin>" for "-").
std::string display_name(const std::string& input);

}  // namespace clpost

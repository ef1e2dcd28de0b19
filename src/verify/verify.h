#pragma once
// `clpost verify`: does an NC program cut what the CL file's plan says? The program's
// synchronized cuts (simulator/control_sim.h: every cycle expanded with its control's law) are
// lined up with the plan's passes (cut_alignment.h) and compared pass by pass: start, depth,
// shift, where each cut starts and ends, the pull-out, the lead.
#include <optional>
#include <string>
#include <vector>

#include "machine/machine.h"
#include "planner/thread_plan.h"
#include "simulator/control_sim.h"
#include "simulator/toolpath.h"
#include "support/diagnostics.h"

namespace clpost {

struct VerifyOptions {
  double tolerance = 0;   // largest difference that counts as equal; 0: cut_tolerance(m)
  std::string plan_name;  // how the plan's source is named in messages ("part.cl")
};

struct ThreadVerdict {
  size_t plan = 0;                    // index into the plans
  size_t planned = 0;                 // passes in the plan
  size_t cut = 0;                     // program cuts matched to this thread (equal or not)
  std::string how;                    // "G76, NC line 40", "G33, NC lines 12-31"
  std::vector<std::string> problems;  // one line each, with the numbers
  std::vector<std::string> notes;     // accepted differences (threading.accept_pass_end)
  // The program's cuts matched to this thread's passes, measured in the plan's frame (depth
  // below the thread surface, shift along it): what `clpost plot --cl` draws for a program.
  std::vector<SectionPass> program_passes;
};

struct VerifyReport {
  std::vector<ThreadVerdict> threads;
  size_t planned_passes = 0;
  size_t program_cuts = 0;
  size_t problems = 0;  // differences beyond the tolerance, missing and extra cuts
  double tolerance = 0;
};

// Compares; every problem is also an error in `nc_diags` at the NC block concerned. Returns
// true when the program cuts the plan.
bool verify_cuts(const std::vector<ThreadPlan>& plans, const Simulation& sim, const Machine& m,
                 const VerifyOptions& options, Diagnostics& nc_diags, VerifyReport& report);

// The report as text for standard output: one line per thread, then the verdict.
std::string verify_report_text(const VerifyReport& report, const std::vector<ThreadPlan>& plans,
                               const std::string& program_name, const Machine& m,
                               const VerifyOptions& options);

// `clpost --verify`: the threads compared as their plans and the program's cuts come, so that
// memory does not grow with the file. Once kWindow threads wait, the leading threads (of the
// first 2 kWindow) that the
// program cuts exactly as planned (kAhead exact pairs after them, kMargin threads left) are
// finished: their report lines written, their plans and cuts let go. The rest is compared at
// the end as verify_cuts compares, every difference reported as verify_cuts reports it (a cut
// the plan does not have right after finished threads is reported with the next thread).
class ThreadStream {
 public:
  ThreadStream(const Machine& m, const VerifyOptions& options);
  ~ThreadStream();
  // A plan, in order; `cuts`: the program's cuts read so far (those finished are taken out).
  void plan(const ThreadPlan& p, std::vector<NcCut>& cuts);
  // More of the program's cuts read (those finished are taken out).
  void poll(std::vector<NcCut>& cuts);
  // The end: the threads left compared (problems into `nc_diags`) and the report as
  // verify_report_text writes it into `text`. True when the program cuts the plan.
  bool finish(const std::vector<NcCut>& cuts, const std::string& program_name,
              Diagnostics& nc_diags, std::string& text);

 private:
  static constexpr size_t kWindow = 64;
  static constexpr size_t kAhead = 16;
  static constexpr size_t kMargin = 8;
  static constexpr size_t kRetryCuts = 256;  // cuts read before a flush is tried again
  bool flush(std::vector<NcCut>& cuts);

  const Machine& m_;
  VerifyOptions options_;
  double tolerance_;
  std::vector<ThreadPlan> plans_;               // the threads waiting
  size_t attempt_at_ = kWindow;                 // the next flush is tried when this many wait
  size_t retry_at_ = 0;                         // or when this many cuts are read
  size_t threads_ = 0, planned_ = 0, cut_ = 0;  // finished threads, their passes and cuts
  std::string lines_;                           // their report lines
  std::optional<bool> mm_;                      // the first plan's units
  std::optional<NcCut> last_cut_;               // the last cut finished
};

}  // namespace clpost

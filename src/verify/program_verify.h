#pragma once
// A whole NC program against what its CL file says, as `clpost verify --cl` and `clpost --verify`
// check it: the program read back through the control simulation (simulator/control_sim.h), then
// its thread cuts against the plans (verify.h), its holes (hole_verify.h) and its path, arcs,
// tool, feed and spindle (path_verify.h) against the CL's.
#include <string>
#include <string_view>
#include <vector>

#include "machine/machine.h"
#include "planner/thread_plan.h"
#include "reader/line_source.h"
#include "simulator/control_sim.h"
#include "verify/mill_verify.h"
#include "verify/path_verify.h"

namespace clpost {

struct VerifyOutcome {
  bool ok = false;          // the program reads and cuts the plan
  std::string report;       // for standard output
  std::string diagnostics;  // rendered, for standard error
  size_t errors = 0;
  std::string first_error;  // "PROGRAM:LINE: message" of the first error, for one-line summaries
};

// Verifies the program read from `src` (shown as `program_name`) against `plans`, the whole
// program in memory (`clpost verify --plan`; `clpost verify --cl` and `--verify` stream it
// through ProgramStream, which says the same).
// `cl`: the CL's holes and motion end points, compared with the program's; nullptr (a plan
// JSON, which has neither): only the threads are checked.
VerifyOutcome verify_program(reader::LineSource& src, const std::string& program_name,
                             const std::vector<ThreadPlan>& plans, const ClExpected* cl,
                             const std::string& plan_name, const Machine& m, double tolerance);

// `clpost --verify`: the program verified as it is written while its CL file is posted, as
// verify_program would: each chunk written goes to program_text(), each CL motion to
// cl_motion() (PostOptions::on_motion). The program is read a line at a time and the path
// compared in a window of moves (PathStream) and the threads in a window of threads
// (ThreadStream), so memory does not grow with the file; the holes are compared at the end.
class ProgramStream {
 public:
  ProgramStream(const std::string& program_name, const std::string& plan_name, const Machine& m,
                double tolerance);
  ~ProgramStream();
  void program_text(std::string_view text);
  void cl_motion(const ClMotion& c, const CutStateAt& state);
  // `clpost verify --cl`: the program read from `src` a line at a time, after every CL motion
  // and plan (as a program behind its header comes).
  void program_lines(reader::LineSource& src);
  // A piece of a live tool's milling, as it is posted (PostOptions::on_mill); the CL's end.
  void mill_segment(const MillSegment& g);
  void cl_ended();
  // A thread's plan, as it is planned.
  void plan(const ThreadPlan& p);
  // Both ended: the outcome. `cl_states`: the states the CL made (ClPath::state_count); `mill`:
  // the CL's milling not handed to mill_segment().
  VerifyOutcome finish(const std::vector<Hole>& holes, const std::vector<MillSegment>& mill,
                       size_t cl_states);

 private:
  // Moves the path is compared ahead in: far more than a program's moves can run ahead of the
  // CL's or behind them (the writer's buffer).
  static constexpr size_t kWindow = 1 << 14;
  const SimOptions& options();
  void read_lines(std::string_view text);
  void line(uint32_t number, std::string_view text);

  std::string name_;
  const Machine& m_;
  VerifyOptions vo_;
  Diagnostics diags_;
  Simulation out_;
  SimOptions so_;
  ControlSim sim_;
  PathStream path_;
  // The program with block delete on against the CL without its OPSKIP ranges (only reported
  // when the program has optional blocks).
  PathStream path_on_;
  ThreadStream threads_;
  MillStream mill_;  // milling compared as it comes (verify/mill_verify.h)
  // While the program with block delete on has had the same input as with it off (no optional
  // CL motion, no optional block yet), path_on_ is not fed: it would compare as path_ does, and
  // a program behind a header has every CL motion spilled to disk before its first line. Where
  // they first differ, path_on_ takes over path_'s comparison so far (part_on()).
  bool on_follows_ = true;
  void part_on();
  std::string partial_;  // the line being written
  uint32_t number_ = 0;
  bool after_cr_ = false;
  bool stopped_ = false;  // too many errors: the rest is not read
  size_t motions_ = 0;
  bool optional_motions_ = false;  // a CL motion in an OPSKIP range
};

}  // namespace clpost

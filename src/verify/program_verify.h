#pragma once
// A whole NC program against what its CL file says, as `clpost verify --cl` and `clpost --verify`
// check it: the program read back through the control simulation (simulator/control_sim.h), then
// its thread cuts against the plans (verify.h), its holes (hole_verify.h) and its path, arcs,
// tool, feed and spindle (path_verify.h) against the CL's.
#include <string>
#include <vector>

#include "machine/machine.h"
#include "planner/thread_plan.h"
#include "reader/line_source.h"
#include "verify/path_verify.h"

namespace clpost {

struct VerifyOutcome {
  bool ok = false;          // the program reads and cuts the plan
  std::string report;       // for standard output
  std::string diagnostics;  // rendered, for standard error
  size_t errors = 0;
  std::string first_error;  // "PROGRAM:LINE: message" of the first error, for one-line summaries
};

// Verifies the program read from `src` (shown as `program_name`) against `plans`.
// `cl`: the CL's holes and motion end points, compared with the program's; nullptr (a plan
// JSON, which has neither): only the threads are checked.
VerifyOutcome verify_program(reader::LineSource& src, const std::string& program_name,
                             const std::vector<ThreadPlan>& plans, const ClExpected* cl,
                             const std::string& plan_name, const Machine& m, double tolerance);

}  // namespace clpost

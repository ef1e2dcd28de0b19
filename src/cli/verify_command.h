#pragma once
// `clpost verify -m M PROGRAM --cl INPUT` and `clpost --verify`: read an NC program back through
// the control simulation and compare its cuts with the plan of the CL file (verify/verify.h).
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

// The verify subcommand: the plans from the CL file `cl` (posted on `m`, nothing written) or,
// when `cl` is empty, from `plan_json` (clpost plan --format json); the program read from the
// file `program`.
VerifyOutcome verify_files(const std::string& program, const std::string& cl,
                           const std::string& plan_json, const Machine& m, double tolerance);

}  // namespace clpost

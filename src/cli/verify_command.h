#pragma once
// `clpost verify -m M PROGRAM --cl INPUT`: the plans and the CL path of a CL file (or the plans of
// a saved plan) against a program read from a file (verify/program_verify.h does the comparing).
#include <string>
#include <vector>

#include "machine/machine.h"
#include "planner/thread_plan.h"
#include "verify/program_verify.h"

namespace clpost {

// The verify subcommand: the plans from the CL file `cl` (posted on `m`, nothing written) or,
// when `cl` is empty, from `plan_json` (clpost plan --format json); the program read from the
// file `program`.
VerifyOutcome verify_files(const std::string& program, const std::string& cl,
                           const std::string& plan_json, const Machine& m, double tolerance);

}  // namespace clpost

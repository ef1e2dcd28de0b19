#pragma once
// Verify of the whole path: every CL motion's end point (GOTO, GODLTA, arcs) is reached by the
// program, in order, by the same kind of move (a rapid where the CL rapids, a feed or arc where
// it cuts), within the tolerance — so that a machine file writing a wrong word anywhere, or a
// program edited by hand, is caught as a control emulator would catch it. Thread passes and holes
// are compared on their own (verify.h, hole_verify.h); their moves lie between these points.
#include <string>
#include <vector>

#include "emitters/hole_output.h"
#include "interpreter/cl_motion.h"
#include "simulator/toolpath.h"
#include "support/diagnostics.h"
#include "verify/verify.h"

namespace clpost {

// What the CL file says the program must do besides its threads.
struct ClExpected {
  std::vector<Hole> holes;
  std::vector<ClMotion> motions;
};

struct PathReport {
  std::string text;  // a summary line (and the first difference), "" when there are no motions
  size_t problems = 0;
};

PathReport verify_path(const std::vector<ClMotion>& cl, const Toolpath& path, const Machine& m,
                       const VerifyOptions& options, Diagnostics& nc_diags);

}  // namespace clpost

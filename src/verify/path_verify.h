#pragma once
// Verify of the whole path: every CL motion's end point (GOTO, GODLTA, arcs) is reached by the
// program, in order, by the same kind of move (a rapid where the CL rapids, a straight feed or an
// arc of the same sense around the same centre where it cuts), within the tolerance, and with the
// CL's tool, feed (value and mode) and spindle (direction, RPM or CSS, speed, limit) as the
// program's words set them (simulator/toolpath.h's StateReadback says which the machine's words
// let it read) — so that a machine file writing a wrong word anywhere, or a program edited by
// hand, is caught as a control emulator would catch it. A state difference is reported once,
// where it begins. Thread passes and holes are compared on their own (verify.h, hole_verify.h);
// their moves lie between these points.
#include <string>
#include <vector>

#include "interpreter/cl_motion.h"
#include "laws/hole_law.h"
#include "simulator/toolpath.h"
#include "support/diagnostics.h"
#include "verify/verify.h"

namespace clpost {

// What the CL file says the program must do besides its threads.
struct ClExpected {
  std::vector<Hole> holes;
  ClPath path;
};

struct PathReport {
  std::string text;  // a summary line (and the first difference), "" when there are no motions
  size_t problems = 0;
};

PathReport verify_path(const ClPath& cl, const Toolpath& path, const Machine& m,
                       const VerifyOptions& options, Diagnostics& nc_diags);

}  // namespace clpost

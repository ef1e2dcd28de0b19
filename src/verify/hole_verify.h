#pragma once
// Verify of holes on the spindle axis: each CL hole (as the post read it: its R plane, pecks and
// bottom) against the hole the program drills (simulator/control_sim.h SimHole: a cycle read
// back through the machine's template and expanded, or the moves after the hole's comment),
// matched by the CL line the program's comment names.
#include <string>
#include <vector>

#include "laws/hole_law.h"
#include "simulator/control_sim.h"
#include "support/diagnostics.h"
#include "verify/verify.h"

namespace clpost {

struct HoleReport {
  std::string text;     // one line per hole, for the verify report ("" when there are none)
  size_t problems = 0;  // holes missing, extra or drilled differently
};

// Every problem is also an error in `nc_diags` at the program's hole (the first difference,
// with the numbers); the tolerance as verify_cuts's.
HoleReport verify_holes(const std::vector<Hole>& cl, const std::vector<SimHole>& nc,
                        const Machine& m, const VerifyOptions& options, Diagnostics& nc_diags);

}  // namespace clpost

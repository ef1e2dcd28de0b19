#pragma once
// The end of every pass of a multi-pass thread (threading.md section 7): the pull-out (a third
// GOTO, ATANGL or CHAMFR) and the height of the clearance line the tool returns along (RETURN).
// Internal to planner/.
#include <optional>
#include <vector>

#include "planner/multi_geometry.h"
#include "planner/plan_report.h"
#include "planner/planner.h"
#include "planner/thread_plan.h"

namespace clpost {

struct Pullout {
  std::optional<Vec2> delta;  // added at the end of every pass; none: no pull-out
  double shorten = 0;         // negative CHAMFR: every pass ends this much earlier along t
  bool linear = false;        // chamfer angle outside 30..60 degrees: G1 in plain emulation
};

// The pull-out of the thread with pitch `pitch`. False, reported, when more than one is given or
// a third GOTO moves into the material.
bool make_pullout(const MultiThreadInput& in, const MultiGeometry& g, double pitch, Pullout& out,
                  plan_report::Reporter& r);

// The height of the clearance line above the thread line (outward): RETURN's, else the default
// pitch/(2 tan 30), and never below the highest pull-out end (that of the pass at the smallest
// depth `shallowest`). False, reported, when RETURN without a height cannot be used.
bool clearance_height(const MultiThreadInput& in, const MultiGeometry& g, double pitch,
                      const Pullout& pullout, double shallowest, double& out,
                      plan_report::Reporter& r);

}  // namespace clpost

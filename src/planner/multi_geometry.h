#pragma once
// The geometry of a multi-pass thread (threading.md section 4): the thread line P1-P2, the
// cutting direction along it, the infeed direction CUTANG and the normal toward the material.
// Internal to planner/.
#include "planner/plan_report.h"
#include "planner/planner.h"
#include "planner/thread_plan.h"

namespace clpost {

struct MultiGeometry {
  Vec2 p0;                   // the initial point: the tool before THREAD/ON
  Vec2 p1;                   // thread start (GOTO 1)
  Vec2 p2;                   // thread end (GOTO 2); P1-P2 is the outer surface
  Vec2 d12;                  // P2 - P1
  double length = 0;         // |P2 - P1|
  Vec2 t;                    // the unit cutting direction P1 -> P2
  bool lead_along_z = true;  // |dZ| >= |dX|: turn or turn-taper (else face or face-taper)
  double cutang = 0;         // the infeed angle, degrees
  Vec2 u;                    // the unit infeed direction at CUTANG
  Vec2 n;                    // the unit normal of the thread line on the side u points to
  double nu = 0;             // n.u: a depth d is reached by moving d/nu along u
  Vec2 out_dir;              // -n: outward, away from the material
};

// The thread line from P0 and the first two GOTOs (there are at least two). False, reported at
// the second GOTO, when it has no length.
bool make_thread_line(const MultiThreadInput& in, MultiGeometry& g, plan_report::Reporter& r);

// The infeed direction (CUTANG, or the default toward the thread line from P0) and the normal.
// False, reported, when CUTANG is too close to the thread line or no default can be chosen.
bool make_infeed_direction(const MultiThreadInput& in, MultiGeometry& g, plan_report::Reporter& r);

// What the plan of a multi-pass thread (form "multi") says before its passes: units, pitch and
// lead from `pitch`, P0, P1, P2, kind, side, lead axis, CUTANG, OPTION and tool angle.
ThreadPlan plan_header(const MultiThreadInput& in, const PlannerSettings& settings,
                       const PitchSpec& pitch, const MultiGeometry& g);

// External when the infeed moves toward the axis; face threads are reported external.
ThreadSide side_of(const MultiGeometry& g);

}  // namespace clpost

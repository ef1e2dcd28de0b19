#pragma once
// The path of a G2/G3 of a machine with C (SimMillMove), as the control moves it: verify checks
// it along its length (verify/mill_verify.cc) and plot draws it (plot/mill_views.cc) by the same
// points.
#include <vector>

#include "simulator/control_sim.h"

namespace clpost {

// A machine position: X (a radius), Y, Z, C (degrees).
struct MillAxes {
  double x = 0, y = 0, z = 0, c = 0;
};

// The centre of the arc `to` (its centre words I, J, K in its plane, from its start `from`).
MillAxes mill_arc_centre(const SimMillMove& from, const SimMillMove& to);

// The points along the G2/G3 `to` from `from` (at to's C), the last at its end angle, in at
// least `min_steps` steps of at most `max_step_degrees`: in its plane (G17 X/Y, G18 Z/X, G19
// Y/Z) about mill_arc_centre at the start's radius, turning positively about the plane's normal
// for G3 (ISO 6983), the axis along the normal linear. None when the start is at the centre.
std::vector<MillAxes> mill_arc_points(const SimMillMove& from, const SimMillMove& to,
                                      double max_step_degrees, int min_steps = 1);

}  // namespace clpost

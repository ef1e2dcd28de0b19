#include "simulator/mill_arc.h"
#include "support/angles.h"

#include <algorithm>
#include <array>
#include <cmath>
#include <numbers>

namespace clpost {

namespace {

// (u, v) the arc's plane, w its normal.
std::array<double, 3> uvw(int plane, double x, double y, double z) {
  if (plane == 17) return {x, y, z};
  if (plane == 19) return {y, z, x};
  return {z, x, y};
}

MillAxes from_uvw(int plane, const std::array<double, 3>& m, double c) {
  if (plane == 17) return {m[0], m[1], m[2], c};
  if (plane == 19) return {m[2], m[0], m[1], c};
  return {m[1], m[2], m[0], c};
}

}  // namespace

MillAxes mill_arc_centre(const SimMillMove& from, const SimMillMove& to) {
  return {from.x + (to.plane == 19 ? 0 : to.i), from.y + (to.plane == 18 ? 0 : to.j),
          from.z + (to.plane == 17 ? 0 : to.k), to.c};
}

std::vector<MillAxes> mill_arc_points(const SimMillMove& from, const SimMillMove& to,
                                      double max_step_degrees, int min_steps) {
  const std::array<double, 3> p = uvw(to.plane, from.x, from.y, from.z),
                              q = uvw(to.plane, to.x, to.y, to.z);
  const MillAxes centre = mill_arc_centre(from, to);
  const std::array<double, 3> o = uvw(to.plane, centre.x, centre.y, centre.z);
  const double r = std::hypot(p[0] - o[0], p[1] - o[1]);
  if (!(r > 0)) return {};
  const double a0 = std::atan2(p[1] - o[1], p[0] - o[0]);
  double sweep = std::atan2(q[1] - o[1], q[0] - o[0]) - a0;
  const double turn = 2 * std::numbers::pi;
  if (to.ccw) {
    while (sweep <= 1e-12) sweep += turn;
  } else {
    while (sweep >= -1e-12) sweep -= turn;
  }
  const int n = std::max(min_steps,
                         static_cast<int>(std::ceil(std::fabs(sweep) / radians(max_step_degrees))));
  std::vector<MillAxes> out;
  for (int i = 1; i <= n; ++i) {
    const double t = static_cast<double>(i) / n, g = a0 + sweep * t;
    out.push_back(
        from_uvw(to.plane,
                 {o[0] + r * std::cos(g), o[1] + r * std::sin(g), p[2] + (q[2] - p[2]) * t}, to.c));
  }
  return out;
}

}  // namespace clpost

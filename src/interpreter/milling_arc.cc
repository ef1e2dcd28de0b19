// A live tool's arcs and helices (docs/millturn.md): CIRCLE/ and the GOTO that ends it, HELICAL/
// and geometric motion (milling_geometry.cc), as chords within the tolerance, G2/G3 in the
// machine's plane with Y, or in polar interpolation.
#include <fmt/format.h>

#include <algorithm>
#include <cmath>

#include "interpreter/milling_parts.h"
#include "interpreter/milling_polar.h"
#include "interpreter/point3_math.h"
#include "interpreter/statement_table.h"
#include "support/angles.h"

namespace clpost {

using namespace point3_math;

namespace {

// The radius vector of `p` about the arc's axis, and its advance along it.
Point3 radial_of(const MillArc& c, Point3 p, double& h) {
  const Point3 u = sub(p, c.center);
  h = dot(u, c.axis);
  return sub(u, scaled(c.axis, h));
}

// Points on the arc from `from` to `to`, the chords within `tol` of it; the last is `to`. The
// same point: a full turn.
std::vector<Point3> arc_points(const MillArc& c, Point3 from, Point3 to, double tol) {
  double h0 = 0, h1 = 0;
  const Point3 r0 = radial_of(c, from, h0), r1 = radial_of(c, to, h1);
  const double r = std::sqrt(dot(r0, r0));
  double sweep = c.sense * std::atan2(dot(cross(r0, r1), c.axis), dot(r0, r1));
  while (sweep <= 1e-9) sweep += 2 * kPi;
  const double step = tol < r ? 2 * std::acos(1 - tol / r) : kPi / 2;
  const int n = std::max(1, static_cast<int>(std::ceil(sweep / std::min(step, kPi / 2))));
  const Point3 side = cross(c.axis, r0);
  std::vector<Point3> out;
  for (int k = 1; k < n; ++k) {
    const double a = c.sense * sweep * k / n;
    const Point3 rk = add(scaled(r0, std::cos(a)), scaled(side, std::sin(a)));
    out.push_back(add(add(c.center, scaled(c.axis, h0 + (h1 - h0) * k / n)), rk));
  }
  out.push_back(to);
  return out;
}

// The arc `c` in polar interpolation: G2/G3 where the control takes them (millturn.polar_arcs),
// else its chords `points`, each an exact G1.
void polar_mill_arc(PostState& s, LiveState& l, const Statement& st, const MillArc& c, Point3 from,
                    Point3 to, const std::vector<Point3>& points, const MotionStart& ms) {
  if (std::abs(std::abs(c.axis.z) - 1) > 1e-6)
    return refuse_milling(s, l, st,
                          "an arc about another axis than the spindle's in polar interpolation");
  if (s.m.polar_arcs) {
    polar_arc(s, l, st, c.center, c.sense * c.axis.z > 0, from, to, ms.index, ms.feed);
    return;
  }
  Point3 a = from;
  for (const Point3& p : points) {
    if (!polar_line(s, l, st, a, p, ms.index, false, ms.feed)) return;
    a = p;
  }
}

// The words of HELICAL/ (CATIA): CENTER x,y,z, INDIRV i,j,k, AXIS i,j,k, END x,y,z (PITCH,
// RADIUS, ANGLE, HEIGHT, ROUND are implied by them and not read).
bool helical_words(PostState& s, const Statement& st, Point3& c, Point3& dir, Point3& axis,
                   Point3& end) {
  const auto three = [&](std::string_view word, Point3& out) {
    for (size_t i = 0; i + 3 < st.args.size(); ++i)
      if (st.args[i].is(word))
        return number_arg(s, st, i + 1, word, out.x) && number_arg(s, st, i + 2, word, out.y) &&
               number_arg(s, st, i + 3, word, out.z);
    error(s, st, st.loc,
          fmt::format("HELICAL/ without {} x,y,z: expected CENTER, INDIRV, AXIS and END", word));
    return false;
  };
  return three("CENTER", c) && three("INDIRV", dir) && three("AXIS", axis) && three("END", end);
}

}  // namespace

void mill_arc(PostState& s, LiveState& l, const Statement& st, const MillArc& c, Point3 from,
              Point3 to, const MotionStart& ms) {
  double h = 0;
  const Point3 r0 = radial_of(c, from, h), r1 = radial_of(c, to, h);
  const double d0 = std::sqrt(dot(r0, r0)), d1 = std::sqrt(dot(r1, r1));
  if (std::abs(d0 - d1) > std::max(1e-3, 1e-4 * d0))
    return error(s, st, st.loc,
                 fmt::format("arc end point is not on the circle of line {}: distance from the "
                             "axis {:.6g} at the start, {:.6g} at the end",
                             c.line, d0, d1));
  // Chords within half the tolerance, each piece within the other half: the segments verify
  // checks the program against.
  const std::vector<Point3> points = arc_points(c, from, to, s.m.xzc_tolerance / 2);
  const bool polar = polar_motion(s, ms.radial);
  if (!s.m.y_axis && !polar && !xzc_arc_reached(s, l, st, c, points, ms.radial)) return;
  if (!s.m.y_axis && !polar) xzc_plane(s, l, ms.radial);
  Point3 at = from;
  for (const Point3& p : points) {
    keep_mill(s, l, {st.loc.line, at, p, ms.index, false});
    const Point3 q = &p == &points.back() ? machine_tip(s, ms, p) : p;
    if (!s.m.y_axis && !polar)
      xzc_move(s, l, at, q, ms.index, false, ms.feed, s.m.xzc_tolerance / 2);
    at = p;
  }
  if (polar) return polar_mill_arc(s, l, st, c, from, to, points, ms);
  if (!s.m.y_axis || xyz_arc(s, l, c, from, to, ms.turn, ms.feed)) return;
  if (l.mill.comp != CutterComp::kOff)
    return refuse_milling(
        s, l, st,
        fmt::format("the arc is not in G{}, the plane cutter compensation (CUTCOM) is on "
                    "in, and a control refuses a plane change under G41/G42: give "
                    "the tool centre's path (CUTCOM/OFF)",
                    l.mill.plane));
  refuse_milling(s, l, st, "the arc's axis is along none of the machine's X, Y, Z at this C");
}

void milling_helical(PostState& s, LiveState& l, const Statement& st, bool radial) {
  if (circle_waits(s, st)) return;
  Point3 c, dir, axis, end;
  if (!helical_words(s, st, c, dir, axis, end)) return;
  const double len = std::sqrt(dot(axis, axis));
  if (!(len > 0) || !s.pos)
    return error(s, st, st.loc, "HELICAL/ needs an axis and a start point (a GOTO before it)");
  const Point3 a = scaled(axis, 1 / len);
  double h = 0;
  const int sense = dot(cross(a, radial_of({c, a, 1, 0}, *s.pos, h)), dir) >= 0 ? 1 : -1;
  milling_arc_to(s, l, st, c, a, sense, end, radial);
}

void milling_arc_to(PostState& s, LiveState& l, const Statement& st, Point3 center, Point3 axis,
                    int sense, Point3 end, bool radial) {
  MotionStart ms;
  ms.radial = radial;
  if (!s.pos) return error(s, st, st.loc, "an arc needs a start point: no GOTO or FROM before it");
  if (!start_motion(s, l, st, false, end, ms)) return;
  const Point3 from = *s.pos;
  s.pos = end;
  mill_arc(s, l, st, {center, axis, sense, st.loc.line}, from, end, ms);
}

}  // namespace clpost

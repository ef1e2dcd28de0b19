// A live tool's milling on a machine with Y (docs/millturn.md): X (diameter) Y Z in the face
// plane at the C index, C turned past it for a radial tool; lines and G2/G3 in the plane the
// work is in (G17, G18, G19).
#include <cmath>

#include "interpreter/clock.h"
#include "interpreter/milling_parts.h"
#include "support/angles.h"

namespace clpost {

Point3 machine_xyz(Point3 p, double turn) {
  const double a = radians(-turn), c = std::cos(a), n = std::sin(a);
  return {p.x * c - p.y * n, p.x * n + p.y * c, p.z};
}

void xyz_move(PostState& s, LiveState& l, Point3 m, bool rapid, double feed, int plane) {
  NcWriter& w = s.prog.writer();
  plane_code(s, l, w, plane);
  if (!rapid) per_minute_code(s, l, w);
  w.code(s.m.code(rapid ? "rapid" : "linear"));
  w.word("X", diameter_factor(s.m) * m.x).word("Y", m.y).word("Z", m.z);
  if (!rapid) w.word("F", feed);
  w.end_block();
  l.mill.y = m.y;
  if (rapid) l.mill.rapid_reached(m.x);
  s.prog.cycle_ended_at(LathePoint{m.x, m.z});
  rapid ? time_rapid(s, Vec2{m.x, m.z}) : time_feed(s, Vec2{m.x, m.z});
}

bool xyz_arc(PostState& s, LiveState& l, const MillArc& c, Point3 from, Point3 to, double turn,
             double feed) {
  const Point3 a = machine_xyz(c.axis, turn), m0 = machine_xyz(from, turn);
  const Point3 m1 = machine_xyz(to, turn), mc = machine_xyz(c.center, turn);
  const double n[3] = {a.x, a.y, a.z};
  int axis = -1;
  for (int i = 0; i < 3; ++i)
    if (std::abs(std::abs(n[i]) - 1) < 1e-6) axis = i;
  const int plane = axis == 2 ? 17 : axis == 1 ? 18 : 19;
  if (axis < 0 || (l.mill.comp != CutterComp::kOff && plane != l.mill.plane)) return false;
  // G3 turns positively about the plane's normal (+Z in G17, +Y in G18, +X in G19: ISO 6983).
  const bool ccw = c.sense * n[axis] > 0;
  NcWriter& w = s.prog.writer();
  plane_code(s, l, w, plane);
  per_minute_code(s, l, w);
  w.code(s.m.code(ccw ? "arc_ccw" : "arc_cw"));
  w.word("X", diameter_factor(s.m) * m1.x).word("Y", m1.y).word("Z", m1.z);
  if (axis != 0) w.word("I", mc.x - m0.x);
  if (axis != 1) w.word("J", mc.y - m0.y);
  if (axis != 2) w.word("K", mc.z - m0.z);
  w.word("F", feed).end_block();
  l.mill.y = m1.y;
  s.prog.cycle_ended_at(LathePoint{m1.x, m1.z});
  time_feed(s, Vec2{m1.x, m1.z});
  return true;
}

}  // namespace clpost

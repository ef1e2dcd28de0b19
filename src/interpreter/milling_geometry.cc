// Geometric motion of a milling tool (docs/millturn.md): CATIA's
// TLON,GOFWD/(CYLNDR/…),ON[,n,INTOF],(PLANE/…) in MillTurn3x_PATH1: the tool centre on the
// cylinder, from where it is, the way INDIRV starts it, around the cylinder's axis to the n-th
// point on the check plane; written as the arc (milling_arc.cc). Other drive or check
// surfaces, tool sides and conditions of a milling tool are located errors.
#include <fmt/format.h>

#include <algorithm>
#include <cmath>

#include "interpreter/lathe_geometry.h"
#include "interpreter/milling_motion.h"
#include "interpreter/point3_math.h"
#include "interpreter/statement_table.h"
#include "support/angles.h"

namespace clpost {

namespace {

using namespace point3_math;

// The words after the drive surface: ON[,n,INTOF] and the check surface's index; false
// (reported) for another condition.
bool on_cond(PostState& s, const Statement& st, size_t& check, int& nth) {
  if (st.args.size() < 3 || !st.args[1].is("ON")) {
    error(s, st, st.args.size() > 1 ? st.args[1].loc : st.loc,
          fmt::format("{}/ of a milling tool: only ON a check plane is written (TO, PAST and "
                      "TANTO need the tool's radius in 3D)",
                      st.major));
    return false;
  }
  nth = 1, check = 2;
  if (st.args.size() > 4 && st.args[2].is_number() && st.args[3].is("INTOF")) {
    nth = static_cast<int>(std::clamp(st.args[2].number, 1.0, 100.0));
    check = 4;
  }
  return true;
}

// The angles (0 <= a < 2 pi) where the circle start + r0 cos a + side sin a meets the plane.
std::vector<double> crossings(Point3 start_centre, Point3 r0, Point3 side, const Geo& plane) {
  const double len = norm(plane.v);
  const Point3 n = scaled(plane.v, 1 / len);
  const double a = dot(sub(start_centre, plane.p), n), b = dot(r0, n), c = dot(side, n);
  const double m = std::hypot(b, c);
  std::vector<double> out;
  if (!(m > 1e-12) || std::abs(a) > m) return out;
  const double d = std::atan2(c, b), w = std::acos(std::clamp(-a / m, -1.0, 1.0));
  for (double t : {d - w, d + w}) {
    t = std::fmod(t, 2 * kPi);
    if (t < 0) t += 2 * kPi;
    if (t > 2 * kPi - 1e-9) t = 0;
    out.push_back(t);
  }
  std::sort(out.begin(), out.end());
  out.erase(std::unique(out.begin(), out.end(),
                        [](double x, double y) { return std::abs(x - y) < 1e-9; }),
            out.end());
  return out;
}

}  // namespace

void milling_go(PostState& s, LiveState& l, const Statement& st, bool radial) {
  if (circle_waits(s, st) || l.reported) return;  // the tool's error came first
  for (const Arg& m : st.modifiers)
    if (!m.is("TLON"))
      return error(s, st, m.loc,
                   fmt::format("'{}' before {}/ of a milling tool: only TLON (the tool centre on "
                               "the drive surface) is written",
                               m.text, st.major));
  size_t check = 0;
  int nth = 1;
  if (!on_cond(s, st, check, nth)) return;
  GeoReader rd{s, st};
  std::optional<Geo> drive = read_geo(rd, st.args[0]);
  std::optional<Geo> plane = drive ? read_geo(rd, st.args[check]) : std::nullopt;
  if (!plane) return;
  // CIRCLE/x,y,z,r (CATIA, after AUTOPS: the part surface through the tool's end, normal to its
  // axis) lies in that plane: its axis is the tool's.
  if (drive->kind == Geo::Kind::kCircle && !drive->axis_given) drive->v = s.tool_axis.dir;
  if (drive->kind == Geo::Kind::kCircle && plane->kind == Geo::Kind::kLine) {
    // A check line in the circle's plane: the plane through it along the circle's axis.
    plane->kind = Geo::Kind::kPlane;
    plane->v = cross(plane->v, drive->v);
  }
  if (drive->kind != Geo::Kind::kCircle || plane->kind != Geo::Kind::kPlane ||
      !(dot(plane->v, plane->v) > 0))
    return error(s, st, st.args[0].loc,
                 fmt::format("{}/ of a milling tool: only around a cylinder or circle to a plane "
                             "or a line is written",
                             st.major));
  if (!s.pos || !s.indirv)
    return error(s, st, st.loc,
                 fmt::format("{}/ needs a start point and INDIRV/ before it", st.major));
  const Point3 axis = scaled(drive->v, 1 / norm(drive->v));
  const Point3 u = sub(*s.pos, drive->p);
  const double h = dot(u, axis);
  const Point3 r0 = sub(u, scaled(axis, h)), centre = add(drive->p, scaled(axis, h));
  if (std::abs(norm(r0) - drive->r) > 1e-3)
    return error(s, st, st.args[0].loc,
                 fmt::format("the tool is not on the drive surface: {:.6g} from its axis, its "
                             "radius {:.6g}",
                             norm(r0), drive->r));
  const int sense = dot(cross(axis, r0), *s.indirv) >= 0 ? 1 : -1;
  const Point3 side = scaled(cross(axis, r0), sense);
  std::vector<double> at = crossings(centre, r0, side, *plane);
  // The start counts as the first point on the plane when it lies on it (CATIA's ON,2,INTOF
  // after a GOTO onto the plane); ON alone goes to the next one.
  if (!at.empty() && at.front() < 1e-9 && nth == 1) at.erase(at.begin());
  if (at.size() < static_cast<size_t>(nth))
    return error(s, st, st.args[check].loc,
                 fmt::format("the arc around the drive surface meets the check plane {} times, "
                             "not {}",
                             at.size(), nth));
  const double t = at[nth - 1];
  const Point3 end = add(centre, add(scaled(r0, std::cos(t)), scaled(side, std::sin(t))));
  milling_arc_to(s, l, st, centre, axis, sense, end, radial);
}

}  // namespace clpost

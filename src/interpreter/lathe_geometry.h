#pragma once
// The geometry of APT geometric motion on a lathe (lathe_geometry.cc): nested definitions
// (LINE, CIRCLE, CYLNDR, PLANE, POINT, VECTOR) read from a statement, the lines and circles they
// are in the turning plane, and where a drive surface meets a check surface.
#include <optional>
#include <string>
#include <utility>
#include <vector>

#include "interpreter/post_state.h"

namespace clpost {

inline constexpr double kOnSurface = 1e-3;  // CL units: a point is on a surface within this

// A 3D element of a nested definition.
struct Geo {
  enum class Kind { kPoint, kVector, kPlane, kCircle, kLine } kind = Kind::kPoint;
  Point3 p, v;  // point / vector / plane (point, normal) / circle (centre, axis) / line (p, dir)
  double r = 0;
  bool cylinder = false;  // CYLNDR: the centre may lie anywhere along the axis
  bool axis_given = true;
};

// A drive or check surface in the turning plane: u along the spindle axis, v the radius (CL).
struct Shape {
  bool circle = false;
  double cu = 0, cv = 0, r = 0;  // circle: centre, radius; line: a point
  double du = 0, dv = 0;         // line: unit direction
};

// Where a check surface stops the motion.
enum class Cond { kTo, kOn, kPast, kTanto };

// Reads the definitions of statement `st`; the first error is reported (at its column) and
// `ok` is false from then on.
struct GeoReader {
  PostState& s;
  const Statement& st;
  bool ok = true;
  void fail(SourceLoc loc, std::string msg) {
    if (ok) error(s, st, loc, std::move(msg));
    ok = false;
  }
};

// The nested definition `a` as a 3D element; nothing (reported) when it cannot be read.
std::optional<Geo> read_geo(GeoReader& rd, const Arg& a);
// The definition `a` as a line or circle in the turning plane (the lathe frame found or checked
// on its points); nothing (reported) for anything else.
std::optional<Shape> lathe_shape(GeoReader& rd, const Arg& a);
// The candidate end points (u, v) of drive `d` on check `c` under `cond`, with the cutter radius
// `rc` for TO and PAST, the tool starting at (pu, pv).
std::vector<std::pair<double, double>> check_ends(const Shape& d, Shape c, Cond cond, double rc,
                                                  double pu, double pv);
// How far along drive `d` (from (pu, pv), counter-clockwise or not for a circle, along (tu, tv)
// for a line) the point (eu, ev) is; negative when it is behind.
double travel(const Shape& d, double pu, double pv, bool ccw, double tu, double tv, double eu,
              double ev);

}  // namespace clpost

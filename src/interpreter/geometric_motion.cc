// APT geometric motion in the turning plane: INDIRV/, PSIS/ and
// TLON|TLLFT|TLRGT,GOFWD|GOLFT|GORGT|GOBACK/drive,ON|TO|PAST|TANTO,check with lines, circles,
// cylinders and planes as the lathe sees them (a line or a circle in the plane of radius and
// axis). Each motion becomes the move a GOTO (line) or CIRCLE/ + GOTO (arc) would give: it goes
// through move_to. Geometry that is not a lathe line or arc is an error at its column. A milling
// tool's geometric motion is its path's (tool_path.h; milling_geometry.cc).
#include <fmt/format.h>

#include <cmath>
#include <optional>
#include <span>

#include "interpreter/lathe_geometry.h"
#include "interpreter/point3_math.h"
#include "interpreter/statement_table.h"
#include "interpreter/tool_path.h"

namespace clpost {

using namespace point3_math;

namespace {

constexpr double kEps = 1e-9;  // a distance this small is none

enum class Side { kOn, kLeft, kRight };

// TLON, TLLFT or TLRGT before the motion word (TLON when none); false: reported.
bool tool_side(PostState& s, const Statement& st, Side& side) {
  side = Side::kOn;
  for (const Arg& m : st.modifiers) {
    if (m.is("TLON") || m.is("TLLFT") || m.is("TLRGT")) {
      side = m.is("TLON") ? Side::kOn : m.is("TLLFT") ? Side::kLeft : Side::kRight;
      continue;
    }
    error(s, st, m.loc,
          fmt::format("'{}' before {}/: expected TLON, TLLFT or TLRGT", m.text, st.major));
    return false;
  }
  return true;
}

bool read_cond(PostState& s, const Statement& st, size_t& i, Cond& cond, int& nth) {
  const Arg& w = st.args[i];
  if (w.is("TO") || w.is("ON") || w.is("PAST") || w.is("TANTO")) {
    cond = w.is("TO")     ? Cond::kTo
           : w.is("ON")   ? Cond::kOn
           : w.is("PAST") ? Cond::kPast
                          : Cond::kTanto;
  } else {
    error(s, st, w.loc,
          fmt::format("expected TO, ON, PAST or TANTO before the check surface, found {}",
                      describe_arg(st, w)));
    return false;
  }
  nth = 1;
  if (i + 2 < st.args.size() && st.args[i + 1].is_number() && st.args[i + 2].is("INTOF")) {
    const double n = st.args[i + 1].number;
    if (!(n >= 1 && n <= 100 && n == std::floor(n))) {
      error(s, st, st.args[i + 1].loc,
            fmt::format("INTOF takes 1..100, got {}", st.args[i + 1].text));
      return false;
    }
    nth = static_cast<int>(n);
    i += 2;
  }
  ++i;
  if (i >= st.args.size()) {
    error(s, st, w.loc, fmt::format("{}/ needs a check surface after {}", st.major, w.text));
    return false;
  }
  if (i + 1 != st.args.size()) {
    error(s, st, st.args[i + 1].loc,
          fmt::format("{}/ takes one check surface; found more after it", st.major));
    return false;
  }
  return true;
}

// The direction the motion starts toward, in (u, v); false: reported.
bool start_direction(PostState& s, const Statement& st, double h, double& ru, double& rv) {
  const std::optional<Point3> ref = s.indirv ? s.indirv : s.last_dir;
  if (!ref) {
    error(s, st, st.loc,
          fmt::format("{}/ needs a direction: no INDIRV/ and no motion before it", st.major));
    return false;
  }
  ru = axis_value(*ref, s.m.cl_axial), rv = axis_value(*ref, s.radial);
  const double len = std::hypot(ru, rv);
  if (!(len > 1e-9)) {
    error(s, st, st.loc,
          "the direction (INDIRV/ or the last motion) has no component in the "
          "turning plane");
    return false;
  }
  ru /= len, rv /= len;
  const double u = ru, v = rv;
  if (st.major == "GOLFT") ru = -h * v, rv = h * u;
  if (st.major == "GORGT") ru = h * v, rv = -h * u;
  if (st.major == "GOBACK") ru = -u, rv = -v;
  return true;
}

}  // namespace

namespace {

// The drive surface as the tool centre follows it (offset for TLLFT/TLRGT), the sense of travel
// (ccw for a circle, (tu, tv) for a line) from the tool at (pu, pv); false: reported.
bool follow_drive(PostState& s, const Statement& st, Shape& d, Side side, double h, double ru,
                  double rv, double pu, double pv, bool& ccw, double& tu, double& tv) {
  const double rc = s.cutter_diameter / 2;
  const double l = side == Side::kLeft ? 1 : side == Side::kRight ? -1 : 0;
  if (d.circle) {
    const double dist = std::hypot(pu - d.cu, pv - d.cv);
    if (!(dist > kEps)) {
      error(s, st, st.args[0].loc, "the tool is at the centre of the drive circle: no direction");
      return false;
    }
    const double cu = -(pv - d.cv) / dist, cv = (pu - d.cu) / dist;  // ccw tangent
    const double dot = cu * ru + cv * rv;
    if (std::abs(dot) < 1e-9) {
      error(s, st, st.loc, "the direction is normal to the drive circle: which way is forward?");
      return false;
    }
    ccw = dot > 0;
    const bool left_is_inside = ccw == (h > 0);
    d.r -= l * rc * (left_is_inside ? 1 : -1);
    if (std::abs(dist - d.r) > kOnSurface) {
      error(s, st, st.args[0].loc,
            fmt::format("the tool is not on the drive circle: {:.6g} from its centre, radius "
                        "{:.6g}",
                        dist, d.r));
      return false;
    }
    return true;
  }
  const double sign = d.du * ru + d.dv * rv;
  if (std::abs(sign) < 1e-9) {
    error(s, st, st.loc, "the direction is normal to the drive line: which way is forward?");
    return false;
  }
  tu = sign > 0 ? d.du : -d.du, tv = sign > 0 ? d.dv : -d.dv;
  d.cu += l * rc * h * -tv, d.cv += l * rc * h * tu;
  const double off = (pu - d.cu) * -d.dv + (pv - d.cv) * d.du;
  if (std::abs(off) > kOnSurface) {
    error(s, st, st.args[0].loc,
          fmt::format("the tool is not on the drive line: {:.6g} away from it", std::abs(off)));
    return false;
  }
  return true;
}

Point3 frame_point_of(const PostState& s, double u, double v) {
  Point3 p;
  *(&p.x + static_cast<int>(s.m.cl_axial)) = u;
  *(&p.x + static_cast<int>(s.radial)) = v;
  return p;
}

}  // namespace

void go_stmt(PostState& s, const Statement& st) {
  s.path->go(s, st);
}

void lathe_go(PostState& s, const Statement& st) {
  Side side;
  if (!tool_side(s, st, side)) return;
  if (st.args.size() < 2) {
    error(s, st, st.args.empty() ? st.loc : st.args[0].loc,
          fmt::format("{}/ takes a drive surface, TO|ON|PAST|TANTO and a check surface", st.major));
    return;
  }
  if (!s.pos)
    return error(s, st, st.loc,
                 fmt::format("{}/ needs a start point: no GOTO or FROM before it", st.major));
  if (s.m.cl_x_is_diameter)
    return error(s, st, st.loc,
                 "geometric motion needs the radius in CL (cl.radial_is_diameter is true)");
  size_t i = 1;
  Cond cond;
  int nth;
  if (!read_cond(s, st, i, cond, nth)) return;
  GeoReader rd{s, st};
  std::optional<Shape> drive = lathe_shape(rd, st.args[0]);
  std::optional<Shape> check = drive ? lathe_shape(rd, st.args[i]) : std::nullopt;
  if (!check) return;
  // (u, v) is right-handed seen from the third axis when axial × radial = +third.
  const int e_u = static_cast<int>(s.m.cl_axial), e_v = static_cast<int>(s.radial);
  const double h = (e_u + 1) % 3 == e_v ? 1 : -1;
  double ru, rv, tu = 0, tv = 0;
  bool ccw = false;
  if (!start_direction(s, st, h, ru, rv)) return;
  const double pu = axis_value(*s.pos, s.m.cl_axial), pv = axis_value(*s.pos, s.radial);
  if (!follow_drive(s, st, *drive, side, h, ru, rv, pu, pv, ccw, tu, tv)) return;
  std::vector<double> ahead;
  std::vector<std::pair<double, double>> at;
  for (auto [eu, ev] : check_ends(*drive, *check, cond, s.cutter_diameter / 2, pu, pv)) {
    const double t = travel(*drive, pu, pv, ccw, tu, tv, eu, ev);
    if (t > kOnSurface) ahead.push_back(t), at.push_back({eu, ev});
  }
  std::vector<size_t> order(ahead.size());
  for (size_t k = 0; k < order.size(); ++k) order[k] = k;
  std::sort(order.begin(), order.end(), [&](size_t a, size_t b) { return ahead[a] < ahead[b]; });
  if (order.size() < static_cast<size_t>(nth))
    return error(s, st, st.args[i].loc,
                 fmt::format("the drive surface does not reach the check surface ahead of the "
                             "tool ({} intersection{} ahead, {} wanted)",
                             order.size(), order.size() == 1 ? "" : "s", nth));
  const auto [eu, ev] = at[order[nth - 1]];
  const Point3 end = frame_point_of(s, eu, ev);
  if (drive->circle) {
    // The arc as CIRCLE/ gives it: positive rotation about the axis turns u toward v when h > 0.
    const Point3 c = frame_point_of(s, drive->cu, drive->cv);
    Point3 axis;
    *(&axis.x + static_cast<int>(third_axis(s))) = (ccw == (h > 0)) ? 1 : -1;
    s.circle = Circle{c.x, c.y, c.z, axis.x, axis.y, axis.z, drive->r, st.loc};
    const double du = eu - drive->cu, dv = ev - drive->cv, r = std::hypot(du, dv);
    tu = ccw ? -dv / r : dv / r, tv = ccw ? du / r : -du / r;
  }
  s.indirv.reset();
  move_to(s, st, end);
  s.last_dir = frame_point_of(s, tu, tv);
}

void indirv_stmt(PostState& s, const Statement& st) {
  Point3 d;
  if (!number_arg(s, st, 0, "the direction I", d.x) ||
      !number_arg(s, st, 1, "the direction J", d.y) ||
      !number_arg(s, st, 2, "the direction K", d.z))
    return;
  if (!(norm(d) > 0)) return error(s, st, st.args[0].loc, "INDIRV/0,0,0 gives no direction");
  s.indirv = d;
}

void psis_stmt(PostState& s, const Statement& st) {
  s.path->part_surface(s, st);
}

// PSIS/: the part surface. On a lathe it can only be the turning plane itself.
void lathe_part_surface(PostState& s, const Statement& st) {
  if (st.args.size() != 1)
    return error(s, st, st.args.empty() ? st.loc : st.args[1].loc,
                 "PSIS/ takes one plane: PSIS/(PLANE/…)");
  GeoReader rd{s, st};
  std::optional<Geo> g = read_geo(rd, st.args[0]);
  if (!g) return;
  if (g->kind != Geo::Kind::kPlane)
    return error(s, st, st.args[0].loc,
                 fmt::format("PSIS/ takes a plane, found ({}/…)", st.args[0].text));
  frame_normal(s, st, g->v);
  const double len = norm(g->v);
  if (!(len > 0) || std::abs(std::abs(axis_value(g->v, third_axis(s))) / len - 1) > 1e-6)
    return error(s, st, st.args[0].loc,
                 fmt::format("PSIS/: the part surface is not the turning plane (normal {}, {}, "
                             "{}): a lathe cuts in the plane of radius and axis",
                             g->v.x, g->v.y, g->v.z));
}

}  // namespace clpost

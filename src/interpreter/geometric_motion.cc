// APT geometric motion in the turning plane: INDIRV/, PSIS/ and
// TLON|TLLFT|TLRGT,GOFWD|GOLFT|GORGT|GOBACK/drive,ON|TO|PAST|TANTO,check with lines, circles,
// cylinders and planes as the lathe sees them (a line or a circle in the plane of radius and
// axis). Each motion becomes the move a GOTO (line) or CIRCLE/ + GOTO (arc) would give: it goes
// through move_to. Geometry that is not a lathe line or arc is an error at its column.
#include <fmt/format.h>

#include <cmath>
#include <optional>
#include <span>

#include "interpreter/statement_table.h"

namespace clpost {

namespace {

constexpr double kTol = 1e-3;  // CL units: the tool is on a surface within this
constexpr double kEps = 1e-9;  // travel shorter than this is no travel
constexpr double kPi = 3.14159265358979323846;

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

Point3 sub(Point3 a, Point3 b) {
  return {a.x - b.x, a.y - b.y, a.z - b.z};
}
Point3 cross(Point3 a, Point3 b) {
  return {a.y * b.z - a.z * b.y, a.z * b.x - a.x * b.z, a.x * b.y - a.y * b.x};
}
double norm(Point3 a) {
  return std::sqrt(a.x * a.x + a.y * a.y + a.z * a.z);
}

struct Reader {
  PostState& s;
  const Statement& st;
  bool ok = true;
  void fail(SourceLoc loc, std::string msg) {
    if (ok) error(s, st, loc, std::move(msg));
    ok = false;
  }
};

std::optional<Geo> read_geo(Reader& rd, const Arg& a);

// The numbers of `args` (all of them), or nothing (reported).
bool numbers(Reader& rd, std::span<const Arg> args, std::vector<double>& out) {
  for (const Arg& a : args) {
    if (!a.is_number() || !within_limits(a.number)) {
      rd.fail(a.loc, fmt::format("expected a number in the definition, found '{}'", a.text));
      return false;
    }
    out.push_back(a.number);
  }
  return true;
}

std::optional<Geo> read_sub(Reader& rd, const Arg& a, Geo::Kind want, std::string_view what) {
  std::optional<Geo> g = read_geo(rd, a);
  if (g && g->kind != want) {
    rd.fail(a.loc, fmt::format("expected {} here, found ({}/…)", what, a.text));
    return std::nullopt;
  }
  return g;
}

// PLANE/ in its forms: a,b,c,d; (POINT),PERPTO,(VECTOR); PERPTO,(PLANE),(POINT),(POINT);
// (POINT),(POINT),(POINT).
std::optional<Geo> read_plane(Reader& rd, const Arg& def, std::span<const Arg> args) {
  Geo g;
  g.kind = Geo::Kind::kPlane;
  if (args.size() == 4 && args[0].is_number()) {
    std::vector<double> n;
    if (!numbers(rd, args, n)) return std::nullopt;
    g.v = {n[0], n[1], n[2]};
    const double len = norm(g.v);
    if (!(len > 0))
      return rd.fail(def.loc, "PLANE/a,b,c,d needs a normal that is not 0"), std::nullopt;
    g.p = {g.v.x * n[3] / (len * len), g.v.y * n[3] / (len * len), g.v.z * n[3] / (len * len)};
    return g;
  }
  if (args.size() == 3 && args[1].is("PERPTO")) {
    auto p = read_sub(rd, args[0], Geo::Kind::kPoint, "a (POINT/…)");
    auto v = p ? read_sub(rd, args[2], Geo::Kind::kVector, "a (VECTOR/…)") : std::nullopt;
    if (!v) return std::nullopt;
    g.p = p->p, g.v = v->v;
    return g;
  }
  if (args.size() == 4 && args[0].is("PERPTO")) {
    auto pl = read_sub(rd, args[1], Geo::Kind::kPlane, "a (PLANE/…)");
    auto p1 = pl ? read_sub(rd, args[2], Geo::Kind::kPoint, "a (POINT/…)") : std::nullopt;
    auto p2 = p1 ? read_sub(rd, args[3], Geo::Kind::kPoint, "a (POINT/…)") : std::nullopt;
    if (!p2) return std::nullopt;
    g.p = p1->p, g.v = cross(sub(p2->p, p1->p), pl->v);
    return g;
  }
  if (args.size() == 3) {
    auto p1 = read_sub(rd, args[0], Geo::Kind::kPoint, "a (POINT/…)");
    auto p2 = p1 ? read_sub(rd, args[1], Geo::Kind::kPoint, "a (POINT/…)") : std::nullopt;
    auto p3 = p2 ? read_sub(rd, args[2], Geo::Kind::kPoint, "a (POINT/…)") : std::nullopt;
    if (!p3) return std::nullopt;
    g.p = p1->p, g.v = cross(sub(p2->p, p1->p), sub(p3->p, p1->p));
    return g;
  }
  rd.fail(def.loc,
          "PLANE/ as a lathe check or drive surface takes a,b,c,d; (POINT/…),PERPTO,"
          "(VECTOR/…); PERPTO,(PLANE/…),(POINT/…),(POINT/…) or three (POINT/…)");
  return std::nullopt;
}

std::optional<Geo> read_geo(Reader& rd, const Arg& a) {
  if (!a.is_definition()) {
    rd.fail(a.loc, a.is_word() ? fmt::format("'{}' names geometry defined in an APT part program: "
                                             "CL data gives it as a nested (WORD/…) definition",
                                             a.text)
                               : fmt::format("expected a geometry definition, found '{}'", a.text));
    return std::nullopt;
  }
  const std::span<const Arg> args = rd.st.args_of(a);
  if (a.text == "PLANE") return read_plane(rd, a, args);
  Geo g;
  if (a.text == "LINE" && args.size() == 2 && args[0].is_definition()) {
    auto p1 = read_sub(rd, args[0], Geo::Kind::kPoint, "a (POINT/…)");
    auto p2 = p1 ? read_sub(rd, args[1], Geo::Kind::kPoint, "a (POINT/…)") : std::nullopt;
    if (!p2) return std::nullopt;
    g.kind = Geo::Kind::kLine, g.p = p1->p, g.v = sub(p2->p, p1->p);
    return g;
  }
  std::vector<double> n;
  if (!numbers(rd, args, n)) return std::nullopt;
  const auto bad = [&](std::string_view forms) {
    rd.fail(a.loc, fmt::format("({}/…) with {} values: expected {}", a.text, n.size(), forms));
    return std::nullopt;
  };
  if (a.text == "POINT") {
    if (n.size() != 3) return bad("x,y,z");
    g.kind = Geo::Kind::kPoint, g.p = {n[0], n[1], n[2]};
  } else if (a.text == "VECTOR") {
    if (n.size() != 3) return bad("i,j,k");
    g.kind = Geo::Kind::kVector, g.v = {n[0], n[1], n[2]};
  } else if (a.text == "LINE") {
    if (n.size() != 6) return bad("x1,y1,z1,x2,y2,z2");
    g.kind = Geo::Kind::kLine, g.p = {n[0], n[1], n[2]},
    g.v = {n[3] - n[0], n[4] - n[1], n[5] - n[2]};
  } else if (a.text == "CIRCLE" || a.text == "CYLNDR") {
    g.kind = Geo::Kind::kCircle, g.cylinder = a.text == "CYLNDR";
    if (n.size() == 4 && !g.cylinder) {
      g.p = {n[0], n[1], n[2]}, g.r = n[3], g.axis_given = false;
    } else if (n.size() == 7) {
      g.p = {n[0], n[1], n[2]}, g.v = {n[3], n[4], n[5]}, g.r = n[6];
    } else {
      return bad(g.cylinder ? "x,y,z,i,j,k,r" : "x,y,z,r or x,y,z,i,j,k,r");
    }
    if (!(g.r > 0))
      return rd.fail(a.loc, fmt::format("({}/…) radius must be positive, got {}", a.text, g.r)),
             std::nullopt;
  } else {
    rd.fail(a.loc, fmt::format("({}/…) is not a lathe line or arc: a lathe drive or check surface "
                               "is a LINE, CIRCLE, CYLNDR or PLANE in the turning plane",
                               a.text));
    return std::nullopt;
  }
  return g;
}

}  // namespace

namespace {

double ax(const PostState& s, Point3 p) {
  return axis_value(p, s.m.cl_axial);
}
double rad(const PostState& s, Point3 p) {
  return axis_value(p, s.radial);
}

// The definition `a` as a line or circle in the turning plane; nothing (reported) otherwise.
std::optional<Shape> lathe_shape(Reader& rd, const Arg& a) {
  std::optional<Geo> g = read_geo(rd, a);
  if (!g) return std::nullopt;
  PostState& s = rd.s;
  Shape sh;
  const auto off_plane = [&](std::string_view why) {
    rd.fail(a.loc, fmt::format("({}/…) is not a lathe line or arc: {}", a.text, why));
    return std::nullopt;
  };
  if (g->kind == Geo::Kind::kCircle) {
    if (g->axis_given) {
      frame_normal(s, rd.st, g->v);
      const double len = norm(g->v);
      if (std::abs(std::abs(axis_value(g->v, third_axis(s))) / len - 1) > 1e-6)
        return off_plane("its axis is not normal to the turning plane");
    }
    Point3 c = g->p;
    if (g->cylinder) *(&c.x + static_cast<int>(third_axis(s))) = 0;
    if (!frame_point(s, rd.st, c)) return rd.ok = false, std::nullopt;
    sh.circle = true, sh.cu = ax(s, c), sh.cv = rad(s, c), sh.r = g->r;
    return sh;
  }
  Point3 p = g->p, d = g->v;
  if (g->kind == Geo::Kind::kPlane) {
    // A plane that contains the normal of the turning plane cuts it in a line.
    const double len = norm(d);
    if (!(len > 0) || std::abs(axis_value(d, third_axis(s))) > 1e-6 * len)
      return off_plane("the plane is not perpendicular to the turning plane");
    *(&p.x + static_cast<int>(third_axis(s))) = 0;
    const double nu = ax(s, d), nv = rad(s, d);
    sh.cu = ax(s, p), sh.cv = rad(s, p), sh.du = -nv / len, sh.dv = nu / len;
    return sh;
  }
  if (g->kind != Geo::Kind::kLine) return off_plane("a point or vector bounds no motion");
  const Point3 q{p.x + d.x, p.y + d.y, p.z + d.z};
  if (!frame_point(s, rd.st, p) || !frame_point(s, rd.st, q)) return rd.ok = false, std::nullopt;
  const double du = ax(s, d), dv = rad(s, d), len = std::hypot(du, dv);
  if (!(len > 0)) return off_plane("its two points are the same");
  sh.cu = ax(s, p), sh.cv = rad(s, p), sh.du = du / len, sh.dv = dv / len;
  return sh;
}

// Where a check surface stops the motion.
enum class Cond { kTo, kOn, kPast, kTanto };

// The candidate end points of drive `d` on check `c` (cond applied, cutter radius rc).
std::vector<std::pair<double, double>> ends(const Shape& d, Shape c, Cond cond, double rc,
                                            double pu, double pv) {
  std::vector<std::pair<double, double>> out;
  if (cond == Cond::kTanto) {
    if (c.circle && !d.circle) {  // the foot of the centre on the line
      const double t = (c.cu - d.cu) * d.du + (c.cv - d.cv) * d.dv;
      out.push_back({d.cu + t * d.du, d.cv + t * d.dv});
    } else if (c.circle && d.circle) {
      const double du = c.cu - d.cu, dv = c.cv - d.cv, l = std::hypot(du, dv);
      if (l > 0) {
        out.push_back({d.cu + d.r * du / l, d.cv + d.r * dv / l});
        out.push_back({d.cu - d.r * du / l, d.cv - d.r * dv / l});
      }
    } else if (!c.circle && d.circle) {  // the point of the circle whose tangent is the line
      out.push_back({d.cu - c.dv * d.r, d.cv + c.du * d.r});
      out.push_back({d.cu + c.dv * d.r, d.cv - c.du * d.r});
    }
    return out;
  }
  if (cond != Cond::kOn && rc > 0) {  // TO: the near side of the check; PAST: the far side
    if (c.circle) {
      const bool outside = std::hypot(pu - c.cu, pv - c.cv) > c.r;
      c.r += (outside == (cond == Cond::kTo)) ? rc : -rc;
    } else {
      const double side = (pu - c.cu) * -c.dv + (pv - c.cv) * c.du;  // left of the line: > 0
      const double k = ((side > 0) == (cond == Cond::kTo)) ? rc : -rc;
      c.cu += -c.dv * k, c.cv += c.du * k;
    }
  }
  if (!d.circle && !c.circle) {
    const double den = d.du * c.dv - d.dv * c.du;
    if (std::abs(den) < 1e-12) return out;
    const double t = ((c.cu - d.cu) * c.dv - (c.cv - d.cv) * c.du) / den;
    out.push_back({d.cu + t * d.du, d.cv + t * d.dv});
    return out;
  }
  const Shape& circ = d.circle ? d : c;
  const Shape& other = d.circle ? c : d;
  if (!other.circle) {  // line ∩ circle
    const double fu = other.cu - circ.cu, fv = other.cv - circ.cv;
    const double b = fu * other.du + fv * other.dv, q = fu * fu + fv * fv - circ.r * circ.r;
    const double disc = b * b - q;
    if (disc < -kTol * kTol) return out;
    const double h = std::sqrt(std::max(0.0, disc));
    for (double t : {-b - h, -b + h})
      out.push_back({other.cu + t * other.du, other.cv + t * other.dv});
    return out;
  }
  const double du = other.cu - circ.cu, dv = other.cv - circ.cv, l = std::hypot(du, dv);
  if (!(l > 0)) return out;
  const double a = (l * l + circ.r * circ.r - other.r * other.r) / (2 * l);
  const double h2 = circ.r * circ.r - a * a;
  if (h2 < -kTol * kTol) return out;
  const double h = std::sqrt(std::max(0.0, h2));
  const double mu = circ.cu + a * du / l, mv = circ.cv + a * dv / l;
  out.push_back({mu - h * dv / l, mv + h * du / l});
  out.push_back({mu + h * dv / l, mv - h * du / l});
  return out;
}

// How far along drive `d` (from (pu,pv), in the sense `ccw` for a circle, direction (tu,tv) for
// a line) the point (eu,ev) is; negative when it is behind.
double travel(const Shape& d, double pu, double pv, bool ccw, double tu, double tv, double eu,
              double ev) {
  if (!d.circle) return (eu - pu) * tu + (ev - pv) * tv;
  double a = std::atan2(ev - d.cv, eu - d.cu) - std::atan2(pv - d.cv, pu - d.cu);
  if (!ccw) a = -a;
  while (a < 0) a += 2 * kPi;
  while (a >= 2 * kPi) a -= 2 * kPi;
  return a * d.r;
}

}  // namespace

namespace {

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
    error(
        s, st, w.loc,
        fmt::format("expected TO, ON, PAST or TANTO before the check surface, found '{}'", w.text));
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
    if (std::abs(dist - d.r) > kTol) {
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
  if (std::abs(off) > kTol) {
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
  Reader rd{s, st};
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
  for (auto [eu, ev] : ends(*drive, *check, cond, s.cutter_diameter / 2, pu, pv)) {
    const double t = travel(*drive, pu, pv, ccw, tu, tv, eu, ev);
    if (t > kTol) ahead.push_back(t), at.push_back({eu, ev});
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

// PSIS/: the part surface. On a lathe it can only be the turning plane itself.
void psis_stmt(PostState& s, const Statement& st) {
  if (st.args.size() != 1)
    return error(s, st, st.args.empty() ? st.loc : st.args[1].loc,
                 "PSIS/ takes one plane: PSIS/(PLANE/…)");
  Reader rd{s, st};
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

// The geometry of APT geometric motion on a lathe (lathe_geometry.h): nested definitions read
// from a statement, as lines and circles in the turning plane, and their intersections.
#include "interpreter/lathe_geometry.h"

#include <fmt/format.h>

#include <cmath>
#include <numbers>
#include <span>

#include "interpreter/point3_math.h"

namespace clpost {

using namespace point3_math;

namespace {

// The numbers of `args` (all of them), or nothing (reported).
bool numbers(GeoReader& rd, std::span<const Arg> args, std::vector<double>& out) {
  for (size_t i = 0; i < args.size(); ++i) {
    const Arg& a = args[i];
    if (!a.is_number() || !within_limits(a.number)) {
      rd.fail(a.loc, a.is_number() ? fmt::format("number {} in the definition is out of range: CL "
                                                 "values must be between -{} and {}",
                                                 a.text, kMaxClValue, kMaxClValue)
                                   : fmt::format("expected a number in the definition, found {}",
                                                 describe_arg(args, i, "the definition")));
      return false;
    }
    out.push_back(a.number);
  }
  return true;
}

std::optional<Geo> read_sub(GeoReader& rd, const Arg& a, Geo::Kind want, std::string_view what) {
  std::optional<Geo> g = read_geo(rd, a);
  if (g && g->kind != want) {
    rd.fail(a.loc, fmt::format("expected {} here, found ({}/…)", what, a.text));
    return std::nullopt;
  }
  return g;
}

// PLANE/ in its forms: a,b,c,d; (POINT),PERPTO,(VECTOR); PERPTO,(PLANE),(POINT),(POINT);
// (POINT),(POINT),(POINT).
std::optional<Geo> read_plane(GeoReader& rd, const Arg& def, std::span<const Arg> args) {
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

}  // namespace

std::optional<Geo> read_geo(GeoReader& rd, const Arg& a) {
  if (!a.is_definition()) {
    rd.fail(a.loc, a.is_word() ? fmt::format("'{}' names geometry defined in an APT part program: "
                                             "CL data gives it as a nested (WORD/…) definition",
                                             a.text)
                               : fmt::format("expected a geometry definition, found {}",
                                             describe_arg(rd.st, a)));
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

namespace {

double ax(const PostState& s, Point3 p) {
  return axis_value(p, s.m.cl_axial);
}
double rad(const PostState& s, Point3 p) {
  return axis_value(p, s.radial);
}

// The definition `a` as a line or circle in the turning plane; nothing (reported) otherwise.
}  // namespace

std::optional<Shape> lathe_shape(GeoReader& rd, const Arg& a) {
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

std::vector<std::pair<double, double>> check_ends(const Shape& d, Shape c, Cond cond, double rc,
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
    if (disc < -kOnSurface * kOnSurface) return out;
    const double h = std::sqrt(std::max(0.0, disc));
    for (double t : {-b - h, -b + h})
      out.push_back({other.cu + t * other.du, other.cv + t * other.dv});
    return out;
  }
  const double du = other.cu - circ.cu, dv = other.cv - circ.cv, l = std::hypot(du, dv);
  if (!(l > 0)) return out;
  const double a = (l * l + circ.r * circ.r - other.r * other.r) / (2 * l);
  const double h2 = circ.r * circ.r - a * a;
  if (h2 < -kOnSurface * kOnSurface) return out;
  const double h = std::sqrt(std::max(0.0, h2));
  const double mu = circ.cu + a * du / l, mv = circ.cv + a * dv / l;
  out.push_back({mu - h * dv / l, mv + h * du / l});
  out.push_back({mu + h * dv / l, mv - h * du / l});
  return out;
}

double travel(const Shape& d, double pu, double pv, bool ccw, double tu, double tv, double eu,
              double ev) {
  if (!d.circle) return (eu - pu) * tu + (ev - pv) * tv;
  double a = std::atan2(ev - d.cv, eu - d.cu) - std::atan2(pv - d.cv, pu - d.cu);
  if (!ccw) a = -a;
  while (a < 0) a += 2 * std::numbers::pi;
  while (a >= 2 * std::numbers::pi) a -= 2 * std::numbers::pi;
  return a * d.r;
}

}  // namespace clpost

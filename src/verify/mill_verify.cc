#include "verify/mill_verify.h"

#include <fmt/format.h>

#include <algorithm>
#include <cmath>

#include "laws/cut_pass.h"

namespace clpost {

namespace {

constexpr double kPi = 3.14159265358979323846;
constexpr int kSamples = 8;  // each feed move is checked at eighths, as the control moves

// A CL motion: its points in the part frame at C0 (turned by its index), from its start.
struct ClMill {
  uint32_t line = 0;
  bool rapid = false;
  std::vector<PartPoint> points;
};

PartPoint turned(PartPoint p, double degrees) {
  const double a = degrees * kPi / 180, c = std::cos(a), s = std::sin(a);
  return {p.x * c - p.y * s, p.x * s + p.y * c, p.z};
}

double distance(PartPoint a, PartPoint b) {
  return std::sqrt((a.x - b.x) * (a.x - b.x) + (a.y - b.y) * (a.y - b.y) +
                   (a.z - b.z) * (a.z - b.z));
}

// The CL's milling as motions: the pieces of one CL line (an arc's chords) together.
std::vector<ClMill> cl_motions(const std::vector<MillSegment>& cl) {
  std::vector<ClMill> out;
  for (const MillSegment& g : cl) {
    const PartPoint from = turned(g.from, g.index), to = turned(g.to, g.index);
    if (out.empty() || out.back().line != g.line || out.back().rapid != g.rapid ||
        distance(out.back().points.back(), from) > 1e-9)
      out.push_back({g.line, g.rapid, {from}});
    out.back().points.push_back(to);
  }
  return out;
}

// A program position: X (a radius), Y, Z, C.
struct Axes {
  double x = 0, y = 0, z = 0, c = 0;
};
Axes axes(const SimMillMove& m) {
  return {m.x, m.y, m.z, m.c};
}
PartPoint part(Axes a) {
  return turned({a.x, a.y, a.z}, a.c);
}

// The point of the polyline `pts` nearest to `q`.
PartPoint nearest(const std::vector<PartPoint>& pts, PartPoint q) {
  PartPoint best = pts.front();
  for (size_t i = 1; i < pts.size(); ++i) {
    const PartPoint a = pts[i - 1], b = pts[i];
    const double dx = b.x - a.x, dy = b.y - a.y, dz = b.z - a.z;
    const double len2 = dx * dx + dy * dy + dz * dz;
    const double t =
        len2 > 0
            ? std::clamp(((q.x - a.x) * dx + (q.y - a.y) * dy + (q.z - a.z) * dz) / len2, 0.0, 1.0)
            : 0;
    const PartPoint p{a.x + dx * t, a.y + dy * t, a.z + dz * t};
    if (distance(p, q) < distance(best, q)) best = p;
  }
  return best;
}

// How the program's position `a` differs from the CL's point `p`: along the circle of its
// radius when that is all (a C off), else the distance.
std::string difference(Axes a, PartPoint p, double tol) {
  const double r = std::hypot(a.x, a.y), rc = std::hypot(p.x, p.y);
  if (std::abs(a.y) < 1e-9 && std::abs(r - rc) <= tol && std::abs(a.z - p.z) <= tol && r > 0) {
    double cc = std::atan2(p.y, p.x) * 180 / kPi;
    cc += 360 * std::round((a.c - cc) / 360);
    return fmt::format("at C{:.4f}, CL C{:.4f} ({:.4f} mm along the circle of radius {:.4f})", a.c,
                       cc, r * std::abs(a.c - cc) * kPi / 180, r);
  }
  return fmt::format(
      "at X{:.4f} (radius) Y{:.4f} Z{:.4f} C{:.4f}, {:.4f} mm from the CL path at ({:.4f}, "
      "{:.4f}, {:.4f}) (the part at C0)",
      a.x, a.y, a.z, a.c, distance(part(a), p), p.x, p.y, p.z);
}

// The first program move from `k` that ends at `p`, or nc.size().
size_t reaching(const std::vector<SimMillMove>& nc, size_t k, PartPoint p, double tol) {
  while (k < nc.size() && distance(part(axes(nc[k])), p) > tol) ++k;
  return k;
}

struct Walk {
  const std::vector<SimMillMove>& nc;
  double tol;
  bool rollover;  // millturn.c_rotation: the control turns C the shortest way to a C word
  size_t k = 0;   // the next program move
  std::string why;
  const SimMillMove* at = nullptr;  // the program's move the difference is at

  // The feed moves from k through the one that reaches the motion's end, each within the
  // tolerance of the CL path; false (why, at) at the first that is not.
  bool feed(const ClMill& mo) {
    if (k == 0 || distance(part(axes(nc[k - 1])), mo.points.front()) > tol) {
      k = reaching(nc, k, mo.points.front(), tol);
      if (k == nc.size()) return missing(mo.points.front(), 0);
      ++k;
    }
    for (; k < nc.size(); ++k) {
      const Axes a = axes(nc[k - 1]);
      Axes b = axes(nc[k]);
      if (rollover) b.c = a.c + std::remainder(b.c - a.c, 360.0);
      // The end first (a C off at a point is said as such), then the way there.
      for (int i = kSamples; i >= (nc[k].arc ? kSamples : 1); --i) {
        const double t = static_cast<double>(i) / kSamples;
        const Axes q{a.x + (b.x - a.x) * t, a.y + (b.y - a.y) * t, a.z + (b.z - a.z) * t,
                     a.c + (b.c - a.c) * t};
        const PartPoint p = nearest(mo.points, part(q));
        if (distance(p, part(q)) > tol) return off(nc[k], q, p);
      }
      if (distance(part(b), mo.points.back()) <= tol) return ++k, true;
    }
    return missing(mo.points.back(), nc.size() - 1);
  }
  bool off(const SimMillMove& m, Axes q, PartPoint p) {
    why = difference(q, p, tol);
    at = &m;
    return false;
  }
  bool missing(PartPoint p, size_t near) {
    at = nc.empty() ? nullptr : &nc[std::min(near, nc.size() - 1)];
    why = at == nullptr ? std::string("the program has no moves in X, Y, Z and C")
                        : fmt::format("not reached: the program's move here ends {}",
                                      difference(axes(*at), p, tol));
    return false;
  }
  bool rapid(const ClMill& mo) {
    const size_t j = reaching(nc, k, mo.points.back(), tol);
    if (j == nc.size()) return missing(mo.points.back(), k);
    k = j + 1;
    return true;
  }
};

}  // namespace

MillReport verify_milling(const std::vector<MillSegment>& cl, const std::vector<SimMillMove>& nc,
                          size_t nc_count, const Machine& m, const VerifyOptions& options,
                          Diagnostics& nc_diags) {
  MillReport r;
  if (cl.empty()) return r;
  const double shown = std::max(options.tolerance > 0 ? options.tolerance : cut_tolerance(m),
                                m.xzc_tolerance + 0.001);
  const std::vector<ClMill> motions = cl_motions(cl);
  Walk w{nc, shown + 1e-9, m.c_rotation == CRotation::kRollover, 0, {}, nullptr};
  for (const ClMill& mo : motions) {
    if (mo.rapid ? w.rapid(mo) : w.feed(mo)) continue;
    ++r.problems;
    const std::string msg = fmt::format("milling at {}:{}: {}", options.plan_name, mo.line, w.why);
    if (w.at != nullptr) {
      nc_diags.error(SourceLoc{w.at->line, 1}, w.at->line_text, msg);
    } else {
      nc_diags.error({}, {}, msg);
    }
    r.text = fmt::format("  {}  DIFFERS: {}\n", options.plan_name + ":" + std::to_string(mo.line),
                         w.why);
    break;  // one cause: the moves after it are not where the CL's are
  }
  r.text = fmt::format("milling: {} CL motions, {} program moves in X, Y, Z and C\n{}{}\n",
                       motions.size(), nc_count, r.text,
                       r.problems == 0
                           ? fmt::format("ok: every CL point reached in order and every feed move "
                                         "on the CL path, within {:g}",
                                         shown)
                           : std::string("FAILED: the milling is not where the CL says"));
  return r;
}

}  // namespace clpost

#include "laws/xzc_law.h"
#include "support/angles.h"

#include <algorithm>
#include <cmath>

namespace clpost {

namespace {

constexpr int kMaxDepth = 40;       // halvings of one line: 2^-40 of it is far below any tolerance
constexpr double kMaxTurn = 90;     // degrees of C in one piece
constexpr double kOnCentre = 1e-9;  // a radius this small is the centre line

Point3 lerp(Point3 a, Point3 b, double t) {
  return {a.x + (b.x - a.x) * t, a.y + (b.y - a.y) * t, a.z + (b.z - a.z) * t};
}

double distance(Point3 a, Point3 b) {
  return std::sqrt((a.x - b.x) * (a.x - b.x) + (a.y - b.y) * (a.y - b.y) +
                   (a.z - b.z) * (a.z - b.z));
}

// `angle` moved by whole turns to the nearest of `near`.
double nearest(double angle, double near) {
  return angle + 360 * std::round((near - angle) / 360);
}

struct Splitter {
  double index, tol;
  std::vector<XzcPiece>* out;

  // The line from `a` (machine `qa`) to `b` (machine `qb`), halved until each piece is within
  // the tolerance.
  void split(Point3 a, XzcPoint qa, Point3 b, XzcPoint qb, int depth) {
    const bool fine = xzc_deviation(qa, qb, index) <= tol && std::abs(qb.c - qa.c) <= kMaxTurn;
    if (fine || depth >= kMaxDepth) {
      out->push_back({qb, distance(a, b), false});
      return;
    }
    const Point3 m = lerp(a, b, 0.5);
    const XzcPoint qm = xzc_point(m, index, qa.c);
    split(a, qa, m, qm, depth + 1);
    split(m, qm, b, xzc_point(b, index, qm.c), depth + 1);
  }
};

}  // namespace

XzcPoint xzc_point(Point3 p, double index, double near) {
  const double r = std::hypot(p.x, p.y);
  if (r < kOnCentre) return {0, near, p.z};  // on the centre line any C is the point
  return {r, nearest(index + degrees(std::atan2(p.y, p.x)), near), p.z};
}

Point3 part_point(XzcPoint q, double index) {
  const double a = radians(q.c - index);
  return {q.r * std::cos(a), q.r * std::sin(a), q.z};
}

Point3 part_of_machine(double x, double y, double z, double c) {
  const double a = radians(c), cs = std::cos(a), sn = std::sin(a);
  return {x * cs - y * sn, x * sn + y * cs, z};
}

double xzc_deviation(XzcPoint from, XzcPoint to, double index, int samples) {
  const Point3 a = part_point(from, index), b = part_point(to, index);
  double worst = 0;
  for (int k = 1; k < samples; ++k) {
    const double t = static_cast<double>(k) / samples;
    const XzcPoint q{from.r + (to.r - from.r) * t, from.c + (to.c - from.c) * t,
                     from.z + (to.z - from.z) * t};
    worst = std::max(worst, distance(part_point(q, index), lerp(a, b, t)));
  }
  return worst;
}

std::vector<XzcPiece> xzc_line(Point3 a, Point3 b, double index, double c_from, double tol) {
  std::vector<XzcPiece> out;
  const double dx = b.x - a.x, dy = b.y - a.y, len2 = dx * dx + dy * dy;
  // Where the line comes closest to the centre line, as a fraction of it.
  const double t = len2 > 0 ? std::clamp(-(a.x * dx + a.y * dy) / len2, 0.0, 1.0) : 0;
  const Point3 m = lerp(a, b, t);
  const XzcPoint qa = xzc_point(a, index, c_from);
  if (std::hypot(m.x, m.y) <= tol && std::hypot(b.x, b.y) >= kOnCentre) {
    // Through (or within the tolerance of) the centre: straight in at a's C, C turns with the
    // tool on the centre, straight out at b's C. Both are radial lines: exact.
    const double at_m = distance(a, m);
    if (at_m > 0 && std::hypot(a.x, a.y) >= kOnCentre) out.push_back({{0, qa.c, m.z}, at_m, false});
    const XzcPoint qb = xzc_point(b, index, qa.c);
    if (std::abs(qb.c - qa.c) > 1e-9) {
      // The turn the shortest way, in steps a rollover control takes the same way.
      const int steps = std::abs(qb.c - qa.c) > kMaxTurn ? 2 : 1;
      for (int k = 1; k <= steps; ++k)
        out.push_back({{0, qa.c + (qb.c - qa.c) * k / steps, m.z}, 0, true});
    }
    out.push_back({qb, distance(m, b), false});
    return out;
  }
  Splitter{index, tol, &out}.split(a, qa, b, xzc_point(b, index, qa.c), 0);
  return out;
}

}  // namespace clpost

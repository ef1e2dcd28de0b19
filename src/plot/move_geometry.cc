#include "plot/move_geometry.h"

#include <algorithm>
#include <cmath>
#include <numbers>

namespace clpost {

namespace {

bool finite(Vec2 p) {
  return std::isfinite(p.x) && std::isfinite(p.z);
}
bool is_arc(MoveKind k) {
  return k == MoveKind::kArcCw || k == MoveKind::kArcCcw;
}

}  // namespace

bool finite_move(const Move& m) {
  return finite(m.from) && finite(m.to) && (!is_arc(m.kind) || finite(m.center));
}

ArcSweep arc_sweep(const Move& m) {
  constexpr double kTwoPi = 2 * std::numbers::pi;
  const double r0 = std::hypot(m.from.x - m.center.x, m.from.z - m.center.z);
  const double r1 = std::hypot(m.to.x - m.center.x, m.to.z - m.center.z);
  ArcSweep a;
  if (r0 <= 0 || r1 <= 0) return a;
  a.radius = (r0 + r1) / 2;
  a.start = std::atan2(m.from.x - m.center.x, m.from.z - m.center.z);
  const double end = std::atan2(m.to.x - m.center.x, m.to.z - m.center.z);
  double ccw = std::fmod(end - a.start, kTwoPi);
  if (ccw < 0) ccw += kTwoPi;
  const bool closed = std::hypot(m.to.x - m.from.x, m.to.z - m.from.z) <= 1e-9 * a.radius;
  if (closed) {
    a.sweep = m.kind == MoveKind::kArcCw ? -kTwoPi : kTwoPi;
  } else {
    a.sweep = m.kind == MoveKind::kArcCw ? (ccw == 0 ? 0 : ccw - kTwoPi) : ccw;
  }
  return a;
}

Vec2 arc_point(Vec2 center, double radius, double angle) {
  return {center.x + radius * std::sin(angle), center.z + radius * std::cos(angle)};
}

void Bounds::add(Vec2 p) {
  if (empty) {
    z_lo = z_hi = p.z;
    x_lo = x_hi = p.x;
    empty = false;
    return;
  }
  z_lo = std::min(z_lo, p.z);
  z_hi = std::max(z_hi, p.z);
  x_lo = std::min(x_lo, p.x);
  x_hi = std::max(x_hi, p.x);
}

size_t draw_class(MoveKind k) {
  switch (k) {
    case MoveKind::kRapid:
      return 0;
    case MoveKind::kFeed:
      return 1;
    case MoveKind::kArcCw:
    case MoveKind::kArcCcw:
      return 2;
    case MoveKind::kThread:
      return 3;
  }
  return 1;
}

void add_move_bounds(Bounds& b, const Move& m) {
  b.add(m.from);
  b.add(m.to);
  if (!is_arc(m.kind)) return;
  const ArcSweep a = arc_sweep(m);
  if (a.radius <= 0) return;
  // The quarter angles k*pi/2 the sweep passes.
  const double lo = std::min(a.start, a.start + a.sweep), hi = std::max(a.start, a.start + a.sweep);
  const double q = std::numbers::pi / 2;
  for (double k = std::ceil(lo / q); k * q <= hi; k += 1)
    b.add(arc_point(m.center, a.radius, k * q));
}

void PathMeasure::add(const Move& m) {
  if (!finite_move(m)) return;
  if (!has_start) {
    has_start = true;
    start = m.from;
  }
  const size_t i = draw_class(m.kind);
  ++moves[i];
  const ArcSweep a = i == 2 ? arc_sweep(m) : ArcSweep{};
  if (a.radius > 0 && a.sweep != 0) {
    length[i] += a.radius * std::fabs(a.sweep);
  } else {
    length[i] += std::hypot(m.to.x - m.from.x, m.to.z - m.from.z);
  }
  add_move_bounds(all, m);
  if (i != 0) add_move_bounds(cut, m);
}

Bounds toolpath_bounds(const Toolpath& tp, bool rapids) {
  Bounds b;
  for (const Move& m : tp.moves) {
    if (!finite_move(m) || (!rapids && m.kind == MoveKind::kRapid)) continue;
    add_move_bounds(b, m);
  }
  return b;
}

}  // namespace clpost

#include "plot/mill_views.h"

#include <algorithm>
#include <array>
#include <cmath>
#include <numbers>

#include "laws/xzc_law.h"
#include "simulator/mill_arc.h"
#include "support/angles.h"

namespace clpost {
namespace {

constexpr double kStepDegrees = 5;  // a move turning C is drawn in steps of at most this

double angle_near(double a, double near) {
  return a + 2 * std::numbers::pi * std::round((near - a) / (2 * std::numbers::pi));
}

// A machine position in X (a radius), Y, Z, C.
using Axes = MillAxes;

}  // namespace

MillViews::MillViews(bool rollover, bool y_axis, ThinOptions options)
    : rollover_(rollover), y_axis_(y_axis), face_(options), peripheral_(options) {}

void MillViews::mill_move(const SimMillMove& m) {
  // The tool that writes C (a C word changing it, or the first) works on the C axis, and so does
  // one that moves in a milling plane (G17, G19: the lathe turns in G18) at the C the last left
  // (MillTurn3x_PATH1's face tool 5 after tool 4 put C back to its index).
  if (m.c_known && (!c_seen_ || m.c != last_c_ || m.plane != 18)) c_tool_ = m.tool;
  c_seen_ = c_seen_ || m.c_known;
  last_c_ = m.c;
  c_work_ = m.c_known && m.tool == c_tool_;
  if (c_work_ && has_prev_ && prev_.c_known && m.at_known) draw(prev_, m);
  if (m.at_known) {
    prev_ = m;
    prev_.line_text.clear();  // only its axes are needed
    has_prev_ = true;
  }
}

bool MillViews::side_move(const Move& m, const CutState& state) {
  if (m.mill || (c_work_ && state.tool == c_tool_)) return false;
  if (m.kind != MoveKind::kRapid)
    stock_ = std::max({stock_, std::fabs(m.from.x), std::fabs(m.to.x)});
  return true;
}

double MillViews::unrolled(Point3 p) {
  if (unroll_r_ == 0) unroll_r_ = std::max(std::hypot(p.x, p.y), 1e-6);
  double a = std::atan2(p.y, p.x);
  a = has_angle_ ? angle_near(a, last_angle_) : (a < 0 ? a + 2 * std::numbers::pi : a);
  has_angle_ = true;
  last_angle_ = a;
  return unroll_r_ * a;
}

// The machine's motion from `a` to `b` in the part frame, in steps: X, Y, Z and C linear (C the
// shortest way on a rollover control), or along the arc of a G2/G3.
void MillViews::draw(const SimMillMove& a, const SimMillMove& b) {
  const double c0 = a.c;
  const double c1 = rollover_ ? c0 + std::remainder(b.c - c0, 360.0) : b.c;
  std::vector<Axes> steps = b.arc ? mill_arc_points(a, b, kStepDegrees) : std::vector<Axes>{};
  if (steps.empty()) {
    const int n = std::max(1, static_cast<int>(std::ceil(std::fabs(c1 - c0) / kStepDegrees)));
    for (int i = 1; i <= n; ++i) {
      const double t = static_cast<double>(i) / n;
      steps.push_back({a.x + (b.x - a.x) * t, a.y + (b.y - a.y) * t, a.z + (b.z - a.z) * t,
                       c0 + (c1 - c0) * t});
    }
  }
  const bool side = b.plane == 19 || (y_axis_ && b.plane == 18);
  // The peripheral view's radius is its first feed's: the rapids before it (approaches from
  // far off) are not drawn.
  if (side && b.rapid && unroll_r_ == 0) return;
  Move mv;
  mv.kind = b.rapid ? MoveKind::kRapid : MoveKind::kFeed;
  mv.line = static_cast<int>(b.line);
  const auto at = [&](const Axes& q) {
    const Point3 p = part_of_machine(q.x, q.y, q.z, q.c);
    if (side) return Vec2{unrolled(p), p.z};
    if (!b.rapid) work_radius_ = std::max(work_radius_, std::hypot(p.x, p.y));
    return Vec2{p.y, p.x};
  };
  Vec2 from = at({a.x, a.y, a.z, c0});
  for (const Axes& q : steps) {
    const Vec2 to = at(q);
    if (to.x != from.x || to.z != from.z) {
      mv.from = from;
      mv.to = to;
      (side ? peripheral_ : face_).add(mv);
    }
    from = to;
  }
}

MillViewsDrawn MillViews::finish(const std::vector<SimHole>& holes, LengthUnit units) {
  MillViewsDrawn out;
  // Without peripheral milling: unrolled at the stock, else at the radial holes' tops.
  if (unroll_r_ == 0 && stock_ > 0) unroll_r_ = stock_;
  for (const SimHole& h : holes)
    if (unroll_r_ == 0 && h.radial && h.c) unroll_r_ = std::fabs(h.r);
  for (const SimHole& h : holes) {
    if (!h.c) continue;  // C never written: not C work
    if (out.face_holes.size() + out.radial_holes.size() >= kMaxHoleMarks) {
      ++out.holes_not_drawn;
      continue;
    }
    if (h.radial) {
      const double deg = *h.c - 360 * std::floor(*h.c / 360);
      out.radial_holes.push_back({unroll_r_ * radians(deg), h.z});
      continue;
    }
    const Point3 p = part_of_machine(h.x, 0, 0, *h.c);
    work_radius_ = std::max(work_radius_, std::fabs(h.x));
    out.face_holes.push_back({p.y, p.x});
  }
  out.face = face_.finish(units);
  out.peripheral = peripheral_.finish(units);
  out.stock_turned = stock_ > 0;
  out.stock_radius = stock_ > 0 ? stock_ : work_radius_;
  out.unroll_radius = unroll_r_;
  return out;
}

}  // namespace clpost

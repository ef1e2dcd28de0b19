#include "verify/mill_verify.h"

#include <fmt/format.h>

#include <algorithm>
#include <cmath>
#include <deque>
#include <optional>

#include "laws/cut_pass.h"
#include "simulator/mill_arc.h"
#include "support/angles.h"

namespace clpost {

namespace {

constexpr int kSamples = 8;            // each feed move is checked at eighths, as the control moves
constexpr double kArcStepDegrees = 5;  // an arc at least at its eighths, at most 5 degrees apart
constexpr size_t kWindow = 1 << 14;    // program moves held for CL motions not yet posted

// A CL motion: its points in the part frame at C0 (turned by its index), from its start.
struct ClMill {
  uint32_t line = 0;
  bool rapid = false;
  std::vector<Point3> points;
};

Point3 turned(Point3 p, double degrees) {
  return part_of_machine(p.x, p.y, p.z, degrees);
}

double distance(Point3 a, Point3 b) {
  return std::sqrt((a.x - b.x) * (a.x - b.x) + (a.y - b.y) * (a.y - b.y) +
                   (a.z - b.z) * (a.z - b.z));
}

// A program position: X (a radius), Y, Z, C.
using Axes = MillAxes;
Axes axes(const SimMillMove& m) {
  return {m.x, m.y, m.z, m.c};
}
Point3 part(Axes a) {
  return part_of_machine(a.x, a.y, a.z, a.c);
}

// The point of the polyline `pts` nearest to `q`.
Point3 nearest(const std::vector<Point3>& pts, Point3 q) {
  Point3 best = pts.front();
  for (size_t i = 1; i < pts.size(); ++i) {
    const Point3 a = pts[i - 1], b = pts[i];
    const double dx = b.x - a.x, dy = b.y - a.y, dz = b.z - a.z;
    const double len2 = dx * dx + dy * dy + dz * dz;
    const double t =
        len2 > 0
            ? std::clamp(((q.x - a.x) * dx + (q.y - a.y) * dy + (q.z - a.z) * dz) / len2, 0.0, 1.0)
            : 0;
    const Point3 p{a.x + dx * t, a.y + dy * t, a.z + dz * t};
    if (distance(p, q) < distance(best, q)) best = p;
  }
  return best;
}

// How the program's position `a` differs from the CL's point `p`: along the circle of its
// radius when that is all (a C off), else the distance.
std::string difference(Axes a, Point3 p, double tol) {
  const double r = std::hypot(a.x, a.y), rc = std::hypot(p.x, p.y);
  if (std::abs(a.y) < 1e-9 && std::abs(r - rc) <= tol && std::abs(a.z - p.z) <= tol && r > 0) {
    double cc = degrees(std::atan2(p.y, p.x));
    cc += 360 * std::round((a.c - cc) / 360);
    return fmt::format("at C{:.4f}, CL C{:.4f} ({:.4f} mm along the circle of radius {:.4f})", a.c,
                       cc, r * radians(std::abs(a.c - cc)), r);
  }
  return fmt::format(
      "at X{:.4f} (radius) Y{:.4f} Z{:.4f} C{:.4f}, {:.4f} mm from the CL path at ({:.4f}, "
      "{:.4f}, {:.4f}) (the part at C0)",
      a.x, a.y, a.z, a.c, distance(part(a), p), p.x, p.y, p.z);
}

}  // namespace

// The walk (docs/millturn.md), forward only: each CL motion in order, the program's moves as
// they come. A rapid: the first move from where the walk is that ends at its end. A feed: from
// its start (the move before, else the first move from where the walk is that ends there), each
// move within the tolerance of the motion's path until one ends at its end. One cause is
// reported: the walk stops at the first problem.
struct MillStream::Impl {
  enum class Phase { kIdle, kSeek, kFollow };
  double tol = 0, shown = 0;
  bool rollover = false;        // millturn.c_rotation: the control turns C the shortest way
  std::string arc_cw, arc_ccw;  // the machine's G2 and G3
  std::string plan_name;
  std::deque<ClMill> motions;                    // complete, not yet walked
  ClMill open;                                   // the motion being received
  size_t motion_count = 0;                       // CL motions in all
  std::deque<SimMillMove> waiting;               // program moves no CL motion is there for yet
  std::optional<SimMillMove> first, prev, last;  // nc[0], nc[k - 1], nc[size - 1]
  std::optional<SimMillMove> scan_start;         // a seek's first move looked at (nc[k])
  Phase phase = Phase::kIdle;
  Point3 target;
  bool seek_feed = false;
  bool failed = false;
  bool cl_ended = false;
  uint32_t failed_line = 0;
  std::string why;
  std::optional<SimMillMove> at;  // the program's move the difference is at

  const ClMill& current() const { return motions.front(); }
  void begin() {
    if (motions.empty()) return void(phase = Phase::kIdle);
    const ClMill& mo = current();
    scan_start.reset();
    if (mo.rapid || !prev || distance(part(axes(*prev)), mo.points.front()) > tol) {
      phase = Phase::kSeek;
      seek_feed = !mo.rapid;
      target = mo.rapid ? mo.points.back() : mo.points.front();
    } else {
      phase = Phase::kFollow;
    }
  }
  void done() {
    motions.pop_front();
    begin();
  }
  void fail(const SimMillMove* m, std::string text) {
    failed = true;
    failed_line = current().line;
    why = std::move(text);
    if (m != nullptr) at = *m;
    motions.clear();
    waiting.clear();
    phase = Phase::kIdle;
  }
  void missing(const std::optional<SimMillMove>& near, Point3 p) {
    if (!near) return fail(nullptr, "the program has no moves in X, Y, Z and C");
    fail(&*near, fmt::format("not reached: the program's move here ends {}",
                             difference(axes(*near), p, tol)));
  }
  void step(const SimMillMove& m) {
    if (phase == Phase::kSeek) return seek(m);
    follow(m);
  }
  void seek(const SimMillMove& m) {
    if (distance(part(axes(m)), target) > tol) {
      if (!scan_start) scan_start = m;
      return;
    }
    prev = m;
    if (current().rapid) return done();
    phase = Phase::kFollow;
  }
  void follow(const SimMillMove& m) {
    const ClMill& mo = current();
    const Axes a = axes(*prev);
    Axes b = axes(m);
    if (rollover) b.c = a.c + std::remainder(b.c - a.c, 360.0);
    // The end first (a C off at a point is said as such), then the way there.
    const Point3 end = nearest(mo.points, part(b));
    if (distance(end, part(b)) > tol) return fail(&m, difference(b, end, tol));
    if (m.arc) return follow_arc(m);
    for (int i = kSamples - 1; i >= 1; --i) {
      const double t = static_cast<double>(i) / kSamples;
      const Axes q{a.x + (b.x - a.x) * t, a.y + (b.y - a.y) * t, a.z + (b.z - a.z) * t,
                   a.c + (b.c - a.c) * t};
      const Point3 p = nearest(mo.points, part(q));
      if (distance(p, part(q)) > tol) return fail(&m, difference(q, p, tol));
    }
    followed(m);
  }
  void followed(const SimMillMove& m) {
    prev = m;
    if (distance(part(axes(m)), current().points.back()) <= tol) done();
  }
  // A G2/G3 along its length, as the control moves it: its end on its circle (the centre as
  // far from both ends), then its points on the CL path, the way it turns.
  void follow_arc(const SimMillMove& m) {
    const std::vector<Axes> pts = mill_arc_points(*prev, m, kArcStepDegrees, kSamples);
    const Axes o = mill_arc_centre(*prev, m);
    const std::string arc = fmt::format("the arc ({} about X{:.4f} (radius) Y{:.4f} Z{:.4f})",
                                        m.ccw ? arc_ccw : arc_cw, o.x, o.y, o.z);
    if (pts.empty()) return fail(&m, arc + " starts at its centre");
    const double off = distance(part(pts.back()), part(axes(m)));
    if (off > tol)
      return fail(
          &m, fmt::format("{}: its end is {:.4f} mm off the circle through its start", arc, off));
    for (const Axes& q : pts) {
      const Point3 p = nearest(current().points, part(q));
      if (distance(p, part(q)) > tol) return fail(&m, arc + " passes " + difference(q, p, tol));
    }
    followed(m);
  }
  // The program ended with the walk at a motion: it is not reached.
  void ended() {
    if (phase == Phase::kIdle) return;
    const ClMill& mo = current();
    if (phase == Phase::kFollow) return missing(last, mo.points.back());
    if (seek_feed) return missing(first, target);
    missing(scan_start ? scan_start : last, target);
  }
  void motion_complete() {
    if (open.points.empty()) return;
    ++motion_count;
    if (failed) return void(open.points.clear());
    motions.push_back(std::move(open));
    open.points.clear();
    if (phase != Phase::kIdle) return;
    begin();
    while (!waiting.empty() && phase != Phase::kIdle) {
      const SimMillMove m = std::move(waiting.front());
      waiting.pop_front();
      step(m);
    }
  }
};

MillStream::MillStream(const Machine& m, const VerifyOptions& options)
    : impl_(std::make_unique<Impl>()) {
  Impl& w = *impl_;
  w.shown = std::max(options.tolerance > 0 ? options.tolerance : cut_tolerance(m),
                     m.xzc_tolerance + 0.001);
  w.tol = w.shown + 1e-9;
  w.rollover = m.c_rotation == CRotation::kRollover;
  w.arc_cw = m.code("arc_cw"), w.arc_ccw = m.code("arc_ccw");
  w.plan_name = options.plan_name;
}

MillStream::~MillStream() = default;

// The CL's milling as motions: the pieces of one CL line (an arc's chords) together.
void MillStream::cl_segment(const MillSegment& g) {
  Impl& w = *impl_;
  const Point3 from = turned(g.from, g.index), to = turned(g.to, g.index);
  if (w.open.points.empty() || w.open.line != g.line || w.open.rapid != g.rapid ||
      distance(w.open.points.back(), from) > 1e-9) {
    w.motion_complete();
    w.open = {g.line, g.rapid, {from}};
  }
  w.open.points.push_back(to);
}

void MillStream::cl_break() {
  impl_->motion_complete();
}

void MillStream::cl_ended() {
  impl_->motion_complete();
  impl_->cl_ended = true;
  impl_->waiting.clear();
}

void MillStream::program_move(const SimMillMove& m) {
  Impl& w = *impl_;
  if (!w.first) w.first = m;
  w.last = m;
  if (w.failed) return;
  if (w.phase != Impl::Phase::kIdle) return w.step(m);
  if (w.cl_ended) return;  // every CL motion walked: the rest is not milling the CL says
  // No CL motion for it yet. The CL runs ahead of its program (clpost --verify) or comes whole
  // before it: what waits is the moves after milling until the CL mills again, of which only a
  // window is kept (as PathStream's).
  if (w.waiting.size() == kWindow) w.waiting.pop_front();
  w.waiting.push_back(m);
}

MillReport MillStream::finish(size_t nc_count, Diagnostics& nc_diags) {
  Impl& w = *impl_;
  w.motion_complete();
  MillReport r;
  if (w.motion_count == 0) return r;
  if (!w.failed) w.ended();
  if (w.failed) {
    r.problems = 1;
    const std::string msg = fmt::format("milling at {}:{}: {}", w.plan_name, w.failed_line, w.why);
    if (w.at) {
      nc_diags.error(SourceLoc{w.at->line, 1}, w.at->line_text, msg);
    } else {
      nc_diags.error({}, {}, msg);
    }
    r.text = fmt::format("  {}  DIFFERS: {}\n", w.plan_name + ":" + std::to_string(w.failed_line),
                         w.why);
  }
  r.text = fmt::format("milling: {} CL motions, {} program moves in X, Y, Z and C\n{}{}\n",
                       w.motion_count, nc_count, r.text,
                       r.problems == 0
                           ? fmt::format("ok: every CL point reached in order and every feed move "
                                         "on the CL path, within {:g}",
                                         w.shown)
                           : std::string("FAILED: the milling is not where the CL says"));
  return r;
}

MillReport verify_milling(const std::vector<MillSegment>& cl, const std::vector<SimMillMove>& nc,
                          size_t nc_count, const Machine& m, const VerifyOptions& options,
                          Diagnostics& nc_diags) {
  MillStream s(m, options);
  for (const MillSegment& g : cl) s.cl_segment(g);
  for (const SimMillMove& mv : nc) s.program_move(mv);
  return s.finish(nc_count, nc_diags);
}
}  // namespace clpost

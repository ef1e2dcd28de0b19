#include "plot/path_thinner.h"

#include <fmt/format.h>

#include <cmath>
#include <functional>
#include <numbers>
#include <utility>

#include "plot/backplot_svg.h"
#include "support/angles.h"

namespace clpost {

namespace {

constexpr size_t kRescaleEvery = 256;  // moves between two looks at the scale while streaming

double dist(Vec2 a, Vec2 b) {
  return std::hypot(b.x - a.x, b.z - a.z);
}

// > 0 when direction v is counterclockwise of u (Z right, X up).
double cross(Vec2 u, Vec2 v) {
  return u.z * v.x - u.x * v.z;
}
double dot(Vec2 u, Vec2 v) {
  return u.z * v.z + u.x * v.x;
}
// u turned counterclockwise by the angle of cosine c and sine s.
Vec2 turned(Vec2 u, double c, double s) {
  return {u.z * s + u.x * c, u.z * c - u.x * s};
}

// Whether the direction from `a` through `p` to `q` turns by at most kTurnDegrees at `p`
// (a zero-length leg does not turn).
bool straight_on(Vec2 a, Vec2 p, Vec2 q) {
  const double ux = p.x - a.x, uz = p.z - a.z, vx = q.x - p.x, vz = q.z - p.z;
  const double nu = std::hypot(ux, uz), nv = std::hypot(vx, vz);
  if (nu == 0 || nv == 0) return true;
  return (ux * vx + uz * vz) / (nu * nv) >= std::cos(radians(kTurnDegrees));
}

// "1 000 000": thousands set apart by spaces.
std::string grouped(size_t n) {
  std::string digits = fmt::format("{}", n), out;
  for (size_t i = 0; i < digits.size(); ++i) {
    if (i > 0 && (digits.size() - i) % 3 == 0) out += ' ';
    out += digits[i];
  }
  return out;
}

}  // namespace

size_t PathThinner::KeyHash::operator()(const Key& k) const {
  size_t h = std::hash<int>()(static_cast<int>(k.kind));
  for (double v : {k.fx, k.fz, k.tx, k.tz}) h = h * 1000003u ^ std::hash<double>()(v);
  return h;
}

std::string simplified_note(const ThinnedPath& p) {
  if (!p.simplified()) return {};
  std::string s = fmt::format("path simplified: {} moves drawn as {} (tolerance {} px)",
                              grouped(p.measure.total()), grouped(p.path.moves.size()),
                              fmt::format("{:g}", p.tolerance_px));
  if (p.dropped > 0) s += fmt::format("; {} moves past the budget not drawn", grouped(p.dropped));
  return s;
}

PathThinner::PathThinner(ThinOptions options) : opt_(options), tol_px_(options.tolerance_px) {}

double PathThinner::tol() const {
  return scale_ > 0 ? tol_px_ / scale_ : 0;
}

void PathThinner::note_scale() {
  if (!out_.measure.cut.empty || !out_.measure.all.empty)
    scale_ = backplot_scale(out_.measure.all, out_.measure.cut);
}

void PathThinner::add(const Move& m) {
  if (!finite_move(m)) return;
  out_.measure.add(m);
  if (scale_ == 0 || out_.measure.total() % kRescaleEvery == 0) note_scale();
  // Full: counted, not drawn (before the budget's test, which a full path may still fail: moves
  // that merge at no tolerance would be thinned again at every move).
  if (full_) {
    ++out_.dropped;
    return;
  }
  if (out_.path.moves.size() > opt_.budget) {
    flush();
    note_scale();
    rethin(scale_);  // first at the scale as it is now: the tolerance grows only if need be
    while (out_.path.moves.size() > opt_.budget / 2 && tol_px_ * 2 <= kMaxTolerancePx) {
      tol_px_ *= 2;
      rethin(scale_);
    }
    if (out_.path.moves.size() > opt_.budget / 2) full_ = true;
  }
  if (full_) {
    ++out_.dropped;
    return;
  }
  take(m, true);
}

void PathThinner::take(const Move& m, bool fresh) {
  const size_t cls = draw_class(m.kind);
  bool straight = cls == 1;
  if (cls == 2) {
    const ArcSweep a = arc_sweep(m);
    const double chord = dist(m.from, m.to);
    straight = a.radius <= 0 || (std::fabs(a.sweep) <= std::numbers::pi && chord < tol() &&
                                 a.radius * (1 - std::cos(a.sweep / 2)) < tol());
  }
  if (straight) {
    take_straight(m);
    return;
  }
  flush();
  if (cls != 2 && fresh && protected_ >= opt_.budget / 2 &&
      seen_.count({m.kind, m.from.x, m.from.z, m.to.x, m.to.z}) == 0) {
    ++out_.dropped;
    return;
  }
  keep(m);
}

// Whether the pending end point can be dropped for a merged move to `q`; `trial` gets the
// chain as it is then.
bool PathThinner::can_drop(Vec2 q, Chain& trial) const {
  const double t = tol();
  const Vec2 a = trial.anchor, p = trial.last;
  if (!(dist(trial.prev, p) < t) && !straight_on(trial.prev, p, q)) return false;
  const double d = dist(a, p);
  if (d > t) {
    // The directions from the anchor whose ray passes within t of p: within asin(t / d) of it.
    const Vec2 u{(p.x - a.x) / d, (p.z - a.z) / d};
    const double sn = t / d, cs = std::sqrt(1 - sn * sn);
    const Vec2 lo = turned(u, cs, -sn), hi = turned(u, cs, sn);
    if (!trial.cone) {
      trial.cone = true;
      trial.ref = u;
      trial.lo = lo;
      trial.hi = hi;
    } else {
      if (dot(u, trial.ref) <= 0) return false;
      if (cross(trial.lo, lo) > 0) trial.lo = lo;
      if (cross(trial.hi, hi) < 0) trial.hi = hi;
      if (cross(trial.lo, trial.hi) < 0) return false;
    }
  }
  trial.far = std::max(trial.far, d);
  if (!trial.cone) return true;
  const Vec2 v{q.x - a.x, q.z - a.z};
  return dist(a, q) >= trial.far - t && dot(v, trial.ref) > 0 && cross(trial.lo, v) >= 0 &&
         cross(v, trial.hi) >= 0;
}

void PathThinner::take_straight(const Move& m) {
  const size_t cls = draw_class(m.kind);
  Chain& c = chain_;
  if (!c.open || c.cls != cls || !(c.last.x == m.from.x && c.last.z == m.from.z)) {
    flush();
    c = Chain{};
    c.open = true;
    c.cls = cls;
    c.anchor = c.prev = m.from;
    c.last = m.to;
    c.tmpl = m;
    return;
  }
  Chain trial = c;
  if (can_drop(m.to, trial)) {
    c = trial;
  } else {
    flush();
    c.open = true;
    c.anchor = c.last;
    c.cone = false;
    c.far = 0;
  }
  c.prev = c.last;
  c.last = m.to;
  c.tmpl = m;
}

void PathThinner::flush() {
  if (!chain_.open) return;
  Move m = chain_.tmpl;
  m.from = chain_.anchor;
  m.to = chain_.last;
  if (chain_.cls == 2) m.center = m.from;  // drawn straight (arc_sweep: radius 0)
  chain_.open = false;
  keep(m);
}

void PathThinner::keep(const Move& m) {
  if (!seen_.insert({m.kind, m.from.x, m.from.z, m.to.x, m.to.z}).second) return;
  if (m.kind == MoveKind::kRapid || m.kind == MoveKind::kThread) ++protected_;
  out_.path.moves.push_back(m);
}

void PathThinner::rethin(double scale) {
  std::vector<Move> kept = std::move(out_.path.moves);
  out_.path.moves.clear();
  chain_ = Chain{};
  seen_.clear();
  protected_ = 0;
  scale_ = scale;
  for (const Move& m : kept) take(m, false);
  flush();
}

ThinnedPath PathThinner::finish(LengthUnit units) {
  flush();
  const double final_scale = out_.measure.all.empty && out_.measure.cut.empty
                                 ? 0
                                 : backplot_scale(out_.measure.all, out_.measure.cut);
  if (final_scale > 0 && final_scale != scale_) rethin(final_scale);
  while (out_.path.moves.size() > opt_.budget && tol_px_ * 2 <= kMaxTolerancePx) {
    tol_px_ *= 2;
    rethin(final_scale);
  }
  out_.path.units = units;
  out_.tolerance_px = tol_px_;
  return std::move(out_);
}

}  // namespace clpost

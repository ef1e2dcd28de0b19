// Motion statements: GOTO, FROM, GODLTA, CIRCLE (+ the GOTO that ends its arc), RAPID, read
// here and written by the path of the tool loaded (tool_path.h); and the lathe's own move
// (move_to) with verify's record of it.
#include <fmt/format.h>

#include <algorithm>
#include <cmath>

#include "interpreter/statement_table.h"
#include "interpreter/tool_path.h"

namespace clpost {

namespace {

// Whether the program says where an arc starts; false (reported) when it does not.
bool arc_start_known(PostState& s, const Statement& st) {
  if (!s.pos) {
    error(s, st, st.loc, "an arc needs a start point: no GOTO or FROM before CIRCLE/");
    return false;
  }
  // GOHOME's point names the machine's home, but the control is at its reference position, which
  // the program does not state: an arc from there would be measured from elsewhere.
  if (s.prog.is_at_machine_position() && s.home_line > 0) {
    error(s, st, st.loc,
          fmt::format("an arc cannot start at the machine's home (GOHOME at line {} wrote its home "
                      "template, a position the program does not state): move to the arc's start "
                      "first",
                      s.home_line));
    return false;
  }
  return true;
}

// The arc of CIRCLE/ `c` from where the tool is to `p`; false when it cannot be cut (reported).
bool arc_to(PostState& s, const Statement& st, const Circle& c, Point3 p) {
  if (!arc_start_known(s, st)) return false;
  const LathePoint from = lathe(s, *s.pos), target = lathe(s, p);
  const LathePoint center = lathe(s, Point3{c.cx, c.cy, c.cz});
  const double r0 = std::hypot(from.r - center.r, from.z - center.z);
  const double r1 = std::hypot(target.r - center.r, target.z - center.z);
  const double tol = std::max(1e-3, 1e-4 * std::max(r0, r1));
  if (std::abs(r0 - r1) > tol) {
    error(s, st, st.loc,
          fmt::format("arc end point is not on the circle of line {}: distance from the centre "
                      "{:.6g} at the start, {:.6g} at the end",
                      c.loc.line, r0, r1));
    return false;
  }
  // An arc that ends where the program put the tool moves nothing: a block of I and K alone is a
  // full circle on most controls, a gouge through a lathe profile.
  if (s.prog.stays_at(target)) {
    warning(s, st, st.loc,
            fmt::format("the arc of the CIRCLE/ at line {} ends where it starts: nothing is cut (a "
                        "full circle is no lathe profile)",
                        c.loc.line));
    if (s.opts.keep_motions) s.cl_path.motions.back().stays = true;  // verify: nothing to reach
    return true;
  }
  // A centre that the output's resolution puts on the start (I0 K0) is no arc the control can
  // cut: the arc, shorter than two least increments, is written as the straight move it is.
  if (s.prog.arc_has_no_radius(center)) {
    warning(s, st, st.loc,
            fmt::format("the arc of the CIRCLE/ at line {} (radius {:.6g}) is written with I and K "
                        "zero at this machine's resolution: written as a straight move",
                        c.loc.line, r0));
    s.prog.comment(fmt::format("arc of radius {:.6g} written as a straight move", r0));
    s.prog.linear(target);
    time_feed(s, cl2(s, p));
    return true;
  }
  // Positive rotation about the axis: G3 when it turns axial toward radial (axis along
  // axial x radial), as ISO G18 defines it.
  const double axis[3] = {c.ax, c.ay, c.az};
  const double normal =
      axis[static_cast<int>(third_axis(s))] / std::sqrt(c.ax * c.ax + c.ay * c.ay + c.az * c.az);
  const int e_r = static_cast<int>(s.radial), e_z = static_cast<int>(s.m.cl_axial);
  // Sign of the permutation (e_z, e_r, third): cross(e_z, e_r) = +third when even.
  const bool even = (e_z + 1) % 3 == e_r;
  const bool ccw = (normal > 0) == even;
  s.prog.arc(target, center, ccw);
  const Vec2 c2 = cl2(s, Point3{c.cx, c.cy, c.cz});
  time_arc(s, cl2(s, p), c2, ccw);
  if (s.opts.keep_motions) {
    ClMotion& mo = s.cl_path.motions.back();
    mo.rapid = false;
    mo.arc = ccw ? ArcSense::kCcw : ArcSense::kCw;
    mo.center = c2;
  }
  return true;
}

// The modal state the next motion is made with, as the program will say it.
CutState cut_state(const PostState& s) {
  CutState c;
  if (s.feed_given) {
    c.feed = s.feed;
    c.per_rev = s.feed_mode == FeedMode::kPerRev ? 1 : 0;
  }
  if (s.spindle.on) {
    c.spindle = s.spindle.dir == SpindleDir::kCw ? SpindleRun::kCw : SpindleRun::kCcw;
    c.css = s.spindle.css;
    c.speed = s.spindle.value;
    c.max_rpm = s.spindle.css ? s.spindle.css_max_rpm : 0;
  }
  c.tool = s.tool.number;
  c.offset = s.tool.offset;
  return c;
}

}  // namespace

void hand_over_motion(PostState& s) {
  ClPath& path = s.cl_path;
  if (!s.opts.on_motion || path.motions.empty()) return;
  s.opts.on_motion(path.motions.back(), path.states[path.motions.back().state]);
  path.motions.clear();
}

namespace {
// The state index of a motion recorded at CL line `line`: a new state when it changed. The
// motion before is finished: handed over (PostOptions::on_motion) before its state goes.
uint32_t state_at(PostState& s, uint32_t line) {
  ClPath& path = s.cl_path;
  hand_over_motion(s);
  const CutState c = cut_state(s);
  if (path.states.empty() || !(path.states.back().state == c)) {
    if (s.opts.on_motion) path.states.clear();
    path.states.push_back({c, line, s.tool_line, s.feed_line, s.spindle_line});
    ++path.state_count;
  }
  return static_cast<uint32_t>(path.states.size() - 1);
}
}  // namespace

void record_exit(PostState& s, uint32_t line, Vec2 at, std::optional<double> hole_bottom,
                 uint32_t thread_cuts) {
  if (!s.opts.keep_motions) return;
  ClMotion mo;
  mo.line = line;
  mo.to = at;
  mo.rapid = true;
  mo.exit = true;
  mo.hole_bottom = hole_bottom;
  mo.thread_cuts = thread_cuts;
  mo.state = state_at(s, line);
  mo.optional = s.before_skip.has_value();
  s.cl_path.motions.push_back(mo);
}

void record_motion(PostState& s, const Statement& st, Vec2 to, bool rapid, bool from_pos) {
  ClPath& path = s.cl_path;
  const uint32_t state = state_at(s, st.loc.line);
  ClMotion mo;
  mo.line = st.loc.line;
  mo.to = to;
  mo.rapid = rapid;
  if (from_pos && s.pos) {
    const Vec2 at = cl2(s, *s.pos);
    mo.stays = std::fabs(at.x - to.x) < 1e-9 && std::fabs(at.z - to.z) < 1e-9;
  }
  mo.state = state;
  mo.optional = s.before_skip.has_value();
  path.motions.push_back(mo);
}

namespace {
// A feed per revolution with the spindle that SPINDL/OFF stopped never moves: the control waits
// for the spindle (docs/cl-meaning.md). An error at the move, naming the statement that stopped
// it. Before any SPINDL/ the spindle is the machine's (a start template or an INSERT may turn it).
void check_spindle_for_feed(PostState& s, const Statement& st) {
  if (s.rapid_next || !s.feed_given || s.feed_mode != FeedMode::kPerRev || s.spindle.on ||
      s.spindle_line == 0)
    return;
  error(s, st, st.loc,
        fmt::format("feed move per revolution with the spindle stopped (SPINDL/OFF at line {}): "
                    "the control waits for the spindle and never moves; program SPINDL/ before "
                    "it, or a feed per minute",
                    s.spindle_line));
}
}  // namespace

void move_to(PostState& s, const Statement& st, const Point3& p) {
  if (s.dntcut) {  // DNTCUT … CUT: the position is tracked, nothing is written
    s.pos = p;
    s.rapid_next = false;
    s.circle.reset();
    return;
  }
  ensure_started(s);
  restart_stopped_spindle(s, st);
  check_spindle_for_feed(s, st);
  ++s.stats.motions;
  if (s.opts.keep_motions) record_motion(s, st, cl2(s, p), s.rapid_next);
  if (s.circle) {
    const Circle c = *s.circle;
    s.circle.reset();
    if (s.rapid_next) {
      s.rapid_next = false;
      return error(s, st, st.loc,
                   fmt::format("RAPID before the GOTO of CIRCLE/ (line {}): an arc is cut at the "
                               "feed, there is no rapid arc",
                               c.loc.line));
    }
    if (arc_to(s, st, c, p)) {
      s.pos = p;
      s.rapid_next = false;
      return;
    }
  }
  const Vec2 v = cl2(s, p);
  if (s.rapid_next) {
    s.prog.rapid(LathePoint{v.x, v.z});
    s.path->rapid_reached(v.x);  // a live tool's XZ approach
    time_rapid(s, v);
  } else {
    if (!s.feed_given) error(s, st, st.loc, "feed move before any FEDRAT/: the feed is unknown");
    s.prog.linear(LathePoint{v.x, v.z});
    time_feed(s, v);
  }
  s.rapid_next = false;
  if (s.pos) s.last_dir = Point3{p.x - s.pos->x, p.y - s.pos->y, p.z - s.pos->z};
  s.pos = p;
}

void goto_stmt(PostState& s, const Statement& st) {
  const size_t n = st.args.size();
  if (n != 2 && n != 3 && n != 6) {
    error(s, st, n ? st.args[std::min<size_t>(n, 6) - 1].loc : st.loc,
          fmt::format("GOTO/ takes x,y[,z[,i,j,k]]: 2, 3 or 6 numbers, found {}", n));
    return;
  }
  Point3 p;
  if (!number_arg(s, st, 0, "X", p.x) || !number_arg(s, st, 1, "Y", p.y)) return;
  if (n >= 3) {
    if (!number_arg(s, st, 2, "Z", p.z)) return;
  } else {
    p.z = s.pos ? s.pos->z : 0;
  }
  if (n == 6) {
    Point3 t;
    if (!number_arg(s, st, 3, "a tool axis component", t.x) ||
        !number_arg(s, st, 4, "a tool axis component", t.y) ||
        !number_arg(s, st, 5, "a tool axis component", t.z))
      return;
    const double len = std::sqrt(t.x * t.x + t.y * t.y + t.z * t.z);
    s.tool_axis.radial =
        !(len > 0) || std::fabs(std::fabs(axis_value(t, s.m.cl_axial)) / len - 1) > 1e-6;
    if (len > 0) s.tool_axis.dir = Point3{t.x / len, t.y / len, t.z / len};
    s.path->tool_axis(s, st);
  }
  s.path->go_to(s, st, p);
}

bool circle_waits(PostState& s, const Statement& st) {
  if (!s.circle) return false;
  error(s, st, st.loc,
        fmt::format("{} between CIRCLE/ (line {}) and its GOTO: a CIRCLE applies to the next GOTO "
                    "only",
                    st.major, s.circle->loc.line));
  s.circle.reset();
  return true;
}

void from_stmt(PostState& s, const Statement& st) {
  if (circle_waits(s, st)) return;
  Point3 p;
  if (!number_arg(s, st, 0, "X", p.x) || !number_arg(s, st, 1, "Y", p.y)) return;
  if (st.args.size() >= 3 && !number_arg(s, st, 2, "Z", p.z)) return;
  if (!frame_point(s, st, p)) return;
  s.pos = p;
  s.clock_at = cl2(s, p);  // the cycle time counts from the start position
}

void godlta_stmt(PostState& s, const Statement& st) {
  if (circle_waits(s, st)) return;
  if (!s.pos) {
    error(s, st, st.loc, "GODLTA/ needs a known position: no GOTO or FROM before it");
    return;
  }
  Point3 d;
  if (st.args.size() == 1) {
    if (!number_arg(s, st, 0, "a Z distance", d.z)) return;
  } else {
    if (!number_arg(s, st, 0, "dX", d.x) || !number_arg(s, st, 1, "dY", d.y)) return;
    if (st.args.size() >= 3 && !number_arg(s, st, 2, "dZ", d.z)) return;
  }
  s.path->go_delta(s, st, Point3{s.pos->x + d.x, s.pos->y + d.y, s.pos->z + d.z});
}

void circle_stmt(PostState& s, const Statement& st) {
  Circle c;
  if (!number_arg(s, st, 0, "the centre X", c.cx) || !number_arg(s, st, 1, "the centre Y", c.cy) ||
      !number_arg(s, st, 2, "the centre Z", c.cz) || !number_arg(s, st, 3, "the axis I", c.ax) ||
      !number_arg(s, st, 4, "the axis J", c.ay) || !number_arg(s, st, 5, "the axis K", c.az) ||
      !number_arg(s, st, 6, "the radius", c.radius))
    return;
  c.loc = st.loc;
  s.path->circle(s, st, c);
}

// Fusion's APT post: MOVARC/cx,cy,cz,i,j,k,r[,ANGLE,a] (or CENTER,cx,cy,cz,AXIS,i,j,k,RADIUS,r)
// then the GOTO that ends the arc: CIRCLE/ with the rotation axis (Fusion flips the normal of a
// clockwise arc). The sweep ANGLE is implied by the GOTO and not read.
void movarc_stmt(PostState& s, const Statement& st) {
  Statement circle = st;
  circle.args.clear();
  const auto take = [&](size_t from, size_t n) {
    for (size_t i = from; i < from + n && i < st.args.size(); ++i)
      circle.args.push_back(st.args[i]);
  };
  if (!st.args.empty() && st.args[0].is("CENTER")) {
    for (size_t i = 0; i < st.args.size(); ++i) {
      if (st.args[i].is("CENTER")) take(i + 1, 3);
      if (st.args[i].is("AXIS")) take(i + 1, 3);
      if (st.args[i].is("RADIUS")) take(i + 1, 1);
    }
  } else {
    take(0, 7);
  }
  if (circle.args.size() < 7 && !st.args.empty()) {
    error(s, st, st.loc,
          "MOVARC/ takes cx,cy,cz,i,j,k,r[,ANGLE,a] or CENTER,cx,cy,cz,AXIS,i,j,k,RADIUS,r");
    return;
  }
  circle_stmt(s, circle);
}

void rapid_stmt(PostState& s, const Statement&) {
  s.rapid_next = true;
}

void helical_stmt(PostState& s, const Statement& st) {
  s.path->helical(s, st);
}

}  // namespace clpost

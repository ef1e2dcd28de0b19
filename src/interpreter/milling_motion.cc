// A live tool's milling motion (docs/millturn.md): on a machine with Y, X (diameter) Y Z in the
// face plane at the C index; without Y, X Z C computed by the post from the part-frame line
// (laws/xzc_law.h), split within millturn.xzc_tolerance, its feed written so that the tool moves
// along the part at the CL's feed (millturn.xzc_feed).
#include "interpreter/milling_motion.h"

#include <fmt/format.h>

#include <algorithm>
#include <cmath>

#include "interpreter/clock.h"
#include "interpreter/milling_polar.h"
#include "interpreter/millturn.h"
#include "interpreter/point3_math.h"
#include "interpreter/statement_table.h"
#include "laws/xzc_law.h"
#include "support/angles.h"

namespace clpost {

using namespace point3_math;

namespace {

// A milling motion clpost does not write: an error at the first of the tool's, the rest left
// out (one cause, one message).
void refuse(PostState& s, LiveState& l, const Statement& st, const std::string& why) {
  if (l.reported) return;
  l.reported = true;
  error(s, st, st.loc,
        fmt::format("milling motion with live tool {} (loaded at line {}): {} (docs/millturn.md)",
                    s.tool.number, s.tool_line, why));
}

// What the machine and the CL must say for the motion to be written; false (reported).
bool can_mill(PostState& s, LiveState& l, const Statement& st, bool radial) {
  if (l.reported) return false;
  if (polar_motion(s, radial))
    if (const std::string missing = polar_missing(s.m); !missing.empty()) {
      refuse(s, l, st,
             fmt::format("machine '{}' asks for polar interpolation "
                         "(millturn.polar_interpolation: true), and {}; false writes the face "
                         "milling in X Y Z or X Z C computed by the post",
                         s.m.name, missing));
      return false;
    }
  if (s.m.cl_axial != ClAxis::kZ || !s.m.c_axis) {
    refuse(s, l, st,
           fmt::format("milling is read with CL Z the spindle axis (cl.axial_axis: z) on a "
                       "machine with a C axis (millturn.c_axis), and machine '{}' has {}",
                       s.m.name, s.m.c_axis ? "another axial axis" : "no C axis"));
    return false;
  }
  return true;
}

// How far the radial tool's tip `p` is off the line of the tool axis through the centre line
// (`off`), and how far along the axis from the centre line it stands (`along`), in CL units.
struct ToolLine {
  double off = 0, along = 0;
};
ToolLine tool_line(Point3 axis, Point3 p) {
  return {std::abs(p.x * axis.y - p.y * axis.x), p.x * axis.x + p.y * axis.y};
}

// A radial tool's tip on a machine without Y (docs/millturn.md, "Peripheral milling without
// Y"): C turns the part so that the tool axis stands on the machine's X axis, so the tip must lie
// on the line of its axis through the centre line (within millturn.xzc_tolerance), on the tool's
// side of it. False (reported) otherwise: the offset needs Y.
bool on_tool_line(PostState& s, LiveState& l, const Statement& st, Point3 p,
                  const std::string& what) {
  const ToolLine t = tool_line(s.tool_axis.dir, p);
  const Point3 a = s.tool_axis.dir;
  if (t.off > s.m.xzc_tolerance) {
    refuse(s, l, st,
           fmt::format("{} is {:.4f} mm off the line of the tool axis ({:g}, {:g}, {:g}) through "
                       "the centre line (millturn.xzc_tolerance {:g}): a radial tool reaches it "
                       "with a Y axis only, and machine '{}' has none",
                       what, t.off, a.x, a.y, a.z, s.m.xzc_tolerance, s.m.name));
    return false;
  }
  if (t.along <= s.m.xzc_tolerance) {
    refuse(s, l, st,
           fmt::format("{} is {:.4f} mm from the centre line along the tool axis ({:g}, {:g}, "
                       "{:g}): a radial tool's tip at or past the centre line is not written",
                       what, t.along, a.x, a.y, a.z));
    return false;
  }
  return true;
}

// The side of the part the tool works on, as the turn of C from the index that brings its axis
// onto the machine's (degrees): 0 for a face tool (tool axis 0,0,1 or 0,0,-1), the axis's
// angle for a radial tool (k 0: C turns it to +X, X its depth, Y across). None (reported) for
// another axis.
//
// Tool axis 0,0,-1 (docs/millturn.md, "A face tool on the -Z side"): the tool axis points from
// the part to the tool, so the tool stands on the -Z side of the face it works, and that face
// looks toward -Z: the part lies at +Z of it, as the CL's turning has it (CATIA's
// MillTurn3x_PATH1, whose frame runs Z into the part). clpost writes every CL point of a file in
// the CL's frame, the turning too, so the face's X, Y, Z and C are written as for 0,0,1; only
// the side CUTCOM names is seen from the other side of the plane (cutcom_stmt).
std::optional<double> side_turn(PostState& s, LiveState& l, const Statement& st) {
  const Point3 t = s.tool_axis.dir;
  const double len = std::sqrt(t.x * t.x + t.y * t.y + t.z * t.z);
  if (len > 0 && std::abs(std::abs(t.z / len) - 1) < 1e-6) return 0.0;
  if (len > 0 && std::abs(t.z / len) < 1e-6) return degrees(std::atan2(t.y, t.x));
  refuse(s, l, st,
         fmt::format("the tool axis ({}, {}, {}) is neither along Z (a face tool, 0,0,1 or "
                     "0,0,-1) nor radial (k 0): a tilted live tool is not written",
                     t.x, t.y, t.z));
  return std::nullopt;
}

// The feed of a feed move per minute, output units: a feed per revolution is per revolution of
// the live tool (the main spindle is stopped). None (reported) when it is not known.
std::optional<double> mill_feed(PostState& s, LiveState& l, const Statement& st) {
  if (!s.feed_given) {
    error(s, st, st.loc, "feed move before any FEDRAT/: the feed is unknown");
    return std::nullopt;
  }
  if (s.feed_mode == FeedMode::kPerMinute) return s.feed;
  if (l.spindle.on && !l.spindle.css && l.spindle.value > 0) return s.feed * l.spindle.value;
  error(s, st, st.loc,
        "a feed per revolution of the live tool needs it turning at a set RPM (SPINDL/n,RPM): "
        "give the feed per minute (MMPM, IPM) or the live tool's speed");
  return std::nullopt;
}

// The part frame's turn: the C of the last ROTABL, else C0 (noted, and C is put there).
double part_index(PostState& s, const Statement& st) {
  if (!s.c.index) {
    note_once(s, st, "mill-c-index",
              "no ROTABL/ since C was engaged: the milling is written with the part frame's X "
              "axis at C0");
    s.c.index = 0;
  }
  return *s.c.index;
}

// A milling motion's start (start_motion): the part frame's C index, the turn of C past it that
// brings a radial tool's axis onto X (with Y), the feed per minute, the tool's side.
struct MotionStart {
  double index = 0, turn = 0, feed = 0;
  bool radial = false;  // the tool axis is radial (k 0): peripheral work
};

// Without Y, where the machine puts a radial tool's CL point `p` (on_tool_line): at its radius
// and at the angle of the tool axis, within the tolerance of `p`, so that C comes from the tool
// axis (a move along the axis keeps C: the CL's rounded points do not turn it by a hair).
Point3 machine_tip(const PostState& s, const MotionStart& ms, Point3 p) {
  if (!ms.radial || s.m.y_axis) return p;
  const double r = std::hypot(p.x, p.y), a = std::hypot(s.tool_axis.dir.x, s.tool_axis.dir.y);
  return {r * s.tool_axis.dir.x / a, r * s.tool_axis.dir.y / a, p.z};
}

// C to `angle` (the shortest way), clamped as the machine clamps an index.
bool c_to(PostState& s, const Statement& st, double angle) {
  return write_c_steps(s, st, c_steps(s.m, s.c.angle, angle, false, std::nullopt));
}

}  // namespace

void per_minute_code(PostState& s, LiveState& l, NcWriter& w) {
  if (l.mill.per_minute) return;
  w.code(s.m.code("feed_per_min"));
  l.mill.per_minute = true;
}

void plane_code(PostState& s, LiveState& l, NcWriter& w, int plane) {
  if (l.mill.plane == plane) return;
  w.code(s.m.code(plane == 17   ? "plane_face"
                  : plane == 19 ? "plane_side"
                                : "plane_lathe"))
      .end_block();
  l.mill.plane = plane;
}

namespace {

// One XZC piece from `from`: a rapid, or a feed move whose F makes the tool move along the
// part at `feed` per minute. A piece that does not turn C is the lathe's own move (G94 F is
// exact along X and Z).
void xzc_block(PostState& s, LiveState& l, XzcPoint from, const XzcPiece& pc, bool rapid,
               double feed) {
  const std::vector<double> steps = c_steps(s.m, s.c.angle, pc.to.c, false, std::nullopt);
  const LathePoint to{pc.to.r, pc.to.z};
  if (steps.empty()) {
    if (rapid) return s.prog.rapid(to);
    s.prog.set_feed(feed, FeedMode::kPerMinute);
    s.prog.linear(to);
    l.mill.inverse_time = false;
    l.mill.per_minute = true;
    return;
  }
  if (s.c.clamped) {
    s.prog.writer().code(s.m.code("c_unclamp")).end_block();
    s.c.clamped = false;
  }
  NcWriter& w = s.prog.writer();
  const double dc = pc.to.c - from.c;
  if (rapid) {
    w.code(s.m.code("rapid"));
  } else if (s.m.xzc_inverse_time) {
    if (!l.mill.inverse_time) w.code(s.m.code("inverse_time"));
    l.mill.inverse_time = true;
    w.code(s.m.code("linear"));
  } else {
    per_minute_code(s, l, w);
    w.code(s.m.code("linear"));
  }
  w.word("X", diameter_factor(s.m) * to.r).word("Z", to.z).word(s.m.c_address, steps.back());
  if (!rapid) {
    const double dr = pc.to.r - from.r, dz = pc.to.z - from.z;
    const double machine = std::sqrt(dr * dr + dz * dz + dc * dc);
    // Inverse time: the piece takes length / feed minutes (a flip on the centre: C at the feed
    // read as degrees per minute). Combined: F over the X, Z and C move in the same time.
    const double minutes = pc.length > 0 ? pc.length / feed : std::abs(dc) / feed;
    w.word("F", s.m.xzc_inverse_time ? 1 / minutes : machine / minutes);
  }
  w.end_block();
  s.c.angle = steps.back();
  s.prog.cycle_ended_at(to);  // X and Z as written here; the lathe's modal words forgotten
}

// The straight part-frame move `from` -> `to` at C index `index`, without Y, its pieces within
// `tol`.
void xzc_move(PostState& s, LiveState& l, Point3 from, Point3 to, double index, bool rapid,
              double feed, double tol) {
  const double c0 = *s.c.angle;
  std::vector<XzcPiece> pieces;
  if (rapid) {
    pieces.push_back({xzc_point(to, index, c0), 0, false});  // the control's own path
  } else {
    pieces = xzc_line(from, to, index, c0, tol);
  }
  XzcPoint at = xzc_point(from, index, c0);
  at.c = c0;
  for (const XzcPiece& pc : pieces) {
    xzc_block(s, l, at, pc, rapid, feed);
    rapid ? time_rapid(s, Vec2{pc.to.r, pc.to.z}) : time_feed(s, Vec2{pc.to.r, pc.to.z});
    at = pc.to;
  }
}

// Part point `p` in the machine's X Y Z with C turned `turn` degrees past the index: the
// point turned back by `turn` (X as a radius).
Point3 machine_xyz(Point3 p, double turn) {
  const double a = radians(-turn), c = std::cos(a), n = std::sin(a);
  return {p.x * c - p.y * n, p.x * n + p.y * c, p.z};
}

// The straight move to machine point `m` (a machine with Y, C set): X (diameter) Y Z, exact.
void xyz_move(PostState& s, LiveState& l, Point3 m, bool rapid, double feed, int plane) {
  NcWriter& w = s.prog.writer();
  plane_code(s, l, w, plane);
  if (!rapid) per_minute_code(s, l, w);
  w.code(s.m.code(rapid ? "rapid" : "linear"));
  w.word("X", diameter_factor(s.m) * m.x).word("Y", m.y).word("Z", m.z);
  if (!rapid) w.word("F", feed);
  w.end_block();
  l.mill.y = m.y;
  if (rapid) l.mill.rapid_reached(m.x);
  s.prog.cycle_ended_at(LathePoint{m.x, m.z});
  rapid ? time_rapid(s, Vec2{m.x, m.z}) : time_feed(s, Vec2{m.x, m.z});
}

// An arc or a helix in the part frame: about `axis` (a unit vector) through `center`, turning
// `sense` (+1 positive about the axis, -1 negative), from `from` to `to` (its advance along
// the axis linear).
struct MillArc {
  Point3 center, axis;
  int sense = 1;
  uint32_t line = 0;  // its CIRCLE/ or HELICAL/
};

// The radius vector of `p` about the arc's axis, and its advance along it.
Point3 radial_of(const MillArc& c, Point3 p, double& h) {
  const Point3 u = sub(p, c.center);
  h = dot(u, c.axis);
  return sub(u, scaled(c.axis, h));
}

// Points on the arc from `from` to `to`, the chords within `tol` of it; the last is `to`. The
// same point: a full turn.
std::vector<Point3> arc_points(const MillArc& c, Point3 from, Point3 to, double tol) {
  double h0 = 0, h1 = 0;
  const Point3 r0 = radial_of(c, from, h0), r1 = radial_of(c, to, h1);
  const double r = std::sqrt(dot(r0, r0));
  double sweep = c.sense * std::atan2(dot(cross(r0, r1), c.axis), dot(r0, r1));
  while (sweep <= 1e-9) sweep += 2 * kPi;
  const double step = tol < r ? 2 * std::acos(1 - tol / r) : kPi / 2;
  const int n = std::max(1, static_cast<int>(std::ceil(sweep / std::min(step, kPi / 2))));
  const Point3 side = cross(c.axis, r0);
  std::vector<Point3> out;
  for (int k = 1; k < n; ++k) {
    const double a = c.sense * sweep * k / n;
    const Point3 rk = add(scaled(r0, std::cos(a)), scaled(side, std::sin(a)));
    out.push_back(add(add(c.center, scaled(c.axis, h0 + (h1 - h0) * k / n)), rk));
  }
  out.push_back(to);
  return out;
}

// The arc in the machine's plane (C turned `turn` past the index): G2/G3 with the two centre
// words of the plane; false when its axis is along none of X, Y, Z there, or its plane is not
// the one cutter compensation is on in.
bool xyz_arc(PostState& s, LiveState& l, const MillArc& c, Point3 from, Point3 to, double turn,
             double feed) {
  const Point3 a = machine_xyz(c.axis, turn), m0 = machine_xyz(from, turn);
  const Point3 m1 = machine_xyz(to, turn), mc = machine_xyz(c.center, turn);
  const double n[3] = {a.x, a.y, a.z};
  int axis = -1;
  for (int i = 0; i < 3; ++i)
    if (std::abs(std::abs(n[i]) - 1) < 1e-6) axis = i;
  const int plane = axis == 2 ? 17 : axis == 1 ? 18 : 19;
  if (axis < 0 || (l.mill.comp != CutterComp::kOff && plane != l.mill.plane)) return false;
  // G3 turns positively about the plane's normal (+Z in G17, +Y in G18, +X in G19: ISO 6983).
  const bool ccw = c.sense * n[axis] > 0;
  NcWriter& w = s.prog.writer();
  plane_code(s, l, w, plane);
  per_minute_code(s, l, w);
  w.code(s.m.code(ccw ? "arc_ccw" : "arc_cw"));
  w.word("X", diameter_factor(s.m) * m1.x).word("Y", m1.y).word("Z", m1.z);
  if (axis != 0) w.word("I", mc.x - m0.x);
  if (axis != 1) w.word("J", mc.y - m0.y);
  if (axis != 2) w.word("K", mc.z - m0.z);
  w.word("F", feed).end_block();
  l.mill.y = m1.y;
  s.prog.cycle_ended_at(LathePoint{m1.x, m1.z});
  time_feed(s, Vec2{m1.x, m1.z});
  return true;
}

// Without Y: the side plane (plane_side) before peripheral work and the lathe plane
// (plane_lathe) before face work after it, when the machine has the codes. No G1 depends on the
// plane: it says which work the XZC moves are (plot's peripheral view is drawn by it).
void xzc_plane(PostState& s, LiveState& l, bool radial) {
  const int plane = radial ? 19 : 18;
  if (l.mill.plane == plane || s.m.code(radial ? "plane_side" : "plane_lathe").empty()) return;
  plane_code(s, l, s.prog.writer(), plane);
}

// A milling piece to verify (PostOptions::on_mill), else kept (LiveState::written).
void keep_mill(PostState& s, LiveState& l, const MillSegment& g) {
  if (s.opts.on_mill) return s.opts.on_mill(g);
  l.written.push_back(g);
}

// Without Y, whether a radial tool reaches the arc's points (reported if not): about Z every
// point (C follows the tip), about another axis only when they lie on the line of the tool axis
// (an arc in the plane of the axis and Z, at one C). A face tool's arc is about Z only.
bool xzc_arc_reached(PostState& s, LiveState& l, const Statement& st, const MillArc& c,
                     const std::vector<Point3>& points, bool radial) {
  if (std::abs(std::abs(c.axis.z) - 1) <= 1e-6) return true;
  if (!radial) {
    refuse(s, l, st, "an arc about another axis than the spindle's needs a Y axis");
    return false;
  }
  Point3 far = points.front(), near = points.front();
  for (const Point3& p : points) {
    if (tool_line(s.tool_axis.dir, p).off > tool_line(s.tool_axis.dir, far).off) far = p;
    if (tool_line(s.tool_axis.dir, p).along < tool_line(s.tool_axis.dir, near).along) near = p;
  }
  const Point3 worst = tool_line(s.tool_axis.dir, far).off > s.m.xzc_tolerance ? far : near;
  return on_tool_line(s, l, st, worst,
                      fmt::format("the arc of line {} about ({:g}, {:g}, {:g}) at ({:.5g}, {:.5g}, "
                                  "{:.5g})",
                                  c.line, c.axis.x, c.axis.y, c.axis.z, worst.x, worst.y, worst.z));
}

// The arc `c` in polar interpolation: G2/G3 where the control takes them (millturn.polar_arcs),
// else its chords `points`, each an exact G1.
void polar_mill_arc(PostState& s, LiveState& l, const Statement& st, const MillArc& c, Point3 from,
                    Point3 to, const std::vector<Point3>& points, const MotionStart& ms) {
  if (std::abs(std::abs(c.axis.z) - 1) > 1e-6)
    return refuse(s, l, st, "an arc about another axis than the spindle's in polar interpolation");
  if (s.m.polar_arcs) {
    polar_arc(s, l, st, c.center, c.sense * c.axis.z > 0, from, to, ms.index, ms.feed);
    return;
  }
  Point3 a = from;
  for (const Point3& p : points) {
    if (!polar_line(s, l, st, a, p, ms.index, false, ms.feed)) return;
    a = p;
  }
}

// The arc `c` to `to`: G2/G3 in the machine's plane with Y, lines within the tolerance without.
void mill_arc(PostState& s, LiveState& l, const Statement& st, const MillArc& c, Point3 from,
              Point3 to, const MotionStart& ms) {
  double h = 0;
  const Point3 r0 = radial_of(c, from, h), r1 = radial_of(c, to, h);
  const double d0 = std::sqrt(dot(r0, r0)), d1 = std::sqrt(dot(r1, r1));
  if (std::abs(d0 - d1) > std::max(1e-3, 1e-4 * d0))
    return error(s, st, st.loc,
                 fmt::format("arc end point is not on the circle of line {}: distance from the "
                             "axis {:.6g} at the start, {:.6g} at the end",
                             c.line, d0, d1));
  // Chords within half the tolerance, each piece within the other half: the segments verify
  // checks the program against.
  const std::vector<Point3> points = arc_points(c, from, to, s.m.xzc_tolerance / 2);
  const bool polar = polar_motion(s, ms.radial);
  if (!s.m.y_axis && !polar && !xzc_arc_reached(s, l, st, c, points, ms.radial)) return;
  if (!s.m.y_axis && !polar) xzc_plane(s, l, ms.radial);
  Point3 at = from;
  for (const Point3& p : points) {
    keep_mill(s, l, {st.loc.line, at, p, ms.index, false});
    const Point3 q = &p == &points.back() ? machine_tip(s, ms, p) : p;
    if (!s.m.y_axis && !polar)
      xzc_move(s, l, at, q, ms.index, false, ms.feed, s.m.xzc_tolerance / 2);
    at = p;
  }
  if (polar) return polar_mill_arc(s, l, st, c, from, to, points, ms);
  if (!s.m.y_axis || xyz_arc(s, l, c, from, to, ms.turn, ms.feed)) return;
  if (l.mill.comp != CutterComp::kOff)
    return refuse(s, l, st,
                  fmt::format("the arc is not in G{}, the plane cutter compensation (CUTCOM) is on "
                              "in, and a control refuses a plane change under G41/G42: give "
                              "the tool centre's path (CUTCOM/OFF)",
                              l.mill.plane));
  refuse(s, l, st, "the arc's axis is along none of the machine's X, Y, Z at this C");
}

// Without Y, a radial tool's CL point: on the line of its axis through the centre line.
bool tip_reached(PostState& s, LiveState& l, const Statement& st, const MotionStart& ms, Point3 p) {
  if (!ms.radial || s.m.y_axis) return true;
  return on_tool_line(s, l, st, p, fmt::format("the tip ({:g}, {:g}, {:g})", p.x, p.y, p.z));
}

// Where a milling motion starts: checked, C set (at the index, or past it for a radial tool on
// a machine with Y). False (reported, or nothing to write) when the motion is not written.
bool start_motion(PostState& s, LiveState& l, const Statement& st, bool rapid, Point3 to,
                  MotionStart& ms) {
  if (s.dntcut || !can_mill(s, l, st, ms.radial)) return false;
  if (s.tool_axis.dir.z < -1 + 1e-6)
    note_once(s, st, "mill-minus-z",
              "tool axis 0,0,-1: a face tool on the -Z side, working a face that looks toward -Z "
              "(the part at +Z of it, as this CL's frame has it); written in the CL's frame, as "
              "the turning is (docs/millturn.md, \"A face tool on the -Z side\")");
  ensure_started(s);
  ++s.stats.motions;
  const std::optional<double> feed = rapid ? std::optional<double>(0) : mill_feed(s, l, st);
  if (!feed) return false;
  ms.feed = *feed;
  ms.index = part_index(s, st);
  const std::optional<double> turn = side_turn(s, l, st);
  if (!turn) return false;
  if (!tip_reached(s, l, st, ms, to)) return false;
  // Without Y the point gives C (the tool axis its side); with Y C turns the tool's side to X.
  if (s.m.y_axis) ms.turn = *turn;
  // C unknown, or a machine with Y: C where the work is first.
  if (!polar_motion(s, ms.radial) && (!s.c.angle || s.m.y_axis) && !c_to(s, st, ms.index + ms.turn))
    return false;
  if (!s.pos && !rapid) {
    error(s, st, st.loc, "a milling feed move needs a start point: no GOTO or FROM before it");
    return false;
  }
  return true;
}

}  // namespace

void milling_goto(PostState& s, LiveState& l, const Statement& st, Point3 p, bool radial) {
  const std::optional<Circle> circle = s.circle;
  const bool rapid = s.rapid_next;
  s.circle.reset();
  s.rapid_next = false;
  if (rapid && circle)
    return error(s, st, st.loc,
                 fmt::format("RAPID before the GOTO of CIRCLE/ (line {}): an arc is cut at the "
                             "feed, there is no rapid arc",
                             circle->loc.line));
  MotionStart ms;
  ms.radial = radial;
  if (!start_motion(s, l, st, rapid, p, ms)) {
    s.pos = p;  // DNTCUT: the position is tracked, nothing is written
    return;
  }
  const Point3 from = s.pos.value_or(p);
  s.pos = p;
  if (circle) {
    const double len =
        std::sqrt(dot({circle->ax, circle->ay, circle->az}, {circle->ax, circle->ay, circle->az}));
    const MillArc arc{{circle->cx, circle->cy, circle->cz},
                      scaled({circle->ax, circle->ay, circle->az}, 1 / len),
                      1,
                      circle->loc.line};
    return mill_arc(s, l, st, arc, from, p, ms);
  }
  keep_mill(s, l, {st.loc.line, from, p, ms.index, rapid});
  if (polar_motion(s, radial)) {
    polar_line(s, l, st, from, p, ms.index, rapid, ms.feed);
    return;
  }
  if (!s.m.y_axis) {
    xzc_plane(s, l, ms.radial);
    return xzc_move(s, l, from, machine_tip(s, ms, p), ms.index, rapid, ms.feed, s.m.xzc_tolerance);
  }
  // The face's lines in G17; a radial tool's in the plane in force (its arcs choose theirs).
  xyz_move(s, l, machine_xyz(p, ms.turn), rapid, ms.feed, radial ? l.mill.plane : 17);
}

void milling_circle(PostState& s, LiveState& l, const Statement& st, const Circle& c, bool radial) {
  if (!can_mill(s, l, st, radial)) return;
  const double len = std::sqrt(c.ax * c.ax + c.ay * c.ay + c.az * c.az);
  if (!(len > 0))
    return refuse(s, l, st, fmt::format("CIRCLE/ with the axis ({}, {}, {})", c.ax, c.ay, c.az));
  if (!s.m.y_axis && !radial && std::abs(std::abs(c.az) / len - 1) > 1e-6)
    return refuse(s, l, st,
                  fmt::format("CIRCLE/ about the axis ({}, {}, {}), not the spindle axis: without "
                              "a Y axis a live tool's arc is written in the face plane only",
                              c.ax, c.ay, c.az));
  s.circle = c;
}

namespace {

// The words of HELICAL/ (CATIA): CENTER x,y,z, INDIRV i,j,k, AXIS i,j,k, END x,y,z (PITCH,
// RADIUS, ANGLE, HEIGHT, ROUND are implied by them and not read).
bool helical_words(PostState& s, const Statement& st, Point3& c, Point3& dir, Point3& axis,
                   Point3& end) {
  const auto three = [&](std::string_view word, Point3& out) {
    for (size_t i = 0; i + 3 < st.args.size(); ++i)
      if (st.args[i].is(word))
        return number_arg(s, st, i + 1, word, out.x) && number_arg(s, st, i + 2, word, out.y) &&
               number_arg(s, st, i + 3, word, out.z);
    error(s, st, st.loc,
          fmt::format("HELICAL/ without {} x,y,z: expected CENTER, INDIRV, AXIS and END", word));
    return false;
  };
  return three("CENTER", c) && three("INDIRV", dir) && three("AXIS", axis) && three("END", end);
}

}  // namespace

void milling_helical(PostState& s, LiveState& l, const Statement& st, bool radial) {
  if (circle_waits(s, st)) return;
  Point3 c, dir, axis, end;
  if (!helical_words(s, st, c, dir, axis, end)) return;
  const double len = std::sqrt(dot(axis, axis));
  if (!(len > 0) || !s.pos)
    return error(s, st, st.loc, "HELICAL/ needs an axis and a start point (a GOTO before it)");
  const Point3 a = scaled(axis, 1 / len);
  double h = 0;
  const int sense = dot(cross(a, radial_of({c, a, 1, 0}, *s.pos, h)), dir) >= 0 ? 1 : -1;
  milling_arc_to(s, l, st, c, a, sense, end, radial);
}

void milling_arc_to(PostState& s, LiveState& l, const Statement& st, Point3 center, Point3 axis,
                    int sense, Point3 end, bool radial) {
  MotionStart ms;
  ms.radial = radial;
  if (!s.pos) return error(s, st, st.loc, "an arc needs a start point: no GOTO or FROM before it");
  if (!start_motion(s, l, st, false, end, ms)) return;
  const Point3 from = *s.pos;
  s.pos = end;
  mill_arc(s, l, st, {center, axis, sense, st.loc.line}, from, end, ms);
}

}  // namespace clpost

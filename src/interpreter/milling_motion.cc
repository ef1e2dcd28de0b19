// A live tool's milling motion (docs/millturn.md): on a machine with Y, X (diameter) Y Z in the
// face plane at the C index; without Y, X Z C computed by the post from the part-frame line
// (laws/xzc_law.h), split within millturn.xzc_tolerance, its feed written so that the tool moves
// along the part at the CL's feed (millturn.xzc_feed).
#include "interpreter/milling_motion.h"

#include <fmt/format.h>

#include <algorithm>
#include <cmath>

#include "interpreter/clock.h"
#include "interpreter/millturn.h"
#include "interpreter/statement_table.h"
#include "laws/xzc_law.h"

namespace clpost {

namespace {

constexpr double kPi = 3.14159265358979323846;

PartPoint part(Point3 p) {
  return {p.x, p.y, p.z};
}

// A milling motion clpost does not write: an error at the first of the tool's, the rest left
// out (one cause, one message).
void refuse(PostState& s, const Statement& st, const std::string& why) {
  if (s.mill_motion_reported) return;
  s.mill_motion_reported = true;
  error(s, st, st.loc,
        fmt::format("milling motion with live tool {} (loaded at line {}): {} (docs/millturn.md)",
                    s.tool.number, s.tool_line, why));
}

// What the machine and the CL must say for the motion to be written; false (reported).
bool can_mill(PostState& s, const Statement& st) {
  if (s.mill_motion_reported) return false;
  if (s.m.polar_interpolation) {
    refuse(s, st,
           fmt::format("machine '{}' asks for polar or cylindrical interpolation "
                       "(millturn.polar_interpolation: true), which clpost does not write yet; "
                       "false writes the face milling in X Y Z or X Z C computed by the post",
                       s.m.name));
    return false;
  }
  if (s.m.cl_axial != ClAxis::kZ || !s.m.c_axis) {
    refuse(s, st,
           fmt::format("face milling is read with CL Z the spindle axis (cl.axial_axis: z) on a "
                       "machine with a C axis (millturn.c_axis), and machine '{}' has {}",
                       s.m.name, s.m.c_axis ? "another axial axis" : "no C axis"));
    return false;
  }
  if (s.hole_axis_radial) {
    refuse(s, st,
           "the tool axis (GOTO i,j,k) is not along Z: milling on the peripheral surface (G19, "
           "cylindrical interpolation) is not written yet, face milling (tool axis 0,0,1) is");
    return false;
  }
  return true;
}

// The feed of a feed move per minute, output units: a feed per revolution is per revolution of
// the live tool (the main spindle is stopped). None (reported) when it is not known.
std::optional<double> mill_feed(PostState& s, const Statement& st) {
  if (!s.feed_given) {
    error(s, st, st.loc, "feed move before any FEDRAT/: the feed is unknown");
    return std::nullopt;
  }
  if (s.feed_mode == FeedMode::kPerMinute) return s.feed;
  if (s.live.on && !s.live.css && s.live.value > 0) return s.feed * s.live.value;
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

// C to `angle` (the shortest way), clamped as the machine clamps an index.
bool c_to(PostState& s, const Statement& st, double angle) {
  return write_c_steps(s, st, c_steps(s.m, s.c.angle, angle, false, std::nullopt));
}

}  // namespace

namespace {

// The feed-per-minute code before the first feed block of the milling (the lathe's last mode
// may be per revolution).
void per_minute_code(PostState& s, NcWriter& w) {
  if (s.mill.per_minute) return;
  w.code(s.m.code("feed_per_min"));
  s.mill.per_minute = true;
}

// One XZC piece from `from`: a rapid, or a feed move whose F makes the tool move along the
// part at `feed` per minute. A piece that does not turn C is the lathe's own move (G94 F is
// exact along X and Z).
void xzc_block(PostState& s, XzcPoint from, const XzcPiece& pc, bool rapid, double feed) {
  const std::vector<double> steps = c_steps(s.m, s.c.angle, pc.to.c, false, std::nullopt);
  const LathePoint to{pc.to.r, pc.to.z};
  if (steps.empty()) {
    if (rapid) return s.prog.rapid(to);
    s.prog.set_feed(feed, FeedMode::kPerMinute);
    s.prog.linear(to);
    s.mill.inverse_time = false;
    s.mill.per_minute = true;
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
    if (!s.mill.inverse_time) w.code(s.m.code("inverse_time"));
    s.mill.inverse_time = true;
    w.code(s.m.code("linear"));
  } else {
    per_minute_code(s, w);
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
void xzc_move(PostState& s, Point3 from, Point3 to, double index, bool rapid, double feed,
              double tol) {
  const double c0 = *s.c.angle;
  const PartPoint a = part(from), b = part(to);
  std::vector<XzcPiece> pieces;
  if (rapid) {
    pieces.push_back({xzc_point(b, index, c0), 0, false});  // the control's own path
  } else {
    pieces = xzc_line(a, b, index, c0, tol);
  }
  XzcPoint at = xzc_point(a, index, c0);
  at.c = c0;
  for (const XzcPiece& pc : pieces) {
    xzc_block(s, at, pc, rapid, feed);
    rapid ? time_rapid(s, Vec2{pc.to.r, pc.to.z}) : time_feed(s, Vec2{pc.to.r, pc.to.z});
    at = pc.to;
  }
}

// The straight move to part point `to` in the face plane (a machine with Y, C at the index):
// X (diameter) Y Z, exact.
void face_move(PostState& s, Point3 to, bool rapid, double feed) {
  NcWriter& w = s.prog.writer();
  if (!s.mill.face_plane) {
    w.code(s.m.code("plane_face")).end_block();
    s.mill.face_plane = true;
  }
  if (!rapid) per_minute_code(s, w);
  w.code(s.m.code(rapid ? "rapid" : "linear"));
  w.word("X", diameter_factor(s.m) * to.x).word("Y", to.y).word("Z", to.z);
  if (!rapid) w.word("F", feed);
  w.end_block();
  s.mill.y = to.y;
  s.prog.cycle_ended_at(LathePoint{to.x, to.z});
  rapid ? time_rapid(s, Vec2{to.x, to.z}) : time_feed(s, Vec2{to.x, to.z});
}

}  // namespace

namespace {

// The arc of CIRCLE/ `c` (about Z, counter-clockwise seen from +Z when `ccw`) from `from` to
// `to` as points on it, the chords within `tol` of it; the last is `to`.
std::vector<Point3> arc_points(const Circle& c, Point3 from, Point3 to, bool ccw, double tol) {
  const double r = std::hypot(from.x - c.cx, from.y - c.cy);
  const double a0 = std::atan2(from.y - c.cy, from.x - c.cx);
  const double a1 = std::atan2(to.y - c.cy, to.x - c.cx);
  double sweep = ccw ? a1 - a0 : a0 - a1;
  while (sweep <= 1e-9) sweep += 2 * kPi;  // the same point: a full circle
  const double step = tol < r ? 2 * std::acos(1 - tol / r) : kPi / 2;
  const int n = std::max(1, static_cast<int>(std::ceil(sweep / std::min(step, kPi / 2))));
  std::vector<Point3> out;
  for (int k = 1; k < n; ++k) {
    const double a = a0 + (ccw ? 1 : -1) * sweep * k / n;
    out.push_back(
        {c.cx + r * std::cos(a), c.cy + r * std::sin(a), from.z + (to.z - from.z) * k / n});
  }
  out.push_back(to);
  return out;
}

// The arc of `c` to `to`: G2/G3 in the face plane with Y, lines within the tolerance without.
void mill_arc(PostState& s, const Statement& st, const Circle& c, Point3 from, Point3 to,
              double index, double feed) {
  const double r0 = std::hypot(from.x - c.cx, from.y - c.cy);
  const double r1 = std::hypot(to.x - c.cx, to.y - c.cy);
  if (std::abs(r0 - r1) > std::max(1e-3, 1e-4 * r0))
    return error(s, st, st.loc,
                 fmt::format("arc end point is not on the circle of line {}: distance from the "
                             "centre {:.6g} at the start, {:.6g} at the end",
                             c.loc.line, r0, r1));
  const bool ccw = c.az > 0;  // positive rotation about +Z: G3 seen from +Z (G17)
  // Chords within half the tolerance, each piece within the other half: the segments verify
  // checks the program against.
  const std::vector<Point3> points = arc_points(c, from, to, ccw, s.m.xzc_tolerance / 2);
  Point3 at = from;
  for (const Point3& p : points) {
    s.mill_path.push_back({st.loc.line, at, p, index, false});
    if (!s.m.y_axis) xzc_move(s, at, p, index, false, feed, s.m.xzc_tolerance / 2);
    at = p;
  }
  if (!s.m.y_axis) return;
  NcWriter& w = s.prog.writer();
  per_minute_code(s, w);
  w.code(s.m.code(ccw ? "arc_ccw" : "arc_cw"));
  w.word("X", diameter_factor(s.m) * to.x).word("Y", to.y).word("Z", to.z);
  w.word("I", c.cx - from.x).word("J", c.cy - from.y).word("F", feed).end_block();
  s.mill.y = to.y;
  s.prog.cycle_ended_at(LathePoint{to.x, to.z});
  time_feed(s, Vec2{to.x, to.z});
}

}  // namespace

void milling_goto(PostState& s, const Statement& st, Point3 p) {
  const std::optional<Circle> circle = s.circle;
  const bool rapid = s.rapid_next;
  s.circle.reset();
  s.rapid_next = false;
  if (s.dntcut || !can_mill(s, st)) {
    s.pos = p;  // DNTCUT: the position is tracked, nothing is written
    return;
  }
  ensure_started(s);
  ++s.stats.motions;
  if (rapid && circle)
    return error(s, st, st.loc,
                 fmt::format("RAPID before the GOTO of CIRCLE/ (line {}): an arc is cut at the "
                             "feed, there is no rapid arc",
                             circle->loc.line));
  const std::optional<double> feed = rapid ? std::optional<double>(0) : mill_feed(s, st);
  if (!feed) return;
  const double index = part_index(s, st);
  // C unknown, or a machine with Y: C at the index first.
  if ((!s.c.angle || s.m.y_axis) && !c_to(s, st, index)) return;
  if (!s.pos && !rapid)
    return error(s, st, st.loc,
                 "a milling feed move needs a start point: no GOTO or FROM before it");
  const Point3 from = s.pos.value_or(p);
  s.pos = p;
  if (circle) return mill_arc(s, st, *circle, from, p, index, *feed);
  s.mill_path.push_back({st.loc.line, from, p, index, rapid});
  if (s.m.y_axis) return face_move(s, p, rapid, *feed);
  xzc_move(s, from, p, index, rapid, *feed, s.m.xzc_tolerance);
}

void milling_circle(PostState& s, const Statement& st, const Circle& c) {
  if (!can_mill(s, st)) return;
  const double len = std::sqrt(c.ax * c.ax + c.ay * c.ay + c.az * c.az);
  if (!(len > 0) || std::abs(std::abs(c.az) / len - 1) > 1e-6)
    return refuse(s, st,
                  fmt::format("CIRCLE/ about the axis ({}, {}, {}), not the spindle axis: a live "
                              "tool's arc is written in the face plane only",
                              c.ax, c.ay, c.az));
  s.circle = c;
}

void end_milling(PostState& s, const Statement& st, bool c_back) {
  if (s.mill.face_plane) {
    NcWriter& w = s.prog.writer();
    if (s.mill.y != 0) w.code(s.m.code("rapid")).word("Y", 0.0).end_block();
    w.code(s.m.code("plane_lathe")).end_block();
    s.prog.forget_modal();
  }
  s.mill = MillState{};
  if (c_back && s.c.index && s.c.angle) c_to(s, st, *s.c.index);
}

}  // namespace clpost

// A live tool's milling motion (milling_motion.h, docs/millturn.md): where it starts (checked,
// the part frame's C index, the feed, C set) and the way the machine takes it: X Y Z in the face
// plane at the C index with Y (milling_xyz.cc), X Z C computed by the post without
// (milling_xzc.cc), or the control's polar interpolation (milling_polar.cc).
#include <fmt/format.h>

#include <cmath>

#include "interpreter/milling_parts.h"
#include "interpreter/milling_polar.h"
#include "interpreter/millturn.h"
#include "interpreter/point3_math.h"
#include "interpreter/statement_table.h"
#include "support/angles.h"

namespace clpost {

using namespace point3_math;

namespace {

// What the machine and the CL must say for the motion to be written; false (reported).
bool can_mill(PostState& s, LiveState& l, const Statement& st, bool radial) {
  if (l.reported) return false;
  if (polar_motion(s, radial))
    if (const std::string missing = polar_missing(s.m); !missing.empty()) {
      refuse_milling(
          s, l, st,
          fmt::format("machine '{}' asks for polar interpolation "
                      "(millturn.polar_interpolation: true), and {}; false writes the face "
                      "milling in X Y Z or X Z C computed by the post",
                      s.m.name, missing));
      return false;
    }
  if (s.m.cl_axial != ClAxis::kZ || !s.m.c_axis) {
    refuse_milling(s, l, st,
                   fmt::format("milling is read with CL Z the spindle axis (cl.axial_axis: z) on a "
                               "machine with a C axis (millturn.c_axis), and machine '{}' has {}",
                               s.m.name, s.m.c_axis ? "another axial axis" : "no C axis"));
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
  refuse_milling(s, l, st,
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

// C to `angle` (the shortest way), clamped as the machine clamps an index.
bool c_to(PostState& s, const Statement& st, double angle) {
  return write_c_steps(s, st, c_steps(s.m, s.c.angle, angle, false, std::nullopt));
}

}  // namespace

void refuse_milling(PostState& s, LiveState& l, const Statement& st, const std::string& why) {
  if (l.reported) return;
  l.reported = true;
  error(s, st, st.loc,
        fmt::format("milling motion with live tool {} (loaded at line {}): {} (docs/millturn.md)",
                    s.tool.number, s.tool_line, why));
}

void keep_mill(PostState& s, LiveState& l, const MillSegment& g) {
  if (s.opts.on_mill) return s.opts.on_mill(g);
  l.written.push_back(g);
}

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
    return refuse_milling(s, l, st,
                          fmt::format("CIRCLE/ with the axis ({}, {}, {})", c.ax, c.ay, c.az));
  if (!s.m.y_axis && !radial && std::abs(std::abs(c.az) / len - 1) > 1e-6)
    return refuse_milling(
        s, l, st,
        fmt::format("CIRCLE/ about the axis ({}, {}, {}), not the spindle axis: without "
                    "a Y axis a live tool's arc is written in the face plane only",
                    c.ax, c.ay, c.az));
  s.circle = c;
}

}  // namespace clpost

#pragma once
// The pieces the milling engine's files share (milling_motion.h is what the live paths call):
// the start of a motion (milling_motion.cc), X Y Z with Y (milling_xyz.cc), X Z C without
// (milling_xzc.cc), a radial tool's tip without Y (milling_tool_line.cc), arcs
// (milling_arc.cc). `l` is the live paths' state.
#include <string>
#include <vector>

#include "interpreter/milling_motion.h"

namespace clpost {

// A milling motion's start (start_motion): the part frame's C index, the turn of C past it that
// brings a radial tool's axis onto X (with Y), the feed per minute, the tool's side.
struct MotionStart {
  double index = 0, turn = 0, feed = 0;
  bool radial = false;  // the tool axis is radial (k 0): peripheral work
};

// An arc or a helix in the part frame: about `axis` (a unit vector) through `center`, turning
// `sense` (+1 positive about the axis, -1 negative), from `from` to `to` (its advance along
// the axis linear).
struct MillArc {
  Point3 center, axis;
  int sense = 1;
  uint32_t line = 0;  // its CIRCLE/ or HELICAL/
};

// A milling motion clpost does not write: an error at the first of the tool's, the rest left
// out (one cause, one message).
void refuse_milling(PostState& s, LiveState& l, const Statement& st, const std::string& why);

// Where a milling motion starts: checked, C set (at the index, or past it for a radial tool on
// a machine with Y). False (reported, or nothing to write) when the motion is not written.
bool start_motion(PostState& s, LiveState& l, const Statement& st, bool rapid, Point3 to,
                  MotionStart& ms);

// A milling piece to verify (PostOptions::on_mill), else kept (LiveState::written).
void keep_mill(PostState& s, LiveState& l, const MillSegment& g);

// The feed-per-minute code (codes.feed_per_min) before the first feed block of the milling (the
// lathe's last mode may be per revolution).
void per_minute_code(PostState& s, LiveState& l, NcWriter& w);

// The straight part-frame move `from` -> `to` at C index `index`, without Y, its pieces within
// `tol`.
void xzc_move(PostState& s, LiveState& l, Point3 from, Point3 to, double index, bool rapid,
              double feed, double tol);

// Without Y: the side plane (plane_side) before peripheral work and the lathe plane
// (plane_lathe) before face work after it, when the machine has the codes. No G1 depends on the
// plane: it says which work the XZC moves are (plot's peripheral view is drawn by it).
void xzc_plane(PostState& s, LiveState& l, bool radial);

// Part point `p` in the machine's X Y Z with C turned `turn` degrees past the index: the
// point turned back by `turn` (X as a radius).
Point3 machine_xyz(Point3 p, double turn);

// The straight move to machine point `m` (a machine with Y, C set): X (diameter) Y Z, exact.
void xyz_move(PostState& s, LiveState& l, Point3 m, bool rapid, double feed, int plane);

// The arc in the machine's plane (C turned `turn` past the index): G2/G3 with the two centre
// words of the plane; false when its axis is along none of X, Y, Z there, or its plane is not
// the one cutter compensation is on in.
bool xyz_arc(PostState& s, LiveState& l, const MillArc& c, Point3 from, Point3 to, double turn,
             double feed);

// Without Y, where the machine puts a radial tool's CL point `p` (on_tool_line): at its radius
// and at the angle of the tool axis, within the tolerance of `p`, so that C comes from the tool
// axis (a move along the axis keeps C: the CL's rounded points do not turn it by a hair).
Point3 machine_tip(const PostState& s, const MotionStart& ms, Point3 p);

// Without Y, a radial tool's CL point: on the line of its axis through the centre line.
bool tip_reached(PostState& s, LiveState& l, const Statement& st, const MotionStart& ms, Point3 p);

// Without Y, whether a radial tool reaches the arc's points (reported if not): about Z every
// point (C follows the tip), about another axis only when they lie on the line of the tool axis
// (an arc in the plane of the axis and Z, at one C). A face tool's arc is about Z only.
bool xzc_arc_reached(PostState& s, LiveState& l, const Statement& st, const MillArc& c,
                     const std::vector<Point3>& points, bool radial);

// The arc `c` to `to`: G2/G3 in the machine's plane with Y, lines within the tolerance without.
void mill_arc(PostState& s, LiveState& l, const Statement& st, const MillArc& c, Point3 from,
              Point3 to, const MotionStart& ms);

}  // namespace clpost

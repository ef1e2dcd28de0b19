// The moves of a machine with C in X, Y, Z and C (docs/millturn.md), for verify of milling
// (verify/mill_verify.h): each motion block's end as the control reads it.
#include <cmath>

#include "simulator/sim_state.h"

namespace clpost::sim {

namespace {

void keep(State& s, SimMillMove&& mv) {
  if (s.opt.on_mill_move) return s.opt.on_mill_move(mv);
  s.out.mill_moves.push_back(std::move(mv));
}

}  // namespace

// Only the moves from the last one before C is first written are kept: where C is before it is
// written the control does not say, so no move before can be on a CL milling path (the part
// frame turns with C), and clpost writes C before a live tool's first milling move (its C index
// or the move's own C word; interpreter/milling_motion.cc). The last move before is kept for
// the milling that starts where it ended. A program without milling, which never writes C,
// keeps one move, not one per block (issue #26: memory does not depend on the file's length).
void mill_move(State& s, const NcBlock& b) {
  const NcWord* x = b.find("X");
  const NcWord* y = b.find("Y");
  const NcWord* z = b.find("Z");
  const bool c = b.find(s.m.c_address) != nullptr;
  if (x == nullptr && y == nullptr && z == nullptr && !c) return;
  const bool arc = s.motion == Motion::kArcCw || s.motion == Motion::kArcCcw;
  if (s.motion != Motion::kRapid && s.motion != Motion::kLinear && !arc) return;
  ++s.out.mill_move_count;
  SimMillMove mv;
  mv.line = s.line;
  mv.line_text.assign(s.line_text);
  mv.rapid = s.motion == Motion::kRapid;
  mv.arc = arc;
  mv.x = x ? s.radius(*x) : s.pos.x;
  if (y) s.y = s.value(*y);
  mv.y = s.y;
  mv.z = z ? s.value(*z) : s.pos.z;
  mv.c = s.c.value_or(0);
  mv.c_known = s.c.has_value();
  mv.at_known = s.pos_known || (x != nullptr && z != nullptr);
  mv.plane = s.plane;
  mv.ccw = s.motion == Motion::kArcCcw;
  if (arc) {
    if (const NcWord* w = b.find("I")) mv.i = s.value(*w);
    if (const NcWord* w = b.find("J")) mv.j = s.value(*w);
    if (const NcWord* w = b.find("K")) mv.k = s.value(*w);
  }
  mv.tool = s.cut.tool;
  if (!s.c) {
    s.mill_before = std::move(mv);
    return;
  }
  if (s.mill_before) keep(s, std::move(*s.mill_before));
  s.mill_before.reset();
  keep(s, std::move(mv));
}

// The plane of polar interpolation is the machine's X and Y at the C the mode started at ("the
// angle of 0 for the position of the tool when G12.1 is specified": interpreter/milling_polar.cc
// quotes the sources): a move in it is X (millturn.polar_x) and the virtual axis
// (millturn.polar_address) at that C, a straight line (or a G2/G3 with I, J) in X and Y.
void polar_move(State& s, const NcBlock& b) {
  const NcWord* x = b.find("X");
  const NcWord* v = b.find(s.m.polar_address);
  const NcWord* z = b.find("Z");
  if (x) s.polar_x = s.value(*x) / (s.m.polar_x == PolarX::kDiameter ? 2 : 1);
  if (v) s.polar_y = s.value(*v);
  if (z) s.pos.z = s.value(*z);
  s.pos.x = std::hypot(s.polar_x, s.polar_y);
  if (x == nullptr && v == nullptr && z == nullptr) return;
  const bool arc = s.motion == Motion::kArcCw || s.motion == Motion::kArcCcw;
  if (s.motion != Motion::kRapid && s.motion != Motion::kLinear && !arc) return;
  ++s.out.mill_move_count;
  SimMillMove mv;
  mv.line = s.line;
  mv.line_text.assign(s.line_text);
  mv.rapid = s.motion == Motion::kRapid;
  mv.arc = arc;
  mv.x = s.polar_x;
  mv.y = s.polar_y;
  mv.z = s.pos.z;
  mv.c = s.polar_c;
  mv.c_known = true;
  if (x && v && z) s.polar_known = true;
  mv.at_known = s.polar_known;
  mv.plane = 17;
  mv.ccw = s.motion == Motion::kArcCcw;
  if (arc) {
    if (const NcWord* w = b.find("I")) mv.i = s.value(*w);
    if (const NcWord* w = b.find("J")) mv.j = s.value(*w);
  }
  mv.tool = s.cut.tool;
  if (s.mill_before) keep(s, std::move(*s.mill_before));
  s.mill_before.reset();
  keep(s, std::move(mv));
}

}  // namespace clpost::sim

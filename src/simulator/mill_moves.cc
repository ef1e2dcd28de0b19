// The moves of a machine with C in X, Y, Z and C (docs/millturn.md), for verify of milling
// (verify/mill_verify.h): each motion block's end as the control reads it.
#include "simulator/sim_state.h"

namespace clpost::sim {

void mill_move(State& s, const NcBlock& b) {
  const NcWord* x = b.find("X");
  const NcWord* y = b.find("Y");
  const NcWord* z = b.find("Z");
  const bool c = b.find(s.m.c_address) != nullptr;
  if (x == nullptr && y == nullptr && z == nullptr && !c) return;
  const bool arc = s.motion == Motion::kArcCw || s.motion == Motion::kArcCcw;
  if (s.motion != Motion::kRapid && s.motion != Motion::kLinear && !arc) return;
  SimMillMove mv;
  mv.line = s.line;
  mv.line_text = std::string(s.line_text);
  mv.rapid = s.motion == Motion::kRapid;
  mv.arc = arc;
  mv.x = x ? s.radius(*x) : s.pos.x;
  if (y) s.y = s.value(*y);
  mv.y = s.y;
  mv.z = z ? s.value(*z) : s.pos.z;
  mv.c = s.c.value_or(0);
  s.out.mill_moves.push_back(std::move(mv));
}

}  // namespace clpost::sim

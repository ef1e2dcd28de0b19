#include "toy_control/toy_readback.h"

#include "simulator/cycle_words.h"
#include "simulator/sim_state.h"
#include "toy_control/toy_law.h"

namespace clpost::toy {

namespace {

bool g177(sim::State& s, const NcBlock& b) {
  const sim::Code code{"G", 177};
  if (!sim::has_code(b, code)) return false;
  if (sim::missing(s, b, code, "XZKF")) return true;
  G177Words w;
  w.x = s.radius(*b.find("X"));
  w.z = s.value(*b.find("Z"));
  w.k = s.value(*b.find("K"));
  w.f = s.value(*b.find("F"));
  const Vec2 start = s.pos;
  s.cycle_cuts({expand_g177(w)}, start, start, "G177", w.f, std::nullopt, false, false);
  return true;
}

}  // namespace

const sim::ControlReadback kReadback{.cycle = g177};

}  // namespace clpost::toy

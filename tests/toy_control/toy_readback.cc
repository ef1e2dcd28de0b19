#include "toy_control/toy_readback.h"

#include "simulator/cycle_words.h"
#include "simulator/sim_state.h"
#include "toy_control/toy_law.h"
#include "toy_control/toy_templates.h"

namespace clpost::toy {

namespace {

// G178's modal F.
struct ToyState : sim::ReadbackState {
  double f = 0;
  bool f_known = false;
};

bool g177(sim::State& s, const NcBlock& b) {
  const sim::Code code = sim::template_code(s.m, kG177);
  if (!sim::has_code(b, code)) return false;
  if (sim::missing(s, b, code, "XZKF")) return true;
  G177Words w;
  w.x = s.radius(*b.find("X"));
  w.z = s.value(*b.find("Z"));
  w.k = s.value(*b.find("K"));
  w.f = s.value(*b.find("F"));
  const Vec2 start = s.pos;
  s.cycle_cuts({expand_g177(w, toy_run_in(s.m))}, start, start, "G177", w.f, std::nullopt, false,
               false);
  return true;
}

}  // namespace

std::unique_ptr<sim::ReadbackState> readback_state() {
  return std::make_unique<ToyState>();
}

bool g178(sim::State& s, const NcBlock& b) {
  const sim::Code code = sim::template_code(s.m, kG178);
  if (!sim::has_code(b, code)) return false;
  if (sim::missing(s, b, code, "XZ")) return true;
  ToyState& state = s.own<ToyState>(readback_state);
  if (const NcWord* f = b.find("F")) {
    state.f = s.value(*f);
    state.f_known = true;
  }
  if (!state.f_known) {
    s.error(b.words.front().col, "G178 without a lead: no F in it or before it");
    return true;
  }
  const G178Words w{s.radius(*b.find("X")), s.value(*b.find("Z")), state.f};
  const Vec2 start = s.pos;
  s.cycle_cuts({expand_g178(w, start)}, start, start, "G178", w.f, std::nullopt, false, false);
  return true;
}

const sim::ControlReadback kReadback{.cycle = g177};

}  // namespace clpost::toy

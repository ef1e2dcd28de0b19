#include "controls/linuxcnc/linuxcnc_readback.h"

#include <fmt/format.h>

#include <cmath>

#include "controls/linuxcnc/linuxcnc_law.h"
#include "controls/linuxcnc/linuxcnc_templates.h"
#include "simulator/cycle_words.h"
#include "simulator/sim_state.h"

namespace clpost::sim {

bool linuxcnc_g76(State& s, const NcBlock& b) {
  Code code = template_code(s.m, tmpl::kLinuxcncG76);
  if (!has_code(b, code)) return false;
  for (const char* a : {"P", "Z", "I", "J", "K"})
    if (b.find(a) == nullptr) {
      s.error(first_col(b), fmt::format("G76 without its {} word", a));
      return true;
    }
  LinuxcncG76 w;
  w.p = word_or(s, b, "P", "g76_lead", 0);
  w.z = word_or(s, b, "Z", "Z", 0);
  w.i = word_or(s, b, "I", "g76_depth", 0);
  w.j = word_or(s, b, "J", "g76_depth", 0);
  w.k = word_or(s, b, "K", "g76_depth", 0);
  w.r = word_or(s, b, "R", "R", 1);
  w.q = word_or(s, b, "Q", "g76_angle", 0);
  bool bad = false;
  auto whole = [&](double v, const char* name, int lo, int hi) {
    const std::optional<int> r = s.whole(v, name, lo, hi, first_col(b));
    bad = bad || !r;
    return r.value_or(lo);
  };
  w.h = whole(word_or(s, b, "H", "H", 0), "H", 0, kMaxCyclePasses);
  w.e = word_or(s, b, "E", "g76_taper", 0);
  w.l = whole(word_or(s, b, "L", "L", 0), "L", 0, 3);
  if (bad) return true;
  // The depths J n^(1/R) reach K after (K/J)^R passes: no more than a plan can hold.
  if (w.j > 0 && w.k > w.j && std::pow(w.k / w.j, std::max(w.r, 1.0)) > kMaxCyclePasses + 1) {
    s.error(first_col(b), fmt::format("G76 J{:g} K{:g} R{:g}: more than {} passes", w.j, w.k, w.r,
                                      kMaxCyclePasses));
    return true;
  }
  std::string refused;
  const std::vector<Cut> cuts = expand_linuxcnc_g76(w, s.pos, s.diameter, &refused);
  if (!refused.empty()) {
    s.error(first_col(b), refused);
    return true;
  }
  const Vec2 start = s.pos;
  s.cycle_cuts(cuts, start, {start.x, w.z}, "G76", w.p, std::nullopt, false, false);
  return true;
}

const ControlReadback kLinuxcncReadback{
    .cycle = linuxcnc_g76, .diameter_on = "G7", .diameter_off = "G8"};

}  // namespace clpost::sim

#include "controls/haas/haas_readback.h"

#include <fmt/format.h>

#include <cmath>

#include "controls/fanuc/fanuc_readback.h"
#include "controls/haas/haas_law.h"
#include "controls/haas/haas_templates.h"
#include "simulator/cycle_words.h"
#include "simulator/sim_state.h"

namespace clpost::sim {

bool haas_g76(State& s, const NcBlock& b) {
  const Code code = template_code(s.m, tmpl::kHaasG76);
  if (!has_code(b, code)) return false;
  if (missing(s, b, code, "XZKDF")) return true;
  HaasG76Words w;
  w.x = s.value(*b.find("X"));
  w.z = s.value(*b.find("Z"));
  if (const NcWord* i = b.find("I")) w.taper = s.value(*i);
  w.height = s.value(*b.find("K"));
  w.first_cut = s.value(*b.find("D"));
  if (const NcWord* a = b.find("A")) {
    const std::optional<int> v = s.whole(a->value, "A", 0, 120, a->col);
    if (!v) return true;
    w.tool_angle = *v;
  }
  if (const NcWord* p = b.find("P")) {
    const std::optional<int> v = s.whole(p->value, "P", 1, 4, p->col);
    if (!v) return true;
    w.mode = *v;
  }
  if (const NcWord* q = b.find("Q")) w.start_angle = s.value(*q, "thread_angle");
  w.lead = s.value(*b.find("F"));
  if (!s.diameter) w.x *= 2;
  const HaasSettings settings = haas_settings(s.m, s.out.units);
  const CycleLaw law{true, s.m.cycle_shifted_end, settings.chamfer_angle};
  const std::vector<Cut> cuts = expand_haas_g76(w, s.pos, settings, law, 1);
  if (cuts.empty()) {
    s.error(b.words.front().col,
            fmt::format("G76 cuts nothing from Z{:g} to Z{:g}: height K {:g}, first cut D {:g}",
                        s.pos.z, w.z, w.height, w.first_cut));
    return true;
  }
  const Vec2 start = s.pos;
  s.cycle_cuts(cuts, start, start, "G76", w.lead, w.start_angle, !s.m.cycle_shifted_end, false);
  return true;
}

const ControlReadback kHaasReadback{.cycle = haas_g76};

}  // namespace clpost::sim

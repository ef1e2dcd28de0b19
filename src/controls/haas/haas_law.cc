#include "controls/haas/haas_law.h"

#include <algorithm>
#include <cmath>
#include <numbers>

#include "controls/haas/haas_keys.h"
#include "machine/machine.h"
#include "support/angles.h"

namespace clpost {

std::vector<double> haas_g76_depths(const HaasG76Words& w, const HaasSettings& s) {
  const double rough_to = w.height - s.finish_allowance;
  const bool sqrt_law = w.mode == 1 || w.mode == 2;
  std::vector<double> out = g76_rough_depths(w.first_cut, s.min_cut, rough_to, sqrt_law);
  if (out.empty() && rough_to > 1e-12) return {};
  if (s.finish_allowance > 0) out.push_back(w.height);
  return out;
}

std::vector<Cut> expand_haas_g76(const HaasG76Words& w, Vec2 start, const HaasSettings& s,
                                 const CycleLaw& law, int starts) {
  FlankCycle g;
  g.start = start;
  g.end = {w.x / diameter_factor(law.diameter), w.z};
  g.taper = w.taper;
  g.height = w.height;
  g.flank = w.tool_angle / 2.0;
  g.chamfer = s.chamfer * w.lead;
  g.chamfer_angle = s.chamfer_angle;
  g.shifted_end = law.shifted_end;
  int start_index = 0;
  if (w.start_angle && starts > 1) {
    long k = std::lround(*w.start_angle * starts / 360.0);
    start_index = static_cast<int>(((k % starts) + starts) % starts);
  }
  const std::vector<double> depths = haas_g76_depths(w, s);
  if (w.mode == 1 || w.mode == 3) return expand_flank_cycle(g, depths, start_index);
  // Alternating edges: odd passes straight in, even ones along the flank.
  FlankCycle radial = g;
  radial.flank = 0;
  std::vector<Cut> out;
  for (size_t i = 0; i < depths.size(); ++i) {
    const std::vector<double> one{depths[i]};
    // The shifted-end rule needs the deepest shift of the whole cycle.
    FlankCycle gi = i % 2 == 1 ? g : radial;
    std::vector<Cut> c = expand_flank_cycle(gi, one, start_index);
    if (c.empty()) return {};  // words the figure cannot draw (a pass at no depth, ...)
    if (gi.shifted_end && gi.flank > 0) {
      const double h_max = *std::max_element(depths.begin(), depths.end());
      const double tan_f = std::tan(radians(gi.flank));
      const double dirz = g.end.z < g.start.z ? -1.0 : 1.0;
      const double back = (h_max - depths[i]) * tan_f * dirz;
      c[0].to.z -= back;
      c[0].end.z -= back;
    }
    out.push_back(c[0]);
  }
  return out;
}

HaasSettings haas_settings(const Machine& m, LengthUnit plan_units) {
  double f = 1;
  if (m.default_units == "mm" && plan_units == LengthUnit::kInch) f = 1 / 25.4;
  if (m.default_units == "in" && plan_units == LengthUnit::kMm) f = 25.4;
  HaasSettings s;
  s.finish_allowance = control_value(m, kHaasFinishAllowance) * f;
  s.min_cut = control_value(m, kHaasMinCut) * f;
  s.chamfer = control_value(m, kHaasChamfer);
  s.chamfer_angle = m.chamfer_angle;
  return s;
}

}  // namespace clpost

#include "controls/fanuc/fanuc_law.h"

#include <algorithm>
#include <cmath>

#include "machine/machine.h"
#include "support/angles.h"
#include "support/vec2_math.h"

namespace clpost {

using namespace vec2_math;

std::vector<Cut> expand_flank_cycle(const FlankCycle& g, const std::vector<double>& heights,
                                    int start) {
  std::vector<Cut> out;
  const double span = g.start.z - g.end.z;
  if (heights.empty() || std::fabs(span) < 1e-12) return out;
  const double s = g.end.x < g.start.x ? 1.0 : -1.0;  // outward: external +X, internal -X
  const double dirz = g.end.z < g.start.z ? -1.0 : 1.0;
  const double slope = g.taper / span;
  const double cos_t = 1 / std::sqrt(1 + slope * slope);
  const double tan_f = std::tan(radians(g.flank));
  const double h_max = *std::max_element(heights.begin(), heights.end());
  const double sigma_max = h_max * tan_f;
  for (double h : heights) {
    // The line of this depth: the full-depth line moved out by what is left of the height.
    auto line = [&](double z) { return g.end.x + slope * (z - g.end.z) + s * (g.height - h); };
    const double sigma = h * tan_f;
    Cut c;
    c.start = start;
    c.depth = h * cos_t;
    c.from.z = g.start.z + dirz * sigma;
    c.from.x = line(c.from.z);
    const double ze = g.shifted_end ? g.end.z - dirz * (sigma_max - sigma) : g.end.z;
    if (g.chamfer > 0) {
      c.to.z = ze - dirz * g.chamfer;
      c.to.x = line(c.to.z);
      c.end = {c.to.x + s * g.chamfer * std::tan(radians(g.chamfer_angle)), ze};
    } else {
      c.to = {line(ze), ze};
      c.end = c.to;
    }
    out.push_back(c);
  }
  return out;
}

bool fanuc_g76_tool_angle_ok(int a) {
  return a == 80 || a == 60 || a == 55 || a == 30 || a == 29 || a == 0;
}

std::vector<double> g76_rough_depths(double first_cut, double min_cut, double rough_to,
                                     bool sqrt_law) {
  std::vector<double> out;
  if (rough_to <= 1e-12) return out;
  if (first_cut <= 0 && min_cut <= 0) return {};
  double prev = 0;
  for (int n = 1;; ++n) {
    if (n > 1000) return {};
    const double law = sqrt_law ? first_cut * std::sqrt(static_cast<double>(n)) : first_cut * n;
    const double d = std::max(law, prev + min_cut);
    if (d >= rough_to - 1e-9) {
      out.push_back(rough_to);
      return out;
    }
    out.push_back(d);
    prev = d;
  }
}

std::vector<double> fanuc_g76_depths(const FanucG76Words& w) {
  const double rough_to = w.height - w.allowance;
  std::vector<double> out = g76_rough_depths(w.first_cut, w.min_cut, rough_to, true);
  if (out.empty() && rough_to > 1e-12) return {};
  for (int i = 0; i < w.finish_passes; ++i) out.push_back(w.height);
  return out;
}

std::vector<Cut> expand_fanuc_g76(const FanucG76Words& w, Vec2 start, const CycleLaw& law) {
  FlankCycle g;
  g.start = start;
  g.end = {w.x / diameter_factor(law.diameter), w.z};
  g.taper = w.taper;
  g.height = w.height;
  g.flank = w.tool_angle / 2.0;
  g.chamfer = w.chamfer * 0.1 * w.lead;
  g.chamfer_angle = law.chamfer_angle;
  g.shifted_end = law.shifted_end;
  return expand_flank_cycle(g, fanuc_g76_depths(w));
}

std::vector<Cut> expand_g92(const std::vector<G92Pass>& passes, bool diameter, Vec2 p1, Vec2 p2,
                            int starts) {
  std::vector<Cut> out;
  const Vec2 line = p2 - p1;
  const double len = length(line);
  for (const G92Pass& p : passes) {
    const double xr = p.words.x / diameter_factor(diameter);
    Cut c;
    c.from = {xr + p.words.taper, p.start.z};
    c.to = {xr, p.words.z};
    c.end = c.to;
    if (len > 0) {
      const Vec2 v = c.to - p1;
      c.depth = std::fabs(line.x * v.z - line.z * v.x) / len;
    }
    if (p.words.start_angle && starts > 1) {
      long k = std::lround(*p.words.start_angle * starts / 360.0);
      c.start = static_cast<int>(((k % starts) + starts) % starts);
    }
    out.push_back(c);
  }
  return out;
}

}  // namespace clpost

#include "plot/thread_profile.h"
#include "support/angles.h"

#include <algorithm>
#include <cmath>
#include <initializer_list>
#include <numbers>

namespace clpost {

double half_angle_tan(const ThreadSection& s) {
  const double a = std::isfinite(s.tool_angle) ? std::clamp(s.tool_angle, 1.0, 179.0) : 60.0;
  return std::tan(radians(a / 2));
}

double groove_pitch(const ThreadSection& s) {
  if (std::isfinite(s.pitch) && s.pitch > 0) return s.pitch;
  if (std::isfinite(s.lead) && s.lead > 0 && s.starts > 0) return s.lead / s.starts;
  const double d = std::isfinite(s.depth) ? std::fabs(s.depth) : 0;
  const double w = 3 * d * half_angle_tan(s);
  return w > 0 ? w : 1;
}

int groove_count(const ThreadSection& s) {
  int n = std::clamp(s.starts, 1, 24);
  for (const SectionPass& p : s.passes)
    if (p.start >= n && p.start < 24) n = p.start + 1;
  return n;
}

bool drawable(const SectionPass& p) {
  return std::isfinite(p.depth) && std::isfinite(p.shift);
}

SectionPoint pass_tip(const ThreadSection& s, const SectionPass& p) {
  const int k = std::clamp(p.start, 0, 23);
  return {k * groove_pitch(s) + p.shift, p.depth};
}

std::vector<SectionPoint> cutting_tips(const ThreadSection& s) {
  std::vector<SectionPoint> tips;
  for (const SectionPass& p : s.passes)
    if (drawable(p)) tips.push_back(pass_tip(s, p));
  if (tips.empty()) {
    const double d = std::isfinite(s.depth) ? s.depth : 0;
    for (int k = 0; k < groove_count(s); ++k) tips.push_back({k * groove_pitch(s), d});
  }
  return tips;
}

std::vector<SectionPoint> cut_profile(const ThreadSection& s, double u_lo, double u_hi,
                                      int samples) {
  std::vector<SectionPoint> out;
  if (!(u_hi > u_lo) || !std::isfinite(u_lo) || !std::isfinite(u_hi)) return out;
  const double tn = half_angle_tan(s);
  const double lead = groove_count(s) * groove_pitch(s);
  // Every V that reaches the window, with its copies one lead apart.
  std::vector<SectionPoint> vs;
  for (const SectionPoint& t : cutting_tips(s)) {
    if (t.d <= 0) continue;
    const double half = t.d * tn;
    for (int m = -2; m <= 2; ++m) {
      const SectionPoint c{t.u + m * lead, t.d};
      if (c.u + half >= u_lo && c.u - half <= u_hi) vs.push_back(c);
    }
  }
  std::vector<double> us;
  samples = std::clamp(samples, 2, 100000);
  for (int i = 0; i <= samples; ++i) us.push_back(u_lo + (u_hi - u_lo) * i / samples);
  for (const SectionPoint& v : vs)
    for (const double u : {v.u - v.d * tn, v.u, v.u + v.d * tn})
      if (u > u_lo && u < u_hi) us.push_back(u);
  std::sort(us.begin(), us.end());
  us.erase(std::unique(us.begin(), us.end()), us.end());
  out.reserve(us.size());
  for (const double u : us) {
    double d = 0;
    for (const SectionPoint& v : vs) d = std::max(d, v.d - std::fabs(u - v.u) / tn);
    out.push_back({u, d});
  }
  // Drop the samples in the middle of straight stretches.
  std::vector<SectionPoint> kept;
  kept.reserve(out.size());
  for (size_t i = 0; i < out.size(); ++i) {
    if (i > 0 && i + 1 < out.size() && !kept.empty()) {
      const SectionPoint a = kept.back();
      const SectionPoint b = out[i];
      const SectionPoint c = out[i + 1];
      const double cross = (b.u - a.u) * (c.d - a.d) - (b.d - a.d) * (c.u - a.u);
      const double scale = (c.u - a.u) * (c.u - a.u) + (c.d - a.d) * (c.d - a.d);
      if (std::fabs(cross) <= 1e-9 * scale) continue;
    }
    kept.push_back(out[i]);
  }
  return kept;
}

}  // namespace clpost

#include "controls/heidenhain/heidenhain_law.h"

#include <fmt/format.h>

#include <algorithm>
#include <cmath>
#include <cstdlib>

#include "planner/vec2_math.h"

namespace clpost {

namespace {

int code_int(const Machine& m, const char* key, int fallback) {
  const std::string& c = m.code(key);
  if (c.empty()) return fallback;
  return std::atoi(c.c_str());
}

}  // namespace

G31FlankCodes g31_flank_codes(const Machine& m) {
  G31FlankCodes c;
  c.toward_minus = code_int(m, "g31_h_minus", 1);
  c.toward_plus = code_int(m, "g31_h_plus", 2);
  c.alternating = code_int(m, "g31_h_alternating", 3);
  return c;
}

using namespace vec2_math;

std::vector<Cut> expand_heidenhain_g31(const HeidenhainG31& w, const G31FlankCodes& codes,
                                       std::string* error) {
  auto refuse = [&](std::string msg) {
    if (error) *error = std::move(msg);
    return std::vector<Cut>{};
  };
  if (w.v != 0 && w.v != 1) return refuse(fmt::format("infeed type V{} is not expanded", w.v));
  if (w.ic < 1) return refuse(fmt::format("IC{}: at least one cut is needed", w.ic));
  if (w.u <= 0) return refuse("U must be positive");
  if (w.d > 1) return refuse(fmt::format("D{}: multi-start G31 is not expanded", w.d));
  if (w.k != 0) return refuse("K (run-out length) is not expanded");
  const Vec2 seg = w.to - w.from;
  const double len = length(seg);
  if (len <= 0) return refuse("the contour element has no length");
  const Vec2 t = (1 / len) * seg;
  const bool face = std::fabs(seg.x) > std::fabs(seg.z);
  // Inward normal (into the material), at right angles to the element.
  Vec2 n{t.z, -t.x};
  const bool toward_axis = w.bd == 0;
  if (face ? n.z > 0 : (n.x > 0) == toward_axis) n = -n;
  if (face && w.bd != 0) n = -n;
  // Direction of the flank offset.
  Vec2 e{0, 0};
  bool alternating = false;
  const Vec2 lead_axis = face ? Vec2{1, 0} : Vec2{0, 1};
  if (w.h == 0) {
  } else if (w.h == codes.toward_minus) {
    e = dot(t, lead_axis) < 0 ? t : -t;
  } else if (w.h == codes.toward_plus) {
    e = dot(t, lead_axis) > 0 ? t : -t;
  } else if (w.h == codes.alternating) {
    e = t;
    alternating = true;
  } else {
    return refuse(fmt::format("flank offset H{} is not expanded", w.h));
  }
  const double tan_a = std::tan(rad(w.a));

  std::vector<double> depths;
  for (int i = 1; i <= w.ic; ++i)
    depths.push_back(w.v == 0 ? w.u * std::sqrt(static_cast<double>(i) / w.ic) : w.u * i / w.ic);
  for (int i = 0; i < w.q; ++i) depths.push_back(w.u);
  std::vector<double> sigma;
  double sigma_max = 0;
  for (size_t i = 0; i < depths.size(); ++i) {
    const bool straight = alternating && (i + 1) % 2 == 1;
    sigma.push_back(straight ? 0 : depths[i] * tan_a);
    sigma_max = std::max(sigma_max, sigma.back());
  }
  std::vector<Cut> out;
  for (size_t i = 0; i < depths.size(); ++i) {
    Cut c;
    c.depth = depths[i];
    const Vec2 base = depths[i] * n + sigma[i] * e;
    c.from = w.from + base - w.b * t;
    c.to = w.to + base - sigma_max * e + w.p * t;
    c.end = c.to;
    out.push_back(c);
  }
  return out;
}

}  // namespace clpost

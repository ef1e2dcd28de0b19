#include "controls/heidenhain/heidenhain_law.h"

#include <fmt/format.h>

#include <algorithm>
#include <cmath>
#include <cstdlib>
#include <optional>

#include "support/angles.h"
#include "support/vec2_math.h"

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

namespace {

// The direction into the material, at right angles to the element `t`: toward the axis for BD0
// (external), away from it for BD1 (internal); a face element is cut toward -Z for BD0.
Vec2 inward_normal(Vec2 t, bool face, int bd) {
  Vec2 n{t.z, -t.x};
  const bool toward_axis = bd == 0;
  if (face ? n.z > 0 : (n.x > 0) == toward_axis) n = -n;
  if (face && bd != 0) n = -n;
  return n;
}

// The flank offset H: the direction along the element every cut is offset in, and whether only
// the even-numbered cuts are (alternating).
struct FlankOffset {
  Vec2 e{0, 0};
  bool alternating = false;
};

// The offset H stands for (G31FlankCodes, machine data), or none for an H the law does not cover.
std::optional<FlankOffset> flank_offset(int h, Vec2 t, bool face, const G31FlankCodes& codes) {
  FlankOffset f;
  const Vec2 lead_axis = face ? Vec2{1, 0} : Vec2{0, 1};
  if (h == 0) {
  } else if (h == codes.toward_minus) {
    f.e = dot(t, lead_axis) < 0 ? t : -t;
  } else if (h == codes.toward_plus) {
    f.e = dot(t, lead_axis) > 0 ? t : -t;
  } else if (h == codes.alternating) {
    f.e = t;
    f.alternating = true;
  } else {
    return std::nullopt;
  }
  return f;
}

// The depth of every cut below the contour: IC cuts, V0 constant cross-section U·√(n/IC), V1
// constant infeed U·n/IC, then Q air cuts at U.
std::vector<double> cut_depths(const HeidenhainG31& w) {
  std::vector<double> depths;
  for (int i = 1; i <= w.ic; ++i)
    depths.push_back(w.v == 0 ? w.u * std::sqrt(static_cast<double>(i) / w.ic) : w.u * i / w.ic);
  for (int i = 0; i < w.q; ++i) depths.push_back(w.u);
  return depths;
}

// How far every cut is offset along the element: σ = depth·tan(A), none on the odd-numbered cuts
// when the offset alternates (they plunge).
std::vector<double> flank_shifts(const std::vector<double>& depths, double a, bool alternating) {
  const double tan_a = std::tan(radians(a));
  std::vector<double> sigma;
  for (size_t i = 0; i < depths.size(); ++i) {
    const bool straight = alternating && (i + 1) % 2 == 1;
    sigma.push_back(straight ? 0 : depths[i] * tan_a);
  }
  return sigma;
}

}  // namespace

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
  const Vec2 n = inward_normal(t, face, w.bd);
  const std::optional<FlankOffset> flank = flank_offset(w.h, t, face, codes);
  if (!flank) return refuse(fmt::format("flank offset H{} is not expanded", w.h));

  const std::vector<double> depths = cut_depths(w);
  const std::vector<double> sigma = flank_shifts(depths, w.a, flank->alternating);
  double sigma_max = 0;
  for (double s : sigma) sigma_max = std::max(sigma_max, s);
  // Run-in B before the contour start, run-out P after its end; the largest offset is taken off
  // every cut's end, so the deepest offset cut ends exactly at the contour end.
  std::vector<Cut> out;
  for (size_t i = 0; i < depths.size(); ++i) {
    Cut c;
    c.depth = depths[i];
    const Vec2 base = depths[i] * n + sigma[i] * flank->e;
    c.from = w.from + base - w.b * t;
    c.to = w.to + base - sigma_max * flank->e + w.p * t;
    c.end = c.to;
    out.push_back(c);
  }
  return out;
}

}  // namespace clpost

#pragma once
// Angles: one π for the whole program (std::numbers), and the one conversion each way between
// the degrees of CL and NC words and the radians of <cmath>.
#include <numbers>

namespace clpost {

inline constexpr double kPi = std::numbers::pi;

// `deg` degrees in radians.
constexpr double radians(double deg) {
  return deg * kPi / 180;
}
// `rad` radians in degrees.
constexpr double degrees(double rad) {
  return rad * 180 / kPi;
}

}  // namespace clpost

#pragma once
// Vector arithmetic on Vec2 (CL lathe frame: x radial, z axial), for every stage that does
// geometry (the planner, the laws, the emitters, verify). In its own namespace so that it cannot
// clash with other stages' helpers; `using namespace clpost::vec2_math;` in a .cc file to use the
// operators.
#include <cmath>
#include <numbers>

#include "support/angles.h"
#include "support/vec2.h"

namespace clpost::vec2_math {

inline Vec2 operator+(Vec2 a, Vec2 b) {
  return {a.x + b.x, a.z + b.z};
}
inline Vec2 operator-(Vec2 a, Vec2 b) {
  return {a.x - b.x, a.z - b.z};
}
inline Vec2 operator-(Vec2 a) {
  return {-a.x, -a.z};
}
inline Vec2 operator*(double k, Vec2 a) {
  return {k * a.x, k * a.z};
}
inline double dot(Vec2 a, Vec2 b) {
  return a.x * b.x + a.z * b.z;
}
inline double length(Vec2 a) {
  return std::hypot(a.x, a.z);
}

// The unit vector at `deg` degrees in the (Z, X) plane, measured from +X toward +Z.
// Multiples of 90 degrees give exact axis vectors (no 1e-16 crumbs).
inline Vec2 direction(double deg) {
  double r = std::fmod(deg, 360.0);
  if (r < 0) r += 360;
  if (r == 0) return {1, 0};
  if (r == 90) return {0, 1};
  if (r == 180) return {-1, 0};
  if (r == 270) return {0, -1};
  return {std::cos(radians(deg)), std::sin(radians(deg))};
}
// The angle of `v` in the same convention, in [0, 360).
inline double angle_of(Vec2 v) {
  double a = degrees(std::atan2(v.z, v.x));
  if (a < 0) a += 360;
  if (a >= 360) a -= 360;
  return a;
}

}  // namespace clpost::vec2_math

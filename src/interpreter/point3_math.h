#pragma once
// Vector arithmetic on Point3 (a CL point or direction as read, before the lathe frame), for the
// interpreter's 3D geometry: geometric motion (lathe_geometry.cc, geometric_motion.cc) and
// milling (milling_geometry.cc, milling_arc.cc, milling_motion.cc). In its own namespace, like
// vec2_math.h; `using namespace clpost::point3_math;` in a .cc file to use it.
#include <cmath>

#include "laws/xzc_law.h"

namespace clpost::point3_math {

inline Point3 add(Point3 a, Point3 b) {
  return {a.x + b.x, a.y + b.y, a.z + b.z};
}
inline Point3 sub(Point3 a, Point3 b) {
  return {a.x - b.x, a.y - b.y, a.z - b.z};
}
inline Point3 scaled(Point3 a, double k) {
  return {a.x * k, a.y * k, a.z * k};
}
inline double dot(Point3 a, Point3 b) {
  return a.x * b.x + a.y * b.y + a.z * b.z;
}
inline Point3 cross(Point3 a, Point3 b) {
  return {a.y * b.z - a.z * b.y, a.z * b.x - a.x * b.z, a.x * b.y - a.y * b.x};
}
inline double norm(Point3 a) {
  return std::sqrt(dot(a, a));
}

}  // namespace clpost::point3_math

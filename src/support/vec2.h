#pragma once
// The lathe frame's point and vector. In support/ (the lowest stage) because every stage that
// does geometry uses it: the planner's thread descriptions and plans, the laws, the emitters,
// verify and plot. The arithmetic on it is in vec2_math.h.

namespace clpost {

// A point or vector in the CL lathe frame: x is the radial coordinate (a radius), z the spindle
// axis.
struct Vec2 {
  double x = 0;
  double z = 0;
};

}  // namespace clpost

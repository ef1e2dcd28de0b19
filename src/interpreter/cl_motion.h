#pragma once
// A CL motion's end point as the post moved the tool there (GOTO, GODLTA, the end of a CIRCLE
// arc, GOHOME/x,y,z): what `clpost verify` expects the program to reach, in order. Lathe frame
// (x a radius), CL units. Collected only when PostOptions::keep_motions asks.
#include <cstdint>

#include "planner/thread_plan.h"

namespace clpost {

struct ClMotion {
  uint32_t line = 0;  // the CL line
  Vec2 to;
  bool rapid = false;
};

}  // namespace clpost

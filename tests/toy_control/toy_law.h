#pragma once
// The toy control's one cycle, G177 X Z K F, as its (made-up) manual defines it: from where the
// tool is, S, a rapid to (X, K), one synchronized cut to (X, Z) at lead F, a rapid out to S's X
// and back to S. X is a radius here (the emitter and read-back convert the diameter word).
// A law is a pure function from a cycle's words to the cuts the control makes: no Machine, no
// program (src/controls/*/*_law.h do the same for real controls, each citing its manual).
#include <vector>

#include "laws/cut_pass.h"

namespace clpost::toy {

struct G177Words {
  double x = 0;  // the pass's radius
  double z = 0;  // where the cut ends
  double k = 0;  // where the cut starts (the flank shift moves it)
  double f = 0;  // lead
};

// The cut one G177 block makes.
Cut expand_g177(const G177Words& w);

}  // namespace clpost::toy

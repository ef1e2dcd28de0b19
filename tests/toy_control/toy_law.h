#pragma once
// The toy control's cycles as its (made-up) manual defines them; X is a radius here (the
// emitters and read-backs convert the diameter word).
// - G177 X Z K F: from where the tool is, S, a rapid to (X, K'), one synchronized cut to (X, Z)
//   at lead F, a rapid out to S's X and back to S. K' is K moved away from Z by parameter 7
//   (the machine key threading.toy_run_in) leads.
// - G178 X Z [F], the loop block: from S, a rapid to X, a cut to (X, Z), a rapid out to S's X
//   and back to S; F is modal (a block without it cuts at the last F).
// A law is a pure function from a cycle's words to the cuts the control makes: no Machine, no
// program (src/controls/*/*_law.h do the same for real controls, each citing its manual).
#include <vector>

#include "laws/cut_pass.h"
#include "machine/machine.h"

namespace clpost::toy {

struct G177Words {
  double x = 0;  // the pass's radius
  double z = 0;  // where the cut ends
  double k = 0;  // where the cut starts, before parameter 7 (the flank shift moves it)
  double f = 0;  // lead
};

// The cut one G177 block makes, the control's parameter 7 being `run_in` leads.
Cut expand_g177(const G177Words& w, double run_in);

// Where the cut of a G177 block starts (K'): K moved `run_in` leads away from Z.
double g177_start(const G177Words& w, double run_in);

// Parameter 7 on machine `m` (threading.toy_run_in).
double toy_run_in(const Machine& m);

struct G178Words {
  double x = 0;  // the pass's radius
  double z = 0;  // where the cut ends
  double f = 0;  // lead (modal)
};

// The cut one G178 block makes from `s`.
Cut expand_g178(const G178Words& w, Vec2 s);

}  // namespace clpost::toy

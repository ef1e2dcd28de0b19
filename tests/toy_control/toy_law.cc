#include "toy_control/toy_law.h"

#include "toy_control/toy_keys.h"

namespace clpost::toy {

double g177_start(const G177Words& w, double run_in) {
  const double away = w.k >= w.z ? 1 : -1;
  return w.k + away * run_in * w.f;
}

Cut expand_g177(const G177Words& w, double run_in) {
  Cut c;
  c.from = {w.x, g177_start(w, run_in)};
  c.to = {w.x, w.z};
  c.end = c.to;
  return c;
}

double toy_run_in(const Machine& m) {
  return control_value(m, kRunIn);
}

Cut expand_g178(const G178Words& w, Vec2 s) {
  Cut c;
  c.from = {w.x, s.z};
  c.to = {w.x, w.z};
  c.end = c.to;
  return c;
}

}  // namespace clpost::toy

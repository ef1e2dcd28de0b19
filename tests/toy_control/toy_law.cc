#include "toy_control/toy_law.h"

namespace clpost::toy {

Cut expand_g177(const G177Words& w) {
  Cut c;
  c.from = {w.x, w.k};
  c.to = {w.x, w.z};
  c.end = c.to;
  return c;
}

}  // namespace clpost::toy

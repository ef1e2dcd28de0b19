#include "verify/expected_cuts.h"

namespace clpost {

std::vector<ExpectedCut> expected_cuts(const std::vector<ThreadPlan>& plans) {
  std::vector<ExpectedCut> out;
  for (size_t t = 0; t < plans.size(); ++t) {
    const ThreadPlan& plan = plans[t];
    if (plan.form != ThreadForm::kMulti) {
      if (plan.path.size() < 2) continue;
      ExpectedCut c;
      c.thread = t;
      c.pass = 1;
      c.from = plan.path.front();
      c.chain.assign(plan.path.begin() + 1, plan.path.end());
      c.to = c.chain.front();
      c.end = c.chain.back();
      c.kind = PassKind::kFinish;
      out.push_back(std::move(c));
      continue;
    }
    for (const ThreadPass& p : plan.passes) {
      ExpectedCut c;
      c.thread = t;
      c.pass = p.n;
      c.start = p.start;
      c.depth = p.depth;
      c.shift = p.shift;
      c.start_angle = p.start_angle;
      c.from = p.from;
      c.to = p.to;
      c.end = p.pullout_end;
      c.kind = p.kind;
      out.push_back(std::move(c));
    }
  }
  return out;
}

}  // namespace clpost

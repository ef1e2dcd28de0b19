#include "verify/expected_cuts.h"

namespace clpost {

std::vector<ExpectedCut> expected_cuts(const std::vector<ThreadPlan>& plans) {
  std::vector<ExpectedCut> out;
  for (size_t t = 0; t < plans.size(); ++t) {
    const ThreadPlan& plan = plans[t];
    if (plan.form != ThreadForm::kMulti && plan.form != ThreadForm::kChain) {
      if (plan.path.size() < 2) continue;
      ExpectedCut c;
      c.thread = t;
      c.pass = 1;
      c.from = plan.path.front();
      c.chain.assign(plan.path.begin() + 1, plan.path.end());
      c.to = c.chain.front();
      c.end = c.chain.back();
      c.kind = PassKind::kFinish;
      c.path = true;
      out.push_back(std::move(c));
      continue;
    }
    const bool chain = plan.form == ThreadForm::kChain;
    for (const ThreadPass& p : plan.passes) {
      ExpectedCut c;
      if (chain && p.path.size() >= 2) {
        // A chained thread: one synchronized move per segment, and a threaded pull-out after
        // them (a linear one is compared apart).
        c.chain.assign(p.path.begin() + 1, p.path.end());
        if (plan.pullout && !plan.pullout_linear) c.chain.push_back(p.pullout_end);
      }
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

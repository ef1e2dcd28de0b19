#include "toy_control/toy_emitter.h"

#include <cmath>

#include "laws/written_value.h"
#include "toy_control/toy_law.h"

namespace clpost::toy {

namespace {

// The words of each pass as the control reads them back (rounded by the machine's formats).
std::vector<G177Words> pass_words(const ThreadPlan& plan, const Machine& m) {
  std::vector<G177Words> words;
  for (const ThreadPass& p : plan.passes) {
    const double k = diameter_factor(m);
    words.push_back({as_read(m, "X", k * p.from.x) / k, as_read(m, "Z", p.to.z),
                     as_read(m, "K", p.from.z), as_read(m, "F", plan.lead)});
  }
  return words;
}

// What G177 cannot say at all.
std::string refusal(const ThreadPlan& plan) {
  if (plan.form == ThreadForm::kChain) return "a chained thread";
  if (plan.kind != ThreadKind::kTurn) return "not a straight thread along Z";
  if (plan.pitch.starts != 1) return "several starts";
  if (plan.pitch.lead_change != 0) return "a variable lead";
  if (plan.pullout) return "a pull-out";
  return {};
}

}  // namespace

Fit G177Emitter::fit(const ThreadPlan& plan, const Machine& m) const {
  Fit f;
  f.mismatch = refusal(plan);
  if (!f.exact()) return f;
  f.mismatch = lead_word_mismatch(m, plan, "F", "F", cut_tolerance(m));
  if (!f.exact()) return f;
  std::vector<Cut> cuts;
  for (const G177Words& w : pass_words(plan, m)) {
    cuts.push_back(expand_g177(w));
    cuts.back().depth = std::fabs(plan.p1.x - w.x);  // below the thread line P1-P2 (straight)
  }
  f.mismatch = compare_cuts(cuts, plan_cuts(plan), {cut_tolerance(m), false});
  return f;
}

bool G177Emitter::emit(const ThreadPlan& plan, NcProgram& prog, const EmitContext& ctx) {
  const Machine& m = prog.machine();
  if (Fit f = fit(plan, m); !f.exact()) return unfit_error(plan, ctx, m, name(), f.mismatch);
  const Vec2 s = plan.end_position;  // every pass starts and ends there
  prog.rapid(lp(s));
  const double k = diameter_factor(m);
  for (const G177Words& w : pass_words(plan, m)) {
    prog.writer().code("G177").word("X", k * w.x).word("Z", w.z).word("K", w.k).word("F", w.f);
    prog.writer().end_block();
    prog.cycle_ended_at(lp(s));
  }
  return true;
}

}  // namespace clpost::toy

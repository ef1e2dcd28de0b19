#include "toy_control/toy_emitter.h"

#include <cmath>

#include "laws/written_value.h"
#include "toy_control/toy_law.h"
#include "toy_control/toy_templates.h"

namespace clpost::toy {

namespace {

// The G177 words of each pass as the control reads them back (rounded by the machine's
// formats): K before the cut's start by parameter 7.
std::vector<G177Words> g177_words(const ThreadPlan& plan, const Machine& m) {
  const double run_in = toy_run_in(m);
  std::vector<G177Words> words;
  for (const ThreadPass& p : plan.passes) {
    const double d = diameter_factor(m);
    const double away = p.from.z >= p.to.z ? 1 : -1;
    words.push_back({as_read(m, "X", d * p.from.x) / d, as_read(m, "Z", p.to.z),
                     as_read(m, "K", p.from.z - away * run_in * plan.lead),
                     as_read(m, "F", plan.lead)});
  }
  return words;
}

// A G178 block as read, and the start point S it is cut from (the clear line at the pass's
// start).
struct G178Pass {
  G178Words w;
  Vec2 s;
};

std::vector<G178Pass> g178_passes(const ThreadPlan& plan, const Machine& m) {
  std::vector<G178Pass> out;
  for (const ThreadPass& p : plan.passes) {
    const double d = diameter_factor(m);
    out.push_back(
        {{as_read(m, "X", d * p.from.x) / d, as_read(m, "Z", p.to.z), as_read(m, "F", plan.lead)},
         {plan.end_position.x, as_read(m, "Z", p.from.z)}});
  }
  return out;
}

// What neither block can say at all.
std::string refusal(const ThreadPlan& plan) {
  if (plan.form == ThreadForm::kChain) return "a chained thread";
  if (plan.kind != ThreadKind::kTurn) return "not a straight thread along Z";
  if (plan.pitch.starts != 1) return "several starts";
  if (plan.pitch.lead_change != 0) return "a variable lead";
  if (plan.pullout) return "a pull-out";
  return {};
}

// The cuts `cuts` (one per pass) compared with the plan's, after what the block cannot say.
Fit fit_cuts(const ThreadPlan& plan, const Machine& m, std::vector<Cut> cuts) {
  Fit f;
  f.mismatch = refusal(plan);
  if (!f.exact()) return f;
  f.mismatch = lead_word_mismatch(m, plan, "F", "F", cut_tolerance(m));
  if (!f.exact()) return f;
  for (Cut& c : cuts) c.depth = std::fabs(plan.p1.x - c.to.x);  // below the line P1-P2
  f.mismatch = compare_cuts(cuts, plan_cuts(plan), {cut_tolerance(m), false});
  return f;
}

// The toy's code that ends a run of its blocks, when the machine gives it.
void end_cycle(NcProgram& prog) {
  const std::string& end = prog.machine().code("toy_cycle_end");
  if (end.empty()) return;
  prog.writer().code(end);
  prog.writer().end_block();
}

}  // namespace

Fit G177Emitter::fit(const ThreadPlan& plan, const Machine& m) const {
  std::vector<Cut> cuts;
  for (const G177Words& w : g177_words(plan, m)) cuts.push_back(expand_g177(w, toy_run_in(m)));
  return fit_cuts(plan, m, cuts);
}

bool G177Emitter::emit(const ThreadPlan& plan, NcProgram& prog, const EmitContext& ctx) {
  const Machine& m = prog.machine();
  if (Fit f = fit(plan, m); !f.exact()) return unfit_error(plan, ctx, m, name(), f.mismatch);
  const Vec2 s = plan.end_position;  // every pass starts and ends there
  prog.rapid(lp(s));
  const double d = diameter_factor(m);
  for (const G177Words& w : g177_words(plan, m)) {
    TemplateFill<kG177> a;
    a.text<"x">(prog.num("X", d * w.x));
    a.text<"z">(prog.num("Z", w.z));
    a.text<"k">(prog.num("K", w.k));
    a.text<"f">(prog.num("F", w.f));
    if (TemplateWrite r = prog.write_template(a); !r) return template_failed(plan, ctx, m, r);
    prog.cycle_ended_at(lp(s));
  }
  end_cycle(prog);
  return true;
}

Fit G178Emitter::fit(const ThreadPlan& plan, const Machine& m) const {
  std::vector<Cut> cuts;
  for (const G178Pass& p : g178_passes(plan, m)) cuts.push_back(expand_g178(p.w, p.s));
  return fit_cuts(plan, m, cuts);
}

bool G178Emitter::emit(const ThreadPlan& plan, NcProgram& prog, const EmitContext& ctx) {
  const Machine& m = prog.machine();
  if (Fit f = fit(plan, m); !f.exact()) return unfit_error(plan, ctx, m, name(), f.mismatch);
  const double d = diameter_factor(m);
  bool first = true;
  Vec2 at{};  // where the last block left the tool (its S)
  for (const G178Pass& p : g178_passes(plan, m)) {
    if (first || p.s.x != at.x || p.s.z != at.z) prog.rapid(lp(p.s));
    TemplateFill<kG178> a;
    a.text<"x">(prog.num("X", d * p.w.x));
    a.text<"z">(prog.num("Z", p.w.z));
    a.text<"f">(first ? " F" + prog.num("F", p.w.f) : std::string());  // F is modal
    if (TemplateWrite r = prog.write_template(a); !r) return template_failed(plan, ctx, m, r);
    prog.cycle_ended_at(lp(p.s));
    first = false;
    at = p.s;
  }
  end_cycle(prog);
  if (plan.end_position.x != at.x || plan.end_position.z != at.z) prog.rapid(lp(plan.end_position));
  return true;
}

}  // namespace clpost::toy

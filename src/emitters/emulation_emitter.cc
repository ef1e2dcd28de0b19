#include "emitters/emulation_emitter.h"

#include <fmt/format.h>

#include <cmath>

#include "laws/cut_pass.h"
#include "laws/written_value.h"

namespace clpost {

namespace {
double dist(Vec2 a, Vec2 b) {
  return std::hypot(a.x - b.x, a.z - b.z);
}
}  // namespace

ThreadLead thread_lead(const ThreadPlan& plan) {
  ThreadLead l;
  l.lead = plan.lead;
  if (plan.pitch.from_tpi && plan.lead > 0)
    l.tpi = (plan.units == LengthUnit::kMm ? 25.4 : 1.0) / plan.lead;
  l.lead_change = plan.pitch.lead_change;
  return l;
}

Fit EmulationEmitter::fit(const ThreadPlan& plan, const Machine& m) const {
  Fit f;
  if (plan.pitch.lead_change != 0 &&
      m.code(plan.pitch.lead_change > 0 ? "thread_increasing" : "thread_decreasing").empty())
    f.mismatch =
        fmt::format("machine '{}' has no code for a variable lead ({})", m.name,
                    plan.pitch.lead_change > 0 ? "thread_increasing" : "thread_decreasing");
  if (f.exact()) f.mismatch = sync_lead_mismatch(m, plan, cut_tolerance(m));
  return f;
}

bool EmulationEmitter::emit(const ThreadPlan& plan, NcProgram& prog, const EmitContext& ctx) {
  const ThreadLead base = thread_lead(plan);
  for (size_t i = 0; i < plan.passes.size(); ++i) {
    const ThreadPass& p = plan.passes[i];
    std::string kind = p.kind == PassKind::kRough    ? "rough"
                       : p.kind == PassKind::kFinish ? "finish"
                                                     : "spring";
    std::string label =
        plan.pitch.starts > 1
            ? fmt::format("pass {} start {} depth {:.4f} {}", p.n, p.start + 1, p.depth, kind)
            : fmt::format("pass {} depth {:.4f} {}", p.n, p.depth, kind);
    prog.comment(label);
    // To the approach point: from the initial point fed or rapid as the CL had it, later back
    // parallel to the thread at rapid. Then the infeed along CUTANG, fed or rapid as the CL had it.
    if (plan.feed_approach && i == 0)
      prog.linear(lp(p.approach));
    else
      prog.rapid(lp(p.approach));
    if (plan.feed_approach)
      prog.linear(lp(p.from));
    else
      prog.rapid(lp(p.from));
    ThreadLead l = base;
    if (plan.starts_by_angle && plan.pitch.starts > 1) l.start_angle = p.start_angle;
    if (p.path.size() >= 2) {
      // A chain (threading.md section 11): one block per segment, modal, synchronized once (the
      // start angle on the first block only).
      for (size_t j = 1; j < p.path.size(); ++j) prog.thread(lp(p.path[j]), j == 1 ? l : base);
    } else {
      prog.thread(lp(p.to), l);
    }
    if (plan.pullout) {
      if (plan.pullout_linear) {
        prog.linear(lp(p.pullout_end));
      } else {
        ThreadLead pl = base;
        if (pl.lead_change != 0) {
          // The lead where the pull-out begins: K² grows by 2·ΔK per unit of travel.
          double k2 = pl.lead * pl.lead + 2 * pl.lead_change * dist(p.from, p.to);
          pl.lead = std::sqrt(std::max(0.0, k2));
          pl.tpi = 0;
        }
        prog.thread(lp(p.pullout_end), pl);
      }
    }
    prog.rapid(lp(p.clear));
  }
  prog.rapid(lp(plan.end_position));
  (void)ctx;
  return true;
}

std::unique_ptr<Emitter> make_emulation_emitter() {
  return std::make_unique<EmulationEmitter>("emulation");
}

std::unique_ptr<Emitter> make_loop_emitter(const LoopBlock* l) {
  if (l == nullptr) return std::make_unique<EmulationEmitter>("G33 loop");
  return l->emitter != nullptr ? l->emitter() : nullptr;
}

}  // namespace clpost

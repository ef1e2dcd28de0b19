#include "emitters/emulation_emitter.h"

#include <fmt/format.h>

namespace clpost {

namespace {
LathePoint lp(Vec2 v) {
  return LathePoint{v.x, v.z};
}
}  // namespace

bool EmulationEmitter::emit(const ThreadPlan& plan, NcProgram& prog, const EmitContext& ctx) {
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
    std::optional<double> angle;
    if (plan.starts_by_angle && plan.pitch.starts > 1) angle = p.start_angle;
    prog.thread(lp(p.to), plan.lead, angle);
    if (plan.pullout) {
      if (plan.pullout_linear)
        prog.linear(lp(p.pullout_end));
      else
        prog.thread(lp(p.pullout_end), plan.lead);
    }
    prog.rapid(lp(p.clear));
  }
  prog.rapid(lp(plan.end_position));
  (void)ctx;
  return true;
}

std::unique_ptr<Emitter> make_emitter(const Machine& m) {
  (void)m;  // every machine emulates until the control emitters land
  return std::make_unique<EmulationEmitter>();
}

}  // namespace clpost

// make_emitter: the machine's threading strategy with its fallback ("exact or fall back",
// controllers.md). The controls' cycle and loop emitters come from the machine's set of controls
// (machine/control.h).
#include <fmt/format.h>

#include "emitters/emitter.h"
#include "emitters/emulation_emitter.h"

namespace clpost {

std::string fallback_comment(const Unfit& first, std::string_view used) {
  return fmt::format("{} not used: {}. {} instead", first.name, first.reason, used);
}

std::string unfit_reasons(const std::vector<Unfit>& unfit) {
  std::vector<std::pair<std::string, std::string>> merged;  // names, reason
  for (const Unfit& u : unfit) {
    if (!merged.empty() && merged.back().second == u.reason) {
      merged.back().first += fmt::format(", {}", u.name);
    } else {
      merged.emplace_back(u.name, u.reason);
    }
  }
  std::string all;
  for (const auto& [names, reason] : merged)
    all += fmt::format("{}{} not used: {}", all.empty() ? "" : "; ", names, reason);
  return all;
}

bool unfit_error(const ThreadPlan& plan, const EmitContext& ctx, const Machine& m,
                 std::string_view emitter, std::string_view why) {
  ctx.diags.error(plan.loc, ctx.lines.text(plan.loc.line),
                  fmt::format("machine '{}': {} cannot cut this thread: {}", m.name, emitter, why));
  return false;
}

bool template_failed(const ThreadPlan& plan, const EmitContext& ctx, const Machine& m,
                     const TemplateWrite& w) {
  ctx.diags.error(plan.loc, ctx.lines.text(plan.loc.line), template_error(m, w));
  return false;
}

namespace {

// Tries each emitter in order; the first that fits writes the thread. When the first one does
// not fit, an NC comment says why (or, with `fallback: error`, an error diagnostic).
class ThreadOutput : public Emitter {
 public:
  // `for_chains`: tried first for a chained thread (threading.md section 11), or null.
  ThreadOutput(const Machine& m, std::vector<std::unique_ptr<Emitter>> chain,
               std::unique_ptr<Emitter> for_chains, bool error_fallback)
      : m_(m),
        chain_(std::move(chain)),
        for_chains_(std::move(for_chains)),
        error_fallback_(error_fallback) {}

  std::string_view name() const override { return chain_.front()->name(); }

  Fit fit(const ThreadPlan& plan, const Machine& m) const override {
    const std::vector<Emitter*> order = order_for(plan);
    Fit f;
    std::vector<Unfit> unfit;
    if (first_exact<ThreadPlan>(order, plan, m, error_fallback_, f, unfit) || error_fallback_)
      return f;
    return order.back()->fit(plan, m);
  }

  bool emit(const ThreadPlan& plan, NcProgram& prog, const EmitContext& ctx) override {
    const std::vector<Emitter*> order = order_for(plan);
    Fit f;
    std::vector<Unfit> unfit;
    if (Emitter* e = first_exact<ThreadPlan>(order, plan, m_, error_fallback_, f, unfit))
      return emit_after_fallback(*e, f, unfit, plan, prog, ctx);
    if (error_fallback_) {
      ctx.diags.error(plan.loc, ctx.lines.text(plan.loc.line),
                      fmt::format("machine '{}': {} would not cut the planned passes: {} "
                                  "(threading.fallback is 'error')",
                                  m_.name, unfit.back().name, unfit.back().reason));
      return false;
    }
    ctx.diags.error(plan.loc, ctx.lines.text(plan.loc.line),
                    fmt::format("machine '{}': no threading output can cut this thread: {}",
                                m_.name, unfit_reasons(unfit)));
    return false;
  }

 private:
  // The emitters tried for `plan`, in order.
  std::vector<Emitter*> order_for(const ThreadPlan& plan) const {
    std::vector<Emitter*> order;
    if (for_chains_ && plan.form == ThreadForm::kChain) order.push_back(for_chains_.get());
    for (const auto& e : chain_) order.push_back(e.get());
    return order;
  }

  const Machine& m_;
  std::vector<std::unique_ptr<Emitter>> chain_;
  std::unique_ptr<Emitter> for_chains_;
  bool error_fallback_;
};

}  // namespace

namespace {

std::vector<std::unique_ptr<Emitter>> emitter_chain(const Machine& m) {
  std::vector<std::unique_ptr<Emitter>> chain;
  auto add = [&](std::unique_ptr<Emitter> e) {
    if (!e) return false;
    for (const auto& have : chain)
      if (have->name() == e->name()) return true;
    chain.push_back(std::move(e));
    return true;
  };
  // The strategy's own output; a style this build does not have degrades to the next simpler.
  switch (m.thread_strategy) {
    case ThreadStrategy::kCycle:
      if (add(m.control ? m.control->cycle_emitter() : nullptr)) break;
      [[fallthrough]];
    case ThreadStrategy::kLoop:
      if (add(make_loop_emitter(m.thread_loop))) break;
      [[fallthrough]];
    case ThreadStrategy::kEmulate:
      add(make_emulation_emitter());
  }
  switch (m.thread_fallback) {
    case ThreadFallback::kLoop:
      add(make_loop_emitter(m.thread_loop));
      break;
    case ThreadFallback::kEmulate:
      add(make_emulation_emitter());
      break;
    case ThreadFallback::kError:
      return chain;
  }
  // Plain emulation cuts any plan: the last resort behind a loop that cannot say it (a G92
  // loop has no face thread).
  add(make_emulation_emitter());
  return chain;
}

}  // namespace

// The first chain cycle a control of the machine's set writes on it (CYCLE98 where the machine
// has its template), or null.
std::unique_ptr<Emitter> make_chain_emitter(const Machine& m) {
  for (const Control* c : m.controls)
    if (c->chain_emitter)
      if (std::unique_ptr<Emitter> e = c->chain_emitter(m)) return e;
  return nullptr;
}

std::unique_ptr<Emitter> make_emitter(const Machine& m) {
  // A machine with a chain cycle's template cuts chained threads with it where it is exact.
  std::unique_ptr<Emitter> for_chains = make_chain_emitter(m);
  return std::make_unique<ThreadOutput>(m, emitter_chain(m), std::move(for_chains),
                                        m.thread_fallback == ThreadFallback::kError);
}

std::string threading_summary(const Machine& m) {
  std::string s;
  for (const auto& e : emitter_chain(m))
    s += fmt::format("{}{}", s.empty() ? "" : ", else ", e->name());
  if (m.thread_fallback == ThreadFallback::kError && s != "emulation") s += ", else error";
  return s;
}

}  // namespace clpost

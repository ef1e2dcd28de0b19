#pragma once
// One interface for every threading output style: plain G1/G33 emulation, G33 / G92 loops, and
// the controls' cycles (CYCLE99, G76, G31 …). The machine file picks the implementation
// (threading.strategy / cycle / loop / fallback); make_emitter() wires the choice with its
// fallback (thread_output.cc).
#include <memory>
#include <string>
#include <string_view>
#include <vector>

#include "machine/machine.h"
#include "planner/planner.h"
#include "planner/thread_plan.h"
#include "reader/statement.h"
#include "support/diagnostics.h"
#include "writer/nc_program.h"

namespace clpost {

// What the planner needs to know of machine `m` (its threading defaults and words).
PlannerSettings planner_settings(const Machine& m);

// A plan point (CL frame: x a radius) as the lathe point NcProgram writes.
inline LathePoint lp(Vec2 v) {
  return LathePoint{v.x, v.z};
}

struct EmitContext {
  Diagnostics& diags;
  const SavedLines& lines;  // the thread's CL statement, for diagnostics
  double rpm = 0;           // spindle speed during the thread
  double feed = 0;          // feed in force (for linear pull-outs), output units
  FeedMode feed_mode = FeedMode::kPerMinute;
};

// Whether an output style cuts exactly a plan. The rule (controllers.md, "exact or fall
// back"): a cycle is written only when the passes the control will cut from the words we would
// write — its own law, its rounding — equal the plan's passes.
struct Fit {
  std::string mismatch;            // empty: exact; else why not, one line with the numbers
  std::vector<std::string> notes;  // accepted differences, written as NC comments before it
  bool exact() const { return mismatch.empty(); }
};

class Emitter {
 public:
  virtual ~Emitter() = default;
  // What the NC comments and diagnostics call it: "CYCLE99", "G76", "G33 loop", ...
  virtual std::string_view name() const = 0;
  // Would this output cut `plan` exactly on machine `m`? Cycle emitters expand the words they
  // would write with the control's law and compare (cut_pass.h). Loops and emulation cut every
  // planned pass as written, so they fit unless the plan needs something they cannot say.
  virtual Fit fit(const ThreadPlan& plan, const Machine& m) const = 0;
  // Writes a multi-pass thread that fits. Returns false (with a diagnostic) when it cannot.
  virtual bool emit(const ThreadPlan& plan, NcProgram& prog, const EmitContext& ctx) = 0;
};

// For emit() handed a plan that does not fit (make_emitter's chain asks fit() first, so this is a
// defence): the error "machine 'm': <emitter> cannot cut this thread: <why>" at the thread's
// statement. Returns false, for `return unfit_error(...)`.
bool unfit_error(const ThreadPlan& plan, const EmitContext& ctx, const Machine& m,
                 std::string_view emitter, std::string_view why);

// For a template that cannot be written (template_error(): the machine and the template) at
// the thread's statement. Returns false, for `return template_failed(...)`.
bool template_failed(const ThreadPlan& plan, const EmitContext& ctx, const Machine& m,
                     const TemplateWrite& w);

// The thread output for machine `m`: its strategy's emitter, falling back as the machine says
// (an NC comment names the reason), or an error diagnostic with `fallback: error`.
std::unique_ptr<Emitter> make_emitter(const Machine& m);
// What make_emitter(m) tries, in order: "CYCLE99, else G33 loop" (for `clpost machines`).
std::string threading_summary(const Machine& m);

// The emitter of one cycle / loop style (nullptr for ThreadCycle::kNone), and the cycle that
// cuts chained threads on machine `m` (nullptr when it has none): the registry's
// (controls/registry_output.cc).
std::unique_ptr<Emitter> make_cycle_emitter(ThreadCycle c);
std::unique_ptr<Emitter> make_loop_emitter(ThreadLoop l);
std::unique_ptr<Emitter> make_chain_emitter(const Machine& m);
std::unique_ptr<Emitter> make_emulation_emitter();

}  // namespace clpost

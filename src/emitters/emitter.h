#pragma once
// The threading outputs: plain G1/G33 emulation, G33 / G92 loops, and the controls' cycles
// (each control's folder, src/controls/), on the one "exact or fall back" interface
// (cycle_output.h). The machine file picks the implementation
// (threading.strategy / cycle / loop / fallback); make_emitter() wires the choice with its
// fallback (thread_output.cc).
#include <memory>
#include <string>
#include <string_view>
#include <vector>

#include "emitters/cycle_output.h"
#include "machine/machine.h"
#include "planner/planner.h"
#include "planner/thread_plan.h"
#include "reader/statement.h"
#include "support/diagnostics.h"
#include "writer/nc_program.h"

namespace clpost {

// A plan point (CL frame: x a radius) as the lathe point NcProgram writes.
inline LathePoint lp(Vec2 v) {
  return LathePoint{v.x, v.z};
}

// The thread outputs: CycleOutput<ThreadPlan> (cycle_output.h). Cycle emitters expand the
// words they would write with the control's law and compare (laws/cut_pass.h); loops and
// emulation cut every planned pass as written, so they fit unless the plan needs something they
// cannot say.
using Emitter = CycleOutput<ThreadPlan>;

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

// The emitter of loop block `l` (threading.loop, a control's: machine/control.h), or of the G33
// loop for null; a machine's cycle is its control's.
std::unique_ptr<Emitter> make_loop_emitter(const LoopBlock* l);
std::unique_ptr<Emitter> make_emulation_emitter();

}  // namespace clpost

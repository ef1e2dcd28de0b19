#pragma once
// SINUMERIK CYCLE99: a pass plan as one cycle call, written only when the cuts the control
// makes from the words (cycle99_law.h, after our output rounding) equal the plan's passes.
// The call's layout is the machine's `cycle99` template.
//
// APP, the run-in, lies before SPL: the cuts begin APP before it. A number for threading.run_in
// is taken from the start of the CL's thread (SPL lies that far into it, so the cuts still start
// where the CL's do); with `auto` the planner begins every pass the run-in δ1 before the CL's
// start (planner/run_in.h), SPL stays the CL's start and APP is δ1. ROP stays the CL's run-out
// (CHAMFR with a negative length): in the law it is a 45-degree cut out of the thread, not an
// overtravel, so the run-out δ2 cannot be written there without cutting a chamfer the CL does
// not ask for.
#include <string>
#include <vector>

#include "controls/sinumerik/cycle99_law.h"
#include "emitters/emitter.h"
#include "machine/template_values.h"

namespace clpost {

// The CYCLE99 words for a plan on machine `m`, as they will be written and read back, with why
// the control would not cut the plan (empty: it cuts it exactly) and the accepted differences.
struct Cycle99Call {
  Cycle99Words words;
  std::string mismatch;
  std::vector<std::string> notes;
};
Cycle99Call cycle99_call(const ThreadPlan& plan, const Machine& m);

// Where a SINUMERIK cycle call starts and the control returns: on the clear line above the
// thread start (the plan's end position), reached as the CL approaches (fed or rapid). Returns
// that point.
LathePoint go_to_cycle_start(const ThreadPlan& plan, NcProgram& prog);

// The words CYCLE99 and CYCLE98 share (APP, ROP, TDEP, FAL, IANG, NSP, NRC, NID), from `w`
// (Cycle99Words or Cycle98Words) into `a` (a fill of either template), in the cycles' named
// formats.
template <const TemplateSpec& T, typename Words>
void fill_shared_cycle_words(TemplateFill<T>& a, const Words& w, const NcProgram& prog) {
  auto num = [&](std::string_view f, double v) { return prog.num(f, v); };
  a.template text<"app">(num("cycle99_depth", w.app));
  a.template text<"rop">(num("cycle99_depth", w.rop));
  a.template text<"tdep">(num("cycle99_depth", w.tdep));
  a.template text<"fal">(num("cycle99_depth", w.fal));
  a.template text<"iang">(num("cycle99_angle", w.iang));
  a.template text<"nsp">(num("cycle99_angle", w.nsp));
  a.template text<"nrc">(std::to_string(w.nrc));
  a.template text<"nid">(std::to_string(w.nid));
}

class Cycle99Emitter : public Emitter {
 public:
  std::string_view name() const override { return "CYCLE99"; }
  Fit fit(const ThreadPlan& plan, const Machine& m) const override;
  bool emit(const ThreadPlan& plan, NcProgram& prog, const EmitContext& ctx) override;
};

}  // namespace clpost

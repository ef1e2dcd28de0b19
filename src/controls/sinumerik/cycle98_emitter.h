#pragma once
// SINUMERIK CYCLE98: a chained thread (threading.md section 11) of 1 to 3 segments as one cycle
// call, written only when the cuts the control makes from the words (cycle98_law.h, after our
// output rounding) equal the plan's passes. The call's layout is the machine's `cycle98`
// template; a machine without one cuts chains with its other outputs. APP is the run-in clpost
// adds before the first point with threading.run_in `auto` (as CYCLE99's), else 0; ROP the CL's
// run-out.
#include <string>

#include "controls/sinumerik/cycle98_law.h"
#include "emitters/emitter.h"

namespace clpost {

// The CYCLE98 words for a chained plan on machine `m`, as they will be written and read back,
// with why the control would not cut the plan (empty: it cuts it exactly).
struct Cycle98Call {
  Cycle98Words words;
  std::string mismatch;
};
Cycle98Call cycle98_call(const ThreadPlan& plan, const Machine& m);

class Cycle98Emitter : public Emitter {
 public:
  std::string_view name() const override { return "CYCLE98"; }
  Fit fit(const ThreadPlan& plan, const Machine& m) const override;
  bool emit(const ThreadPlan& plan, NcProgram& prog, const EmitContext& ctx) override;
};

}  // namespace clpost

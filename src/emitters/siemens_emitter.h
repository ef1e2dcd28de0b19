#pragma once
// SINUMERIK CYCLE99: a pass plan as one cycle call, written only when the cuts the control
// makes from the words (siemens_law.h, after our output rounding) equal the plan's passes.
// The call's layout is the machine's `cycle99` template.
#include <string>
#include <vector>

#include "emitters/emitter.h"
#include "emitters/siemens_law.h"

namespace clpost {

// The CYCLE99 words for a plan on machine `m`, as they will be written and read back, with why
// the control would not cut the plan (empty: it cuts it exactly) and the accepted differences.
struct Cycle99Call {
  Cycle99Words words;
  std::string mismatch;
  std::vector<std::string> notes;
};
Cycle99Call cycle99_call(const ThreadPlan& plan, const Machine& m);

class Cycle99Emitter : public Emitter {
 public:
  std::string_view name() const override { return "CYCLE99"; }
  Fit fit(const ThreadPlan& plan, const Machine& m) const override;
  bool emit(const ThreadPlan& plan, NcProgram& prog, const EmitContext& ctx) override;
};

}  // namespace clpost

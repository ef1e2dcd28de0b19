#pragma once
// G177, the toy control's thread cycle (toy_law.h), one block per pass: written only when the
// cuts the law makes from the words as written equal the plan's passes ("exact or fall back").
#include "emitters/emitter.h"

namespace clpost::toy {

class G177Emitter : public Emitter {
 public:
  std::string_view name() const override { return "G177"; }
  Fit fit(const ThreadPlan& plan, const Machine& m) const override;
  bool emit(const ThreadPlan& plan, NcProgram& prog, const EmitContext& ctx) override;
};

}  // namespace clpost::toy

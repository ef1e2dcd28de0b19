#pragma once
// The toy control's outputs, each written only when the cuts its law makes from the words as
// written equal the plan's passes ("exact or fall back"): G177, its cycle, one block per pass
// (template toy_g177), and G178, its loop block (template toy_g178). Both end with the toy's
// code toy_cycle_end (M178) when the machine gives it.
#include "emitters/emitter.h"

namespace clpost::toy {

class G177Emitter : public Emitter {
 public:
  std::string_view name() const override { return "G177"; }
  Fit fit(const ThreadPlan& plan, const Machine& m) const override;
  bool emit(const ThreadPlan& plan, NcProgram& prog, const EmitContext& ctx) override;
};

class G178Emitter : public Emitter {
 public:
  std::string_view name() const override { return "G178"; }
  Fit fit(const ThreadPlan& plan, const Machine& m) const override;
  bool emit(const ThreadPlan& plan, NcProgram& prog, const EmitContext& ctx) override;
};

}  // namespace clpost::toy

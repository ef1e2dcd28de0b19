#pragma once
// Plain emulation: every pass as explicit blocks (approach, infeed along CUTANG, synchronized
// cut, pull-out, clearing move, return), for controls without a usable threading cycle.
#include "emitters/emitter.h"

namespace clpost {

class EmulationEmitter : public Emitter {
 public:
  std::string_view name() const override { return "emulate"; }
  bool emit(const ThreadPlan& plan, NcProgram& prog, const EmitContext& ctx) override;
};

}  // namespace clpost

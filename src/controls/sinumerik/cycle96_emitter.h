#pragma once
// SINUMERIK CYCLE96(DIATH, AXSA, FORM): the DIN 76-1 thread undercut as the control cuts it
// (seed 001_…), on a machine with the cycle96 template. It refuses what the control stops on
// with an alarm: a final diameter below 3 mm, and no active tool offset.
#include "emitters/undercut_output.h"

namespace clpost {

class Cycle96Emitter : public CycleOutput<Undercut> {
 public:
  std::string_view name() const override { return "CYCLE96"; }
  Fit fit(const Undercut& u, const Machine& m) const override;
  bool emit(const Undercut& u, NcProgram& prog, const EmitContext& ctx) override;
};

}  // namespace clpost

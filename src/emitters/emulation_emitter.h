#pragma once
// Every pass as explicit blocks (approach, infeed along CUTANG, synchronized cut, pull-out,
// clearing move, return). Two names for one output: "emulation" on controls without a usable
// threading cycle (generic-lathe), and the "G33 loop" of controls whose single-pass thread
// block is G33 with their own lead, start-angle (SF=, Q) and threads-per-inch (E) words.
#include "emitters/emitter.h"

namespace clpost {

class EmulationEmitter : public Emitter {
 public:
  explicit EmulationEmitter(std::string_view name = "emulation") : name_(name) {}
  std::string_view name() const override { return name_; }
  Fit fit(const ThreadPlan& plan, const Machine& m) const override;
  bool emit(const ThreadPlan& plan, NcProgram& prog, const EmitContext& ctx) override;

 private:
  std::string_view name_;
};

// The lead words of a plan's synchronized moves (lead, threads per inch, lead change).
ThreadLead thread_lead(const ThreadPlan& plan);

}  // namespace clpost

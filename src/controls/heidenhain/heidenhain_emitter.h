#pragma once
// HEIDENHAIN DIN G31 (threading.cycle: heidenhain_g31): the thread as G31 with its contour (the
// crest / bore line P1->P2 as a G0 and a G1 block) and G80, when the cuts the law in
// heidenhain_law.h gives equal the plan; else a mismatch so that the machine's fallback is used.
//
// Mapping (decisions; the G31 geometry is unverified, see heidenhain_law.h):
// - F pitch, U the deepest pass, IC the passes up to the first at U, Q the passes at U after it;
// - OPTION 1 -> V0 with H toward the cutting direction (codes g31_h_minus / g31_h_plus),
//   OPTION 2 -> V0 H alternating (g31_h_alternating), OPTION 3 -> V1 H toward the cutting
//   direction, OPTION 4 -> V1 H alternating; A = TLANGL/2; OPTION 0 has no G31 law;
// - D1 C0 (multi-start is not mapped), BD0/1 from the side, K0;
// - B = threading.run_in taken from the start of the CL's thread (the contour starts B after P1),
//   P0; with run_in `auto` the contour is the thread less its run-out: B the run-in δ1 clpost
//   adds before P1, P the run-out δ2 (planner/run_in.h), the contour ending P before P2;
// - not mapped: OPTION 0, a finish allowance (no G31 word), pull-outs, an angled CUTANG,
//   several starts, a variable lead.
#include <optional>

#include "controls/heidenhain/heidenhain_law.h"
#include "emitters/emitter.h"

namespace clpost {

class HeidenhainG31Emitter : public Emitter {
 public:
  std::string_view name() const override { return "G31"; }
  Fit fit(const ThreadPlan& plan, const Machine& m) const override;
  bool emit(const ThreadPlan& plan, NcProgram& prog, const EmitContext& ctx) override;

  // The words for `plan` on `m` (as the control reads them), or the reason in `why`.
  static std::optional<HeidenhainG31> words_for(const ThreadPlan& plan, const Machine& m,
                                                std::string& why);
};

}  // namespace clpost

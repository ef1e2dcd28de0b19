#pragma once
// Haas one-block G76 (threading.cycle: haas_g76), written only when the cuts the control makes
// from the block and its settings (haas_law.h; settings 86, 99, 95/96 are the machine keys
// threading.haas_finish_allowance, haas_min_cut, haas_chamfer and threading.chamfer_angle)
// equal the plan's passes.
//
// Mapping: OPTION 1 (constant cross-section, d·√n, one flank) -> P1 "constant cutting amount,
// single edge"; OPTION 3 (constant depth, one flank) -> P3 "constant depth, single edge". D = the
// first pass rounded up, K = the deepest pass, A = TLANGL (0-120, whole degrees), X/Z the end at
// full depth, I the taper (radius at the start Z minus at the end). Several starts: one G76 per
// start with Q = the start angle (0.001°), the control cutting start by start (noted).
// Not used: OPTION 0 (no such law), OPTION 2 and 4 (the control's alternating pattern is not
// documented in our sources), a FINCUT allowance other than setting 86, spring passes (the cycle
// cuts one pass at K), a pull-out other than the settings' chamfer, an angled CUTANG, face
// threads, a variable lead.
#include "controls/haas/haas_law.h"
#include "emitters/emitter.h"

namespace clpost {

class HaasG76Emitter : public Emitter {
 public:
  std::string_view name() const override { return "G76"; }
  Fit fit(const ThreadPlan& plan, const Machine& m) const override;
  bool emit(const ThreadPlan& plan, NcProgram& prog, const EmitContext& ctx) override;
};

}  // namespace clpost

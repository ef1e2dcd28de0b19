#pragma once
// LinuxCNC G76 (threading.cycle: linuxcnc_g76): one G76 block per thread when the passes the
// interpreter will cut from it (linuxcnc_law.h) equal the plan, else a mismatch naming the
// difference so that the machine's fallback is used.
//
// Mapping (plan -> words; lathe in G7 diameter mode, so I, J, K are written as diameters):
// - the tool is first put on the clear line above the thread start: X = the drive line, Z = P1;
// - I = crest (P1) - drive line; J = depth of the first pass (rounded up, so that J·c^(1/R)
//   reaches K after the planned count); K = the deepest pass; H = passes at K - 1;
//   R = 2 (OPTION 1, 2: J·√n) or 1 (OPTION 3, 4: n·J), whichever the plan follows;
// - Q = the flank angle the plan shifts its passes by (atan(shift / depth): TLANGL/2 for
//   OPTION 1 and 3, the CUTANG offset for an angled infeed, 0 radial);
// - a threaded pull-out that rises by the thread depth maps to the exit taper E<length> L2
//   (Z is then where the pull-out ends);
// - what G76 cannot say: taper and face threads, several starts, alternating flanks, a finish
//   allowance or law its J·n^(1/R) does not give, a single depth (the control needs J < K),
//   other pull-outs, a variable lead.
#include <optional>

#include "controls/linuxcnc/linuxcnc_law.h"
#include "emitters/emitter.h"

namespace clpost {

// Everything the G76 output of one plan needs: the words and where the tool must be first.
struct LinuxcncG76Block {
  LinuxcncG76 words;  // as the control reads them
  Vec2 start;         // drive line X (radius) and start Z, as the control reads them
};

class LinuxcncG76Emitter : public Emitter {
 public:
  std::string_view name() const override { return "G76"; }
  Fit fit(const ThreadPlan& plan, const Machine& m) const override;
  bool emit(const ThreadPlan& plan, NcProgram& prog, const EmitContext& ctx) override;

  // The block for `plan` on `m`, or a mismatch in `why` when G76 cannot say the plan at all
  // (before any expansion).
  static std::optional<LinuxcncG76Block> words_for(const ThreadPlan& plan, const Machine& m,
                                                   std::string& why);
};

}  // namespace clpost

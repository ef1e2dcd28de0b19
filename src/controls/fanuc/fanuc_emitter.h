#pragma once
// Fanuc two-block G76 (threading.cycle: fanuc_g76) and the G92 loop (threading.loop: g92) used by
// Fanuc and Haas machines. Both are written only when the cuts the control makes from the words
// (fanuc_law.h) equal the plan's passes; otherwise fit() names the difference and the machine's
// fallback is used.
//
// G76 mapping (plan -> words):
// - the tool first goes to A: the plan's clear line at the thread start Z (P1); the control
//   returns there after every pass;
// - k = the deepest pass (radial), m = the passes at k, d = k − the deepest pass below k
//   (rounded up), so roughing stops exactly where the plan's last pass below k is; a plan whose
//   passes are all at k has d = 0 and m = passes − 1; a single pass needs one extra spring pass
//   (threading.extra_spring_passes);
// - Δd = the first pass's depth rounded up to the least increment (so Δd·√c reaches the
//   roughing depth after the planned count c), Δdmin = the smallest roughing increment rounded
//   down (it never raises a planned pass);
// - a = TLANGL (80, 60, 55, 30, 29); r = a 45° chamfer pull-out (threading.chamfer_angle) of
//   whole tenths of the lead, with Z where the chamfer ends;
// - X/Z the end at full depth, R the taper (radius at A's Z minus at the end).
// What G76 cannot say: OPTION 0, 3, 4 (other laws), OPTION 2 (alternating flanks), an angled
// CUTANG, other tool angles, several starts (no start-angle word: G92 with Q cuts them), other
// pull-outs, face threads, a variable lead.
//
// G92: one block per pass from the start point S on the clear line at the pass's start Z (a flank
// shift is a G0 Z before it); consecutive blocks without a move between give only what changes.
// Plans with a pull-out (G92's chamfer is a control parameter) and face threads do not fit.
#include "controls/fanuc/fanuc_law.h"
#include "emitters/emitter.h"
#include "laws/written_value.h"

namespace clpost {

class FanucG76Emitter : public Emitter {
 public:
  std::string_view name() const override { return "G76"; }
  Fit fit(const ThreadPlan& plan, const Machine& m) const override;
  bool emit(const ThreadPlan& plan, NcProgram& prog, const EmitContext& ctx) override;
};

class G92Emitter : public Emitter {
 public:
  std::string_view name() const override { return "G92"; }
  Fit fit(const ThreadPlan& plan, const Machine& m) const override;
  bool emit(const ThreadPlan& plan, NcProgram& prog, const EmitContext& ctx) override;
};

namespace g76 {

// A single-start (or one start's) turn plan read as a flank cycle.
struct CyclePlan {
  double outward = 1;           // +1 external, -1 internal (the crest is outward of the root)
  double slope = 0;             // dX/dZ (radius) of the thread line
  double cos_t = 1;             // cos of the thread line's angle to Z
  double flank = 0;             // the plan's flank infeed angle (degrees) or -1: not one angle
  Vec2 t;                       // unit cutting direction
  std::vector<double> heights;  // radial depth of every pass of the start, in cutting order
  std::vector<double> shifts;   // their flank shifts
  std::vector<Cut> cuts;        // the plan's cuts of the start
  double chamfer = 0;           // pull-out length along Z (0: none)
  double chamfer_angle = 0;     // degrees to the thread line
  Vec2 start;                   // A: the clear line at P1's Z
  Vec2 end;                     // full-depth end: X (radius), Z where the deepest pass ends
};

// Reads `plan` (start `start` only) as a flank cycle, or returns a one-line reason it is not one
// (a face thread, an angled CUTANG, a pull-out that is not a chamfer along Z, ...).
// `cycle` names the output in the reason ("G76").
std::string read_cycle_plan(const ThreadPlan& plan, int start, std::string_view cycle,
                            CyclePlan& out);

// The plan's cuts `cp.cuts` as a fixed-end cycle cuts them: every pass's end moved along the
// thread to where the deepest pass ends. Returns the largest move.
double move_ends_to_deepest(const CyclePlan& cp, std::vector<Cut>& cuts);

// How many of the last `heights` are at `h` (full depth), within 1e-9.
size_t passes_at(const std::vector<double>& heights, double h);

// Why G76's `cuts` are not the plan's `want` (empty: they are). A fixed-end control (not
// threading.cycle_shifted_end) ends every pass where the deepest ends: cuts that equal `moved`
// (the plan so moved, by up to `most`) are accepted with a note in `notes` when
// threading.accept_pass_end is on; `z` is the Z word the passes end at, as read.
std::string pass_end_mismatch(const std::vector<Cut>& cuts, const std::vector<Cut>& want,
                              const std::vector<Cut>& moved, double most, double z,
                              const Machine& m, const CutCompareOptions& opt,
                              std::vector<std::string>& notes);

std::string describe_pullout(const ThreadPlan& plan);

// Whether the tool is at `p` (as written) after a cycle.
bool at_end(const NcProgram& prog, Vec2 p);

}  // namespace g76

}  // namespace clpost

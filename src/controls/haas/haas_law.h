#pragma once
// What a Haas lathe cuts for its one-block G76:
// `G76 X Z [I<taper radius>] K<height> D<first depth> A<tool angle> P<1|2|3|4> [Q<start>] F<L>`.
// Source: ../shared/reference/controllers.md ("Haas lathe"); the depth law and the roles of the
// settings are from secondary sources *(unverified)*:
// - P1 constant cutting amount, single edge: cumulative depth D·√n (the same law as Fanuc's Δd);
//   P2 the same, alternating edges; P3 constant depth, single edge: n·D; P4 the same,
//   alternating edges;
// - an increment below setting 99 (minimum cut) is raised to it;
// - roughing stops at K − setting 86 (finish allowance); when setting 86 is above 0 one pass at
//   K follows; the cycle cuts no spring passes;
// - setting 95 (chamfer size, in leads) and 96 (chamfer angle) give the run-out at the end;
// - alternating edges (P2, P4): odd passes go straight in, even ones are shifted by
//   depth·tan(A/2) as the plan's OPTION 2/4 are — a guess, which is why the emitter does not
//   use P2/P4 (haas_emitter.cc).
// The pass geometry (start point, pass ends, chamfer, taper) is expand_flank_cycle's
// (fanuc_law.h).
#include <optional>
#include <vector>

#include "controls/fanuc/fanuc_law.h"

namespace clpost {

// The control settings G76 reads besides its words (machine keys threading.haas_*), in the
// program's units.
struct HaasSettings {
  double finish_allowance = 0;  // setting 86
  double min_cut = 0;           // setting 99
  double chamfer = 0;           // setting 95, in leads (0: none)
  double chamfer_angle = 45;    // setting 96, degrees
};

struct HaasG76Words {
  double x = 0;                       // X word (a diameter when the machine programs diameters)
  double z = 0;                       // Z word
  double taper = 0;                   // I: radius at the start minus radius at the end
  double height = 0;                  // K
  double first_cut = 0;               // D
  int tool_angle = 60;                // A, 0–120
  int mode = 1;                       // P 1–4
  std::optional<double> start_angle;  // Q, degrees
  double lead = 0;                    // F
};

// Radial depths of every pass (see above). Empty when the words cannot end.
std::vector<double> haas_g76_depths(const HaasG76Words& w, const HaasSettings& s);

// The cuts of one G76 block started with the tool at `start` (lathe frame, radius); `starts`
// turns the start angle Q into a start index.
std::vector<Cut> expand_haas_g76(const HaasG76Words& w, Vec2 start, const HaasSettings& s,
                                 const CycleLaw& law, int starts = 1);

// The control settings in the plan's units (the machine keys are in the machine's units).
HaasSettings haas_settings(const Machine& m, LengthUnit plan_units);

}  // namespace clpost

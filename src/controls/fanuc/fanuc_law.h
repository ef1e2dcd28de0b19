#pragma once
// What a Fanuc-style lathe control cuts for its threading cycles: the words of the two-block
// G76, of the one-pass G92 cycle and of the Haas one-block G76 (haas_law.h) as the control reads
// them (numbers after the rounding of the output format, lengths in output units, X as written),
// and the law turning those words into synchronized cuts. Written for the emitters' exactness
// check and for `clpost verify`, which parses the words back from an NC program.
//
// Sources: ../shared/reference/controllers.md ("Fanuc (system A lathe)", "Haas lathe"). The
// G76 law there comes from secondary sources *(unverified)*: cumulative depth Δd·√n, an
// increment below Δdmin raised to Δdmin, roughing stops at k − d, then m passes at k, flank
// infeed at a/2. Where the reference is silent these functions decide, and docs/machines.md
// says so:
// - the cycle starts from the tool position A; pass n starts at A's Z moved by h_n·tan(a/2) in
//   the cutting direction (the infeed runs along the flank from A);
// - every pass ends at the Z word (`shifted_end` false, the Fanuc figure), or the whole pass is
//   shifted and only the deepest ends at Z (`shifted_end` true, as LinuxCNC's G76) — machine
//   key threading.cycle_pass_end;
// - the chamfer (G76 r, Haas settings 95/96) is a run-out that ends at the Z word: the thread
//   leaves its line `chamfer` before Z and reaches Z `chamfer·tan(angle)` further out;
// - depths k, Δd, d are radial (along X); a cut's `depth` is reported at right angles to the
//   thread line (for a taper, radial × cos of the taper angle).
#include <optional>
#include <vector>

#include "laws/cut_pass.h"

namespace clpost {

// The geometry shared by the G76 cycles, in the lathe frame (x a radius).
struct FlankCycle {
  Vec2 start;                 // A: where the tool is when the cycle starts; passes return to it
  Vec2 end;                   // X/Z words: end of the thread at full depth
  double taper = 0;           // radius at A's Z minus radius at the end Z (Fanuc R, Haas I)
  double height = 0;          // thread height k (radial)
  double flank = 0;           // infeed angle from the radial direction, degrees (a/2)
  double chamfer = 0;         // run-out length along Z, ending at the Z word (0: none)
  double chamfer_angle = 45;  // its angle to the thread line, degrees
  bool shifted_end = false;   // see above
};

// The cuts of a flank cycle whose passes reach the radial depths `heights` (in cutting order,
// heights[i] ≤ height). External when the end X lies toward the axis from A, else internal.
// `start` is the start index every cut gets.
std::vector<Cut> expand_flank_cycle(const FlankCycle& g, const std::vector<double>& heights,
                                    int start = 0);

// The roughing depths of a G76-style cycle: first_cut·√n (or first_cut·n with `sqrt_law`
// false), each increment at least `min_cut`, the pass that reaches `rough_to` cut at it and the
// last. Empty when the words can never get there (no first cut and no minimum, or > 1000 passes).
std::vector<double> g76_rough_depths(double first_cut, double min_cut, double rough_to,
                                     bool sqrt_law);

// Fanuc G76, two blocks: `G76 P<m><r><a> Q<Δdmin> R<d>` and `G76 X Z R<i> P<k> Q<Δd> F<L>`.
struct FanucG76Words {
  int finish_passes = 1;  // m, 01–99: passes at k after roughing
  int chamfer = 0;        // r, 00–99: chamfer length in tenths of the lead
  int tool_angle = 60;    // a: 80, 60, 55, 30, 29 or 0
  double min_cut = 0;     // Δdmin (length; P/Q words are written in the least increment)
  double allowance = 0;   // d, finishing allowance
  double x = 0;           // X word (a diameter when the machine programs diameters)
  double z = 0;           // Z word
  double taper = 0;       // i: radius at the start minus radius at the end
  double height = 0;      // k
  double first_cut = 0;   // Δd
  double lead = 0;        // F
};

// Whether `a` is a tool angle G76 accepts.
bool fanuc_g76_tool_angle_ok(int a);

// The radial depths of every pass: Δd·√n (n = 1, 2, …), an increment below Δdmin raised to
// Δdmin, the pass reaching k − d cut at k − d and ending the roughing; then m passes at k.
// Empty when the words cannot end (Δd and Δdmin both 0, or over 1000 passes).
std::vector<double> fanuc_g76_depths(const FanucG76Words& w);

struct CycleLaw {
  bool diameter = true;       // X words are diameters
  bool shifted_end = false;   // threading.cycle_pass_end: shifted
  double chamfer_angle = 45;  // the control's chamfer angle (parameter / setting)
};

// The cuts of one G76 cycle started with the tool at `start` (lathe frame, radius).
std::vector<Cut> expand_fanuc_g76(const FanucG76Words& w, Vec2 start, const CycleLaw& law);

// Fanuc / Haas G92: one pass per block, `G92 X Z [R] F [Q]` from the start point S (where the
// tool is): rapid in along X, thread to (X, Z) with the taper R (radius, start − end) so that
// the cut starts at S's Z, rapid out to S's X, rapid back to S. Its own chamfer is a control
// parameter, not a block word; clpost writes G92 only for plans without a pull-out.
struct G92Words {
  double x = 0;  // X word (diameter when the machine programs diameters)
  double z = 0;
  double taper = 0;                   // R
  double lead = 0;                    // F
  std::optional<double> start_angle;  // Q, degrees
};

struct G92Pass {
  Vec2 start;  // S: the tool position when the block is read (lathe frame, radius)
  G92Words words;
};

// The cuts of a run of G92 blocks. `p1`, `p2`: the thread line (outer surface) the cut depths are
// measured from; `starts`: the thread's start count (a start angle Q gives start index
// round(Q·starts/360)).
std::vector<Cut> expand_g92(const std::vector<G92Pass>& passes, bool diameter, Vec2 p1, Vec2 p2,
                            int starts = 1);

}  // namespace clpost

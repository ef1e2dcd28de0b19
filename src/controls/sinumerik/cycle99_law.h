#pragma once
// SINUMERIK CYCLE99 (thread cutting) as the control reads it, and the synchronized cuts it makes
// from those words. Source: the 840D cycles manual, section 9.5.8 "Thread cutting - CYCLE99"
// (shared/reference/seeds/000_…), summarised in shared/reference/controllers.md. The manual gives
// the parameters and the principle of the infeed; the geometry below fills in what it leaves
// open, each point marked (unverified):
//
//  - The thread line runs from (DM1/2, SPL) to (DM2/2, FPL); its direction t is the cutting
//    direction. The infeed axis is X (PSYS 0 longitudinal, 20 taper) toward the axis for the
//    external variants (VARI 300101, 300103) and away from it for the internal ones (300102,
//    300104); Z toward -Z for a face thread (PSYS 10) (unverified).
//  - TDEP and FAL are paraxial, along the infeed axis ("the finishing allowance acts
//    paraxially"). Roughing: TDEP - FAL in NRC cuts, cumulative (TDEP-FAL)*i/NRC for constant
//    infeed (300101/300102) and (TDEP-FAL)*sqrt(i/NRC) for constant cross-section
//    (300103/300104) (unverified: controllers.md). Then one cut at TDEP when FAL > 0, then NID
//    idle passes at TDEP (unverified: with FAL = 0 there is no separate finishing cut).
//  - IANG: every cut is shifted along t by d*tan(IANG), d its depth at right angles to the thread
//    line; IANG > 0 (the rear flank) shifts it in the cutting direction, IANG < 0 (front flank)
//    against it (unverified sign). The cut at full depth TDEP ends ROP before FPL; every other
//    cut is the same line moved by its own depth and shift (so no cut runs past the full-depth
//    one).
//  - APP: the cuts begin APP before SPL along t. ROP: the cut ends ROP before its end and runs
//    out at 45 degrees over ROP (ROP along t and ROP out of the thread), so the full-depth
//    cut's run-out ends at FPL (unverified angle).
//  - NUMTH starts (0 = one) are cut one after the other, every cut of start 1 first; start k is
//    the same path at spindle angle NSP + k*360/NUMTH.
// `clpost verify` parses these words back from an NC program and calls expand_cycle99.
#include <string>
#include <vector>

#include "laws/cut_pass.h"

namespace clpost {

// The words of one CYCLE99 call, as the control reads them (after our output rounding).
// Lengths in program units; DM1/DM2 are diameters; IANG and NSP in degrees.
struct Cycle99Words {
  double spl = 0;   // SPL: thread start in the longitudinal axis
  double dm1 = 0;   // DM1: diameter at SPL (internal: the tap-hole diameter)
  double fpl = 0;   // FPL: thread end in the longitudinal axis
  double dm2 = 0;   // DM2: diameter at FPL
  double app = 0;   // APP: run-in
  double rop = 0;   // ROP: run-out, ending at FPL
  double tdep = 0;  // TDEP: thread depth
  double fal = 0;   // FAL: finishing allowance
  double iang = 0;  // IANG: infeed angle (> 0 rear flank, < 0 front flank, 0 radial)
  double nsp = 0;   // NSP: start angle of the first start
  int nrc = 1;      // NRC: roughing cuts
  int nid = 0;      // NID: idle passes
  double pit = 0;   // PIT: lead, unit PITA
  int vari = 300101;
  int numth = 0;   // NUMTH: starts (0 = single)
  double vrt = 0;  // _VRT: retraction above the initial diameter (0 = 1 mm)
  int pita = 1;    // PITA: 1 lead per revolution, 2 threads per inch
  int psys = 0;    // PSYS: 0 longitudinal, 10 face, 20 taper
};

// VARI values (seed table).
constexpr int kVariExternalConstantInfeed = 300101;
constexpr int kVariInternalConstantInfeed = 300102;
constexpr int kVariExternalConstantSection = 300103;
constexpr int kVariInternalConstantSection = 300104;

struct Cycle99Expansion {
  std::vector<Cut> cuts;  // in the control's cutting order (start by start)
  std::string alarm;      // not empty: the control refuses the call (no cuts)
};

// The cuts the control makes from `w` (CL frame: x a radius, z axial; program units).
Cycle99Expansion expand_cycle99(const Cycle99Words& w);

// The lead the control cuts, in program units per revolution (`inch`: an inch program), from PIT
// and PITA; 0 for a PITA it does not know.
double cycle99_lead(const Cycle99Words& w, bool inch);

}  // namespace clpost

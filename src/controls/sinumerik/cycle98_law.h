#pragma once
// SINUMERIK CYCLE98 (chained thread, up to three segments) as the control reads it, and the
// synchronized cuts clpost takes it to make. Source: the 840D cycles manual (seed 000_…) gives
// the parameters; shared/reference/controllers.md decodes its example call word by word. The
// manual gives the principle of the infeed only, so the geometry below is clpost's reading,
// the same law as CYCLE99's (cycle99_law.h) on a contour, every point (unverified):
//
//  - The contour runs through (DM1/2, PO1), (DM2/2, PO2), (DM3/2, PO3), (DM4/2, PO4); a point
//    that repeats the one before it ends the contour early (fewer than three segments). Every
//    segment is cut at one lead: PP1 = PP2 = PP3 (clpost writes them equal; a call with
//    different pitches is not expanded).
//  - TDEP and FAL are paraxial, along X: toward the axis for VARI 1 and 3 (external), away from
//    it for 2 and 4 (internal). Roughing: TDEP - FAL in NRC cuts, cumulative (TDEP-FAL)*i/NRC
//    for constant infeed (VARI 1, 2) and (TDEP-FAL)*sqrt(i/NRC) for constant cross-section
//    (VARI 3, 4); then one cut at TDEP when FAL > 0, then NID idle passes at TDEP.
//  - IANG: every cut is also shifted along Z, in the cutting direction, by d*tan(IANG) (d its
//    paraxial depth); so that no cut runs past the full-depth one, every cut ends where its last
//    segment has come back along Z by TDEP*tan(IANG) (threading.md section 11).
//  - APP: the first segment is run in APP longer (backward along it). ROP: every cut ends ROP
//    earlier along its last segment and runs out at 45 degrees over ROP (ROP along the segment
//    and ROP away from the material).
//  - NUMTH starts (0 = one), one after the other, every cut of start 1 first; start k at
//    spindle angle NSP + k*360/NUMTH.
// `clpost verify` parses the words back from an NC program and calls expand_cycle98.
#include <string>
#include <vector>

#include "laws/cut_pass.h"

namespace clpost {

// The words of one CYCLE98 call as the control reads them. Lengths in program units; DMs are
// diameters; IANG and NSP in degrees; PP leads per revolution.
struct Cycle98Words {
  double po[4] = {0, 0, 0, 0};  // PO1 … PO4: contour points along Z
  double dm[4] = {0, 0, 0, 0};  // DM1 … DM4: their diameters
  double app = 0;               // APP: run-in
  double rop = 0;               // ROP: run-out
  double tdep = 0;              // TDEP: thread depth
  double fal = 0;               // FAL: finishing allowance
  double iang = 0;              // IANG: infeed angle
  double nsp = 0;               // NSP: start angle of the first start
  int nrc = 1;                  // NRC: roughing cuts
  int nid = 0;                  // NID: idle passes
  double pp[3] = {0, 0, 0};     // PP1 … PP3: lead of each segment
  int vari = 1;                 // VARI 1..4
  int numth = 0;                // NUMTH: starts (0 = one)
  double vrt = 0;               // _VRT: retraction above the contour (0 = 1 mm)
};

struct Cycle98Expansion {
  std::vector<Cut> cuts;  // in the control's cutting order (start by start)
  std::string alarm;      // not empty: not expanded (no cuts)
};

// The cuts the control makes from `w` (CL frame: x a radius, z axial; program units).
Cycle98Expansion expand_cycle98(const Cycle98Words& w);

}  // namespace clpost

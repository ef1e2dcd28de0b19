#pragma once
// HEIDENHAIN CNC PILOT / MANUALplus DIN G31 thread cycle on a directly given contour (G31 … the
// contour blocks … G80), as clpost assumes the control runs it, so that the words clpost writes
// (and, later, words read back by `clpost verify`) expand into synchronized cuts.
//
// Source: HEIDENHAIN DIN Programming User Manual (SW 54843x-03), G31 (seed 004) and
// shared/reference/controllers.md. The seed names the words and the infeed types but not the
// geometry, so most of the law is *(unverified)*:
// - depth of cut n (n = 1 … IC) below the contour: V0 constant cross-section U·√(n/IC),
//   V1 constant infeed U·n/IC (controllers.md: "V0 cumulative I·√n (or from IC and U), V1 n·I");
//   then Q air cuts at U; other V types are not expanded;
// - depth is measured at right angles to the contour element, toward the axis for BD0
//   (external), away from it for BD1 (internal); a face element (X travel dominating) is cut
//   toward -Z for BD0 *(unverified)*;
// - flank offset H: every cut is moved by σ_n = depth·tan(A) along the contour element, toward
//   the side the H value stands for (G31FlankCodes: which H means "toward -Z" / "toward +Z" is
//   machine data); H "alternating" moves the even-numbered cuts only and plunges the odd ones
//   (clpost's OPTION 2/4 rule); the largest offset is taken off every cut's end, so the deepest
//   offset cut ends exactly at the contour end *(unverified)*;
// - run-in B starts every cut B before the contour start, run-out P ends it P after the contour
//   end *(unverified)*; K (run-out length) is not expanded (only K0 is);
// - D > 1 starts are not expanded.
#include <string>
#include <vector>

#include "laws/cut_pass.h"
#include "machine/machine.h"

namespace clpost {

// The words of one G31 block and its contour, as the control reads them.
struct HeidenhainG31 {
  double f = 0;   // thread pitch
  double u = 0;   // thread depth
  int ic = 1;     // number of cuts
  int v = 0;      // infeed type: 0 constant cross-section, 1 constant infeed, 2..6 others
  int h = 0;      // flank offset type (see G31FlankCodes)
  double a = 30;  // infeed angle, degrees
  int d = 1;      // starts
  int q = 0;      // air cuts after the last cut
  double c = 0;   // start angle, degrees
  int bd = 0;     // 0 external, 1 internal
  double b = 0;   // run-in length
  double p = 0;   // run-out length (overtravel)
  double k = 0;   // run-out (> 0) / run-in (< 0) length
  Vec2 from, to;  // the contour element (CL frame: x a radius)
};

// What each H value does (machine data: threading codes g31_h_minus / g31_h_plus /
// g31_h_alternating). 0 never offsets.
struct G31FlankCodes {
  int toward_minus = 1;  // every cut offset toward -Z (-X on a face)
  int toward_plus = 2;   // toward +Z (+X)
  int alternating = 3;
};

// The cuts of `w`, or none with `error` set when the words fall outside what this law covers.
std::vector<Cut> expand_heidenhain_g31(const HeidenhainG31& w, const G31FlankCodes& codes,
                                       std::string* error = nullptr);

// The machine's H values (codes g31_h_minus, g31_h_plus, g31_h_alternating; 1, 2, 3 when absent).
G31FlankCodes g31_flank_codes(const Machine& m);

}  // namespace clpost

#pragma once
// LinuxCNC's G76 threading cycle as its interpreter runs it, so that the words clpost writes
// (and, later, words read back from an NC program by `clpost verify`) can be expanded into the
// synchronized cuts the control makes.
//
// Source: LinuxCNC src/emc/rs274ngc/interp_convert.cc, convert_threading_cycle() and
// threading_pass(); checked against the real interpreter (`rs274 -g`, Debian package
// linuxcnc-uspace) by tests/thread_matrix_test.cc. The law, in the radius frame (I, J, K
// halved in G7 diameter mode):
// - the tool starts at (x0, z0): the drive line x0, the thread start z0; the crest (or bore) line
//   is x0 + I; I > 0 is an internal thread (cuts move away from the axis);
// - pass n (n = 1, 2, ...) cuts at depth J·n^(1/R) below the crest while |I| + J·n^(1/R) <
//   |I| + K, then H + 1 passes at K (R < 1 or absent counts as 1);
// - every pass is shifted by depth·tan(Q) in the cutting direction (Q = -1 means 0): it runs
//   from z0 - zoff to Z + K·tan(Q) - zoff, so the full-depth pass ends exactly at Z;
// - E > 0 with L & 2 (exit taper): the straight part ends E before the pass end and a
//   synchronized taper rises by K over E; L & 1 (entry taper) starts every pass K higher and
//   E earlier;
// - the control refuses I = 0, J <= 0 and K <= J;
// - after the cycle the tool is at (x0, Z).
#include <string>
#include <vector>

#include "laws/cut_pass.h"

namespace clpost {

// The words of one G76 block as the control reads them (numbers after our output rounding).
struct LinuxcncG76 {
  double p = 0;  // lead per revolution
  double z = 0;  // end of the thread (the full-depth pass ends here)
  double i = 0;  // crest offset from the drive line: < 0 external, > 0 internal
  double j = 0;  // first cut depth
  double k = 0;  // full thread depth
  double r = 1;  // depth degression (J·n^(1/R)); < 1 counts as 1
  double q = 0;  // compound (infeed) angle, degrees
  int h = 0;     // spring passes: H + 1 passes at K
  double e = 0;  // taper length along Z (0: none)
  int l = 0;     // taper kind: 1 entry, 2 exit, 3 both
};

// The cuts G76 makes from the drive-line start `start` (CL frame: x a radius, z axial). With
// `diameter_mode` (G7) I, J and K are diameters. Returns no cuts and sets `error` (the control's
// own message) when the control would refuse the block.
std::vector<Cut> expand_linuxcnc_g76(const LinuxcncG76& w, Vec2 start, bool diameter_mode,
                                     std::string* error = nullptr);

}  // namespace clpost

#pragma once
// Random valid lathe CL programs from a small grammar (docs/cl-meaning.md's statements): UNITS
// switches both ways, FEDRAT with and without a mode word, SPINDL (RPM, SMM/SFM with and without
// MAXRPM, OFF, ON), LOADTL with and without ADJUST, RAPID, GOTO, GODLTA, GOHOME, CIRCLE arcs in
// the XZ plane, DELAY in seconds and revolutions, COOLNT, OPSKIP ranges and single-pass threads
// (THREAD/TURN). The same seed gives the same program (std::mt19937).
//
// Valid means: every arc starts and ends on its circle, with its start where the CL program put
// the tool in both block-delete runs (no arc as the first motion after an OPSKIP range that moved,
// none before a GOTO has fixed the position after a UNITS switch); every feed move comes after a
// FEDRAT; a DELAY in revolutions and a thread only with the spindle turning at a set RPM; no tool
// change, UNITS or thread inside an OPSKIP range; all numbers on the 1e-4 grid of their unit, so
// that the program can say every point exactly.
#include <cstdint>
#include <string>

namespace oracle {

// `nct`: also the thread forms of NCT's G33: PITCH/ in threads per inch (G33 E) and coupled
// threads, COUPLE/ON[,pitch] … COUPLE/OFF around a cut and now and then a pull-out (successive G33
// blocks); the programs of the other controls stay as they were, seed for seed.
std::string generate_program(uint32_t seed, bool nct = false);

}  // namespace oracle

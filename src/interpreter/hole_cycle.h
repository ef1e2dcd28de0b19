#pragma once
// A hole-making cycle as the CL gave it (CYCLE/DRILL|DEEP|BRKCHP|TAP|BORE|REAM …), in force
// until CYCLE/OFF: every GOTO in between is a hole (hole_cycles.cc). CL units.
#include <cstdint>
#include <optional>
#include <string>

#include "emitters/hole_output.h"
#include "support/source_loc.h"

namespace clpost {

struct HoleCycle {
  HoleKind kind = HoleKind::kDrill;
  std::string word;  // DRILL, DEEP2, … as written
  double depth = 0;
  std::optional<double> clearance;    // R plane above the hole's top (CLEAR, RAPTO)
  std::optional<double> retract;      // retract plane above the top (RTRCTO)
  double first_peck = 0, peck = 0;    // 0: none
  double dwell = 0;                   // seconds (DWELL, SEC)
  std::optional<double> dwell_revs;   // REV: revolutions, seconds at the hole's RPM
  std::optional<double> return_dist;  // ICAM RETURN: the retract plane above the R plane
  std::optional<double> backoff;      // ICAM BRKCHP: CLEAR,c,backoff (each peck backs off by it)
  bool invers = false;                // ICAM INVERS on TAP: a reverse (left-hand) tap
  SourceLoc return_loc, dwell_loc;
  std::optional<double> feed;  // the cycle's own feed (output units), else FEDRAT's
  FeedMode feed_mode = FeedMode::kPerMinute;
  std::optional<double> lead;  // taps: TPI or PITCH (CL units per revolution)
  SourceLoc loc;
  uint32_t line = 0;
};

}  // namespace clpost

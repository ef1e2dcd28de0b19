#pragma once
// A hole along the spindle axis (on its centre line, or off it at a C index with a live tool), or
// radial along X with a live tool, as the controls' drilling cycles define it: where each feed into
// the hole ends (the pecks measured from the R plane, as a G83 does). The emitters write holes by
// it (emitters/hole_output.h) and the simulator expands a hole cycle's words with it.
#include <cstddef>
#include <cstdint>
#include <optional>
#include <string>
#include <string_view>
#include <vector>

#include "writer/nc_program.h"

namespace clpost {

enum class HoleKind : uint8_t { kDrill, kDeep, kChipBreak, kTap, kBore, kReam };

// "drilling", "peck drilling", …
std::string_view hole_kind_name(HoleKind k);

// A hole in the lathe frame, output units. The tool drills from `top` toward `top + dir·depth`
// along its axis: Z for a hole on the centre line or a face hole, X (as a radius) for a radial
// hole of a live tool (docs/millturn.md). start, top, r, bottom and retract are positions along
// that axis.
struct Hole {
  HoleKind kind = HoleKind::kDrill;
  std::string name;                 // "hole at CL line 12", for comments and diagnostics
  uint32_t cl_line = 0;             // the hole's GOTO
  bool radial = false;              // drilled along X toward the centre line (else along Z)
  double x = 0;                     // X of a hole along Z (a radius): 0 on the centre line, else
                                    // a face hole of a live tool (docs/millturn.md)
  double z = 0;                     // Z of a radial hole
  std::optional<double> c;          // the C axis (degrees) for a hole of a live tool
  double start = 0;                 // where the tool is before the hole (the initial level)
  double top = 0;                   // the hole's top (the CL hole point)
  double r = 0;                     // the R plane (top plus the clearance)
  double bottom = 0;                // the hole's bottom
  double retract = 0;               // where the tool leaves the hole to
  double dir = -1;                  // -1: drilling toward -Z (radial: toward the centre line)
  double first_peck = 0, peck = 0;  // 0: no pecks; measured from the R plane
  std::optional<double> backoff;    // chip breaking: each peck backs off by it (else the machine's)
  double dwell = 0;                 // seconds at the bottom
  double feed = 0;                  // a tap: its lead per revolution
  FeedMode feed_mode = FeedMode::kPerMinute;
  double lead = 0;  // taps
  double rpm = 0;   // taps and dwells (0: unknown)
  SpindleDir spindle = SpindleDir::kCw;
  std::optional<double> tool_diameter;  // the drill's, where the CL gave it (the setup sheet)
};

// The most pecks of one hole (a peck of 1e-6 into a deep hole is refused, not written).
inline constexpr size_t kMaxHolePecks = 1000;

// How far a chip-breaking peck of `h` backs off: the CL's back-off, else `peck_clearance` (the
// machine's holes.peck_clearance).
inline double chip_backoff(const Hole& h, double peck_clearance) {
  return h.backoff ? *h.backoff : peck_clearance;
}

// Where each feed into the hole ends (Z, in order; the last is the bottom): the pecks from the R
// plane, first_peck then peck; one feed without pecks.
std::vector<double> hole_feed_ends(const Hole& h);

}  // namespace clpost

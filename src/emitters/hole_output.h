#pragma once
// One hole on the spindle axis (CYCLE/DRILL … and its GOTO at radial 0) written for a control:
// its own canned cycle through a `hole_*` template when the machine has one and the cycle's words
// say exactly what the CL says, else plain G0/G1/G4 moves with the pecks expanded (the reason in
// a comment) — "exact or fall back", as threads are written.
#include <cstddef>
#include <cstdint>
#include <string>
#include <string_view>
#include <vector>

#include "writer/nc_program.h"

namespace clpost {

enum class HoleKind : uint8_t { kDrill, kDeep, kChipBreak, kTap, kBore, kReam };

// "drilling", "peck drilling", …
std::string_view hole_kind_name(HoleKind k);

// A hole in the lathe frame, output units. The tool drills from `top` toward `top + dir·depth`.
struct Hole {
  HoleKind kind = HoleKind::kDrill;
  std::string name;                 // "hole at CL line 12", for comments and diagnostics
  uint32_t cl_line = 0;             // the hole's GOTO
  double start = 0;                 // Z of the tool before the hole (the cycle's initial level)
  double top = 0;                   // Z of the hole's top (the CL hole point)
  double r = 0;                     // Z of the R plane (top plus the clearance)
  double bottom = 0;                // Z of the hole's bottom
  double retract = 0;               // Z the tool leaves the hole to
  double dir = -1;                  // -1: drilling toward -Z
  double first_peck = 0, peck = 0;  // 0: no pecks; measured from the R plane
  double dwell = 0;                 // seconds at the bottom
  double feed = 0;                  // a tap: its lead per revolution
  FeedMode feed_mode = FeedMode::kPerMinute;
  double lead = 0;  // taps
  double rpm = 0;   // taps and dwells (0: unknown)
  SpindleDir spindle = SpindleDir::kCw;
};

// The template that writes `h` on its machine (hole_drill, hole_peck, …).
const TemplateSpec& hole_template(const Machine& m, const Hole& h);

// Why the template cannot write `h` exactly, or "" when it can (the machine has it, and its one
// peck word, dwell or retract say what the CL says).
std::string hole_misfit(const Machine& m, const Hole& h);

// Writes `h`: the template when it fits, else moves (with a comment saying why). A template that
// cannot be written is returned (an error at the hole's CL line); the moves always are.
[[nodiscard]] TemplateWrite write_hole(NcProgram& prog, const Hole& h);

// The most pecks of one hole (a peck of 1e-6 into a deep hole is refused, not written).
inline constexpr size_t kMaxHolePecks = 1000;

// Where each feed into the hole ends (Z, in order; the last is the bottom): the pecks from the R
// plane, first_peck then peck; one feed without pecks.
std::vector<double> hole_feed_ends(const Hole& h);

// The hole as G0/G1/G4 moves, pecks expanded (a tap: G1 at its lead per revolution in, the
// spindle reversed, G1 out). Returns the dwell's write (kWritten when there is none).
[[nodiscard]] TemplateWrite expand_hole(NcProgram& prog, const Hole& h);

}  // namespace clpost

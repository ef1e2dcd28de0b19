#pragma once
// What the CL file makes the tool do besides its threads and holes, as the post moved it: every
// motion's end point (GOTO, GODLTA, the end of a CIRCLE arc, GOHOME/x,y,z), each arc's centre,
// and the modal state each motion is made with (feed, spindle, tool). What `clpost verify`
// expects the program to do, in order (verify/path_verify.h); the control simulation reads the
// same CutState back from the program (simulator/toolpath.h). Lathe frame (x a radius), CL units.
// Collected only when PostOptions::keep_motions asks.
#include <cstdint>
#include <optional>
#include <vector>

#include "planner/thread_plan.h"

namespace clpost {

enum class SpindleRun : uint8_t { kOff, kCw, kCcw };
enum class ArcSense : uint8_t { kNone, kCw, kCcw };  // G2 / G3 in the lathe frame

// The modal state a move is made with.
struct CutState {
  double feed = 0;      // 0: none yet (per minute or per revolution, program units)
  int8_t per_rev = -1;  // 1 per revolution, 0 per minute, -1 not known (never programmed)
  SpindleRun spindle = SpindleRun::kOff;
  bool css = false;    // constant surface speed: `speed` is a surface speed
  double speed = 0;    // rpm, or the surface speed (0: none yet)
  double max_rpm = 0;  // the CSS speed limit (0: not known)
  int tool = -1;       // -1: no tool change yet
  int offset = -1;     // -1: not known
  bool operator==(const CutState&) const = default;
};

// A state and the line where it came into force (a CL line, or an NC line in the simulation);
// on the CL side also the statements that set its parts (LOADTL, FEDRAT, SPINDL; 0: none).
struct CutStateAt {
  CutState state;
  uint32_t line = 0;
  uint32_t tool_line = 0, feed_line = 0, spindle_line = 0;
};

struct ClMotion {
  uint32_t line = 0;  // the CL line
  Vec2 to;
  bool rapid = false;
  bool stays = false;  // the tool is already there: nothing moves, the program need not say it
  // Where a cycle the CL names (a hole, a thread, an undercut) leaves the tool, by whatever move
  // its control takes (a rapid, a tap's feed out, a synchronized pull-out): the cycle's own moves
  // lie before it and are compared on their own.
  bool exit = false;
  std::optional<double> hole_bottom;  // a hole's exit: its bottom Z, which the tool reaches first
  uint32_t thread_cuts = 0;           // a thread's exit: its synchronized cuts, which come first
  ArcSense arc = ArcSense::kNone;
  Vec2 center;         // arcs only
  uint32_t state = 0;  // index into ClPath::states
  // Inside an OPSKIP range: written as optional blocks, which block delete skips.
  bool optional = false;
};

struct ClPath {
  std::vector<ClMotion> motions;
  std::vector<CutStateAt> states;  // each motion's, in order; a new entry at each change
  size_t state_count = 0;          // states made (PostOptions::on_motion keeps the last only)
};

}  // namespace clpost

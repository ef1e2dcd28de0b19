#pragma once
// What a program makes the tool do, as clpost's control simulation (simulator/) or the CL plan
// sees it: every move in order, in the CL lathe frame (x a radius, z the spindle axis). What
// `clpost verify` compares and `clpost plot` draws.
#include <cstdint>
#include <string>
#include <vector>

#include "interpreter/cl_motion.h"
#include "planner/thread_plan.h"

namespace clpost {

enum class MoveKind : uint8_t {
  kRapid,   // G0
  kFeed,    // G1, and the feed moves of canned cycles
  kArcCw,   // G2 (center in `center`)
  kArcCcw,  // G3
  kThread,  // a synchronized (spindle-locked) move: G33, G32, G92's cut, a cycle's passes
};

struct Move {
  MoveKind kind = MoveKind::kRapid;
  Vec2 from;
  Vec2 to;
  Vec2 center;         // arcs only
  int line = 0;        // NC (or CL) line the move comes from, 1-based; cycle moves: the call's line
  double lead = 0;     // kThread: lead per revolution along the dominant axis, program units
  uint32_t state = 0;  // the modal state it is made with: index into Toolpath::states
  // A live tool's milling: a feed (not a rapid) whose block writes C, or with Y off 0. verify's
  // lathe path check leaves it to the milling check (verify/mill_verify.h). The lathe's XZ feeds
  // never write C or Y; a rapid may (a live tool's XZ approach back to its C index: G0 X Z C).
  bool mill = false;
};

// Which parts of CutState the program states in words the simulation reads back (the machine's
// codes and its templates tool_change, spindle_rpm, spindle_css, spindle_stop): what verify can
// compare. A part the machine file writes in a form that cannot be read back stays false.
struct StateReadback {
  bool feed_mode = false;  // codes feed_per_min and feed_per_rev
  bool spindle = false;    // spindle_cw, spindle_ccw, the speed word of spindle_rpm
  bool css = false;        // spindle_css's speed line has a code of its own (G96)
  bool max_rpm = false;    // spindle_css's {max_rpm} word
  bool tool = false;       // tool_change's {tool} word
  bool offset = false;     // tool_change's {offset}
};

// A program's whole motion, in order.
struct Toolpath {
  LengthUnit units = LengthUnit::kMm;
  std::vector<Move> moves;
  // Moves from where the tool happened to be (the first, or after a machine position such as
  // G28): not drawn; each comes before moves[before].
  struct Entry {
    size_t before;
    Move move;
  };
  std::vector<Entry> entries;
  std::vector<CutStateAt> states;  // the moves' modal states, a new entry at each change
  StateReadback readback;
};

// One thread's passes seen in its cross-section: where the tool's V sits at each pass.
struct SectionPass {
  int n = 0;         // 1-based pass number (the depth ladder index: starts share it)
  int start = 0;     // start index, 0-based
  double depth = 0;  // cumulative depth below the thread surface
  double shift = 0;  // flank shift along the cutting direction (sigma)
  PassKind kind = PassKind::kRough;
};

// Where a thread's lead is not yet right (planner/run_in.h: its run-in and run-out), along its
// lead axis in the CL frame, for the pictures. Not `known` when the spindle speed is not.
struct SectionLead {
  bool known = false;
  bool along_z = true;                  // the lead axis: Z, or X for a face-like thread
  double cut_from = 0, cut_to = 0;      // the stretch every pass cuts, in cutting order
  double right_from = 0, right_to = 0;  // where in it the lead is right, when `any`
  bool any = false;                     // some length has the right lead
  double run_in = 0, run_out = 0, rpm = 0;
  double across_lo = 0, across_hi = 0;  // the other axis: what the passes span
};

struct ThreadSection {
  std::string title;  // e.g. "thread at part.cl:12 - pitch 1.5, depth 0.92, OPTION 1"
  LengthUnit units = LengthUnit::kMm;
  ThreadSide side = ThreadSide::kExternal;
  double pitch = 0;  // crest to crest
  double lead = 0;   // starts x pitch
  int starts = 1;
  double depth = 0;        // full thread depth D
  double tool_angle = 60;  // included angle of the tool's V, degrees
  std::vector<SectionPass> passes;
  SectionLead zones;  // the run-in and run-out along the thread
};

}  // namespace clpost

#pragma once
// Runs an NC program the way its control would (machine m's dialect): modal motion, units,
// diameter mode, and every threading cycle clpost writes expanded with the control's documented
// law (controls/*/*_law.h). The result is the tool's moves (for `clpost plot`) and the synchronized
// cuts (for `clpost verify`).
#include <functional>
#include <memory>
#include <optional>
#include <string>
#include <utility>
#include <vector>

#include "machine/machine.h"
#include "reader/line_source.h"
#include "simulator/toolpath.h"
#include "support/diagnostics.h"

namespace clpost {

// One synchronized cut: a G33/G32 move with its chained pull-out moves, one G92 cycle, or one
// pass of a cycle's expansion. CL frame (x a radius), program units.
struct NcCut {
  Vec2 from;
  Vec2 to;                  // end of the first synchronized move (the thread itself)
  Vec2 end;                 // after the chained pull-out moves (== to when there are none)
  std::vector<Vec2> chain;  // every synchronized move's end point, in order (to .. end)
  std::optional<Vec2> linear_pullout;  // a G1 move right after the cut ends here
  double lead = 0;                     // per revolution, program units
  double lead_change = 0;              // G34 (+) / G35 (-) per revolution
  int start = -1;                      // start index when a cycle says it (else -1)
  std::optional<double> start_angle;   // degrees, when the block gives one
  uint32_t line = 0;                   // the NC block (a cycle's call)
  std::string line_text;               // that block's text, for diagnostics
  std::string source;                  // "G33", "G92", "G76", "CYCLE99", "G31"
  int call = -1;                       // cuts of one cycle call share it; -1 single block
  bool fixed_end = false;  // G76 with threading.cycle_pass_end: fixed (every pass ends at Z)
};

// One hole drilled on the spindle axis: a hole cycle's block (its words read back through the
// machine's hole_* template and expanded with hole_feed_ends, the law the emitter writes by) or
// the moves after a "hole at CL line N" comment. CL frame, program units.
struct SimHole {
  uint32_t cl_line = 0;  // from the program's "hole at CL line N" comment (0: none)
  uint32_t line = 0;     // NC line of the cycle block or of the first feed into the hole
  std::string line_text;
  std::string source;             // "G83", "CYCLE83", "moves"
  double x = 0;                   // X of the hole, a radius (0: on the centre line)
  bool radial = false;            // drilled along X at Z `z` (feed_ends, r, out: X radii)
  double z = 0;                   // Z of a radial hole
  std::optional<double> c;        // the C axis's position then (degrees), when C was written
  double r = 0;                   // where the first feed into the hole starts
  double dir = -1;                // the way the feeds go in
  std::vector<double> feed_ends;  // Z where each feed into the hole ends, each deeper
  bool left = false;              // the tool came back to the R plane after the last feed
  std::optional<double> out;      // how far out (Z) the tool came after the last feed, if at all
  std::optional<double> lead;     // a tap's lead, when the cycle says it
};

// A move of a machine with C (millturn.c_axis) in X, Y, Z and C, as read: where it ends, so
// that verify maps it back to the part frame (verify/mill_verify.h, docs/millturn.md).
struct SimMillMove {
  uint32_t line = 0;
  std::string line_text;
  bool rapid = false;
  bool arc = false;            // G2/G3 (simulator/mill_arc.h: its path)
  double x = 0, y = 0, z = 0;  // X a radius
  double c = 0;                // degrees, as written (0 before any C)
  bool c_known = false;        // a C word came before (or in) this block
  bool at_known = false;       // X and Z are known at its end (not the first move's unknown start)
  int plane = 18;              // the plane selected then (17, 18, 19)
  bool ccw = false;            // G3
  double i = 0, j = 0, k = 0;  // an arc's centre words, from its start (I a radius)
  int tool = -1;               // the tool loaded then, as read back (-1: not known)
};

struct Simulation {
  LengthUnit units = LengthUnit::kMm;
  Toolpath path;            // every move (only when SimOptions::keep_moves)
  std::vector<NcCut> cuts;  // in cutting order
  size_t blocks = 0;        // NC lines read
  int calls = 0;            // cycle calls expanded
  std::vector<SimHole> holes;
  // A machine with C: its moves in X, Y, Z or C from the last one before C is first written
  // (mill_moves.cc says why no milling is before it), and how many there were in all.
  std::vector<SimMillMove> mill_moves;
  size_t mill_move_count = 0;
  size_t deleted_blocks = 0;  // blocks marked optional ('/'), which block delete skips
  std::pair<uint32_t, std::string> first_optional;  // the first one's line and text
  // With SimOptions::block_delete_too and optional blocks: the run with block delete on (one).
  std::vector<Simulation> with_block_delete;
};

struct SimOptions {
  bool keep_moves = true;
  // Every move as it is made, with the modal state it is made with (the entries from an unknown
  // position among them, in order, as Move{from == to}): verify of the path while the program
  // is read, with no moves kept.
  std::function<void(const Move&, const CutState&)> on_move;
  // A machine with C: each move Simulation::mill_moves would keep, handed over and not kept.
  std::function<void(const SimMillMove&)> on_mill_move;
  // Also runs the program with block delete on (its optional blocks skipped), beside the run
  // with it off: Simulation::with_block_delete. Its errors the other run has not are reported
  // too, marked "(block delete on)".
  bool block_delete_too = false;
  // With block_delete_too: the moves of the run with block delete on, as on_move has the others.
  std::function<void(const Move&, const CutState&)> on_block_delete_move;
  // Called before the first optional block is run: where the runs with block delete off and on
  // first differ.
  std::function<void()> on_first_optional;
};

// The simulation a line at a time, as the program is written (clpost --verify). `out` and
// `options` must outlive it.
class ControlSim {
 public:
  ControlSim(const Machine& m, Diagnostics& diags, Simulation& out, const SimOptions& options);
  ~ControlSim();
  // One line of the program, 1-based, without its line end. False: too many errors, stop.
  bool line(uint32_t number, std::string_view text);
  // A line that cannot be read (reported by the caller).
  void unreadable();
  // The end of the program: true when it was read without errors.
  bool finish();
  // What the program's words let verify compare (the machine's codes and templates).
  const StateReadback& readback() const;
  // The units of the run with block delete on (SimOptions::block_delete_too), as read so far;
  // without it, those of the run.
  const LengthUnit& block_delete_units() const;
  // Before the first line: the caller knows the program has no optional block to come (its CL
  // has no OPSKIP range), so the run with block delete on is not made. Should one come all the
  // same, the caller reports it (verify: optional_without_opskip).
  void no_optional_blocks();

 private:
  struct Impl;
  std::unique_ptr<Impl> impl_;
};

// Reads a program from `src` a line at a time into `line(number, text)` (false: stop there), as
// the control simulation reads one: a line too long is an error and `unreadable()`; binary data
// and a read error are errors that stop it. False when it stopped.
bool read_nc_lines(reader::LineSource& src, Diagnostics& diags,
                   const std::function<bool(uint32_t, std::string_view)>& line,
                   const std::function<void()>& unreadable);

// Reads the program from `src` into `out`. Errors (text that is not NC, a word the control
// would refuse, a cycle its law refuses) go to `diags` as `file:line:col: error: ...`; returns
// false when there were any.
bool simulate_nc(reader::LineSource& src, const Machine& m, Diagnostics& diags, Simulation& out,
                 const SimOptions& options = {});

}  // namespace clpost

#pragma once
// A thread undercut (CL CYCLE/UNDCUT,DIAM,d,AT,z,FORM,A|B|C|D) written for a machine: its
// control's undercut cycle where it has one (the registry's make_undercut_cycle: SINUMERIK
// CYCLE96), else the DIN 76-1 contour as moves. Unlike a thread or a hole, an undercut does not
// fall back from a machine's cycle to moves: the cycle refuses what the control would stop on with
// an alarm, and that is an error at the CL word.
#include <memory>
#include <optional>

#include "emitters/cycle_output.h"
#include "laws/din76_undercut.h"

namespace clpost {

// The undercut as the CL asks for it (mm, CL lathe frame: x a radius).
struct Undercut {
  double diam = 0;           // the thread's nominal diameter (DIAM)
  double at = 0;             // the shoulder face's Z (AT)
  char form = 'A';           // DIN 76-1 form (FORM)
  double pitch = 0;          // the ISO coarse pitch of diam
  std::optional<Vec2> tool;  // where the tool is (the side of AT the undercut lies on)
  double feed = 0;           // the feed in force, which the cycle cuts at
  FeedMode feed_mode = FeedMode::kPerMinute;
  int tool_offset = -1;          // the active offset (-1: no tool loaded)
  SourceLoc diam_loc, form_loc;  // the CL words, for errors about them
};

// What writing it did, for the interpreter's path and statistics.
struct UndercutWritten {
  size_t moves = 0;          // motions written (0: a cycle)
  std::optional<Vec2> exit;  // where the moves leave the tool (a cycle returns where it began)
};

// Writes `u`; false, with an error at the CL word the refusal is about (ctx.loc otherwise).
bool write_undercut(NcProgram& prog, const Undercut& u, const EmitContext& ctx,
                    UndercutWritten& written);

// The undercut cycle a control of the machine's set writes on it (CYCLE96 where the machine has
// its template), or null.
std::unique_ptr<CycleOutput<Undercut>> make_undercut_cycle(const Machine& m);

}  // namespace clpost

#pragma once
// A thread sequence while the interpreter reads it: THREAD/ON … THREAD/OFF (and Pro/E's
// OP/THREAD … OP/THREAD,NOMORE), THREAD/TURN|FACE|TAPER and its GOTOs, COUPLE/ON … COUPLE/OFF.
// It holds only what the planner needs (planner.h); the planner plans every form, and the
// interpreter writes what it planned (thread_statements.cc).
#include <cstdint>
#include <memory>

#include "emitters/emitter.h"
#include "planner/planner.h"
#include "planner/thread_plan.h"

namespace clpost {

struct ThreadSequence {
  enum class Kind : uint8_t { kNone, kMulti, kSingle, kCouple };
  Kind kind = Kind::kNone;
  SourceLoc loc;        // the statement that opened it
  SavedLines lines;     // its lines, for diagnostics after the reader has moved on
  bool failed = false;  // its opening statement had an error: read to its end, not cut

  MultiThreadInput multi;       // kMulti
  SingleThreadInput single;     // kSingle
  CouplePlanner couple;         // kCouple: planned as it is read
  bool couple_cutting = false;  // the first synchronized move is written (spindle checked)
  double couple_travel = 0;     // length of the coupled path cut so far

  PitchSpec pitch;  // the modal PITCH/
  PlannerSettings settings;
  std::unique_ptr<Emitter> emitter;  // the machine's multi-pass thread output

  // The spindle for the thread in progress: constant surface speed is turned into this rpm
  // (forced_rpm) and restored afterwards.
  bool forced_rpm = false;
  double rpm = 0;
};

}  // namespace clpost

#pragma once
// Where the diagnostics of a multi-pass thread point: its THREAD/ON statement (and the words on
// it) and its GOTOs. Internal to planner/.
#include <cstddef>

#include "planner/plan_report.h"
#include "planner/planner.h"

namespace clpost::plan_report {

// The THREAD/ON statement (or OP/THREAD) at its major word.
inline Site on_site(const MultiThreadInput& in) {
  return Site{in.on_loc, &in.on_lines};
}
// A word of the THREAD/ON statement, at `loc`.
inline Site word_site(const MultiThreadInput& in, SourceLoc loc) {
  return Site{loc, &in.on_lines};
}
// GOTO `i` (0-based) of the sequence.
inline Site goto_site(const MultiThreadInput& in, size_t i) {
  return Site{in.gotos[i].loc, &in.gotos[i].lines};
}
// The note that follows an error at a GOTO: where the sequence began.
inline void note_sequence_start(const MultiThreadInput& in, Reporter& r) {
  r.note(on_site(in), "the thread sequence starts here");
}

}  // namespace clpost::plan_report

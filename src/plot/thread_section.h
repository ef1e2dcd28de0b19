#pragma once
// A thread's cross-section as `clpost plot` draws it (simulator/toolpath.h: ThreadSection), made
// from the planner's pass plan.
#include <string>

#include "planner/thread_plan.h"
#include "simulator/toolpath.h"

namespace clpost {

// The section of a planned thread: units, side, pitch, lead, starts, full depth D and tool angle
// from the plan, and one SectionPass per planned pass in cutting order, with the plan's pass
// number n (the depth ladder index, so the starts of a multi-start thread share it), start index,
// cumulative depth, flank shift and kind. Coupled and single-pass threads have no passes.
// `zones`: the run-in and run-out of the plan (planner/run_in.h) when its speed is known.
// An empty `title` becomes "thread at line L - pitch P, depth D, OPTION o" (numbers as in
// `clpost plan`; without the OPTION part for threads that have no infeed).
ThreadSection section_from_plan(const ThreadPlan& plan, std::string title);

}  // namespace clpost

namespace clpost {

// The sections `clpost plot` draws for a planned thread: one, section_from_plan's, or for a
// chained thread (threading.md section 11) one per segment, titled "... segment j of k", each
// pass's depth and flank shift measured at right angles to that segment and along it (on a
// segment sloping a from the infeed's normal the depth is d cos a).
std::vector<ThreadSection> sections_from_plan(const ThreadPlan& plan);

}  // namespace clpost

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
// An empty `title` becomes "thread at line L - pitch P, depth D, OPTION o" (numbers as in
// `clpost plan`; without the OPTION part for threads that have no infeed).
ThreadSection section_from_plan(const ThreadPlan& plan, std::string title);

}  // namespace clpost

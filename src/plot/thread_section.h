#pragma once
// A thread's cross-section as `clpost plot` draws it (simulator/toolpath.h: ThreadSection), made
// from the planner's pass plan.
#include <cstddef>
#include <string>
#include <utility>
#include <vector>

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

namespace clpost {

// Whether two sections draw the same picture of the same thread plan, wherever it is: equal in
// everything, the titles but for the line they name ("thread at line 12 - ...", "... at
// part.cl:12 ...": the digits after the first "line " or ':').
bool same_section(const ThreadSection& a, const ThreadSection& b);

// The sections a backplot draws, each distinct one once: identical ones (same_section) are
// counted, and the first of them drawn with " \u00d7N (N identical threads)" after its title.
// At most kMaxDrawnSections distinct ones are kept (memory and picture stay bounded); the
// others are only counted, in `left_out`.
inline constexpr size_t kMaxDrawnSections = 24;
class SectionGroups {
 public:
  void add(ThreadSection s);
  // The sections to draw, titles with their counts.
  std::vector<ThreadSection> drawn() const;
  size_t total() const { return total_; }
  size_t left_out() const { return left_out_; }

 private:
  std::vector<std::pair<ThreadSection, size_t>> groups_;
  size_t total_ = 0;
  size_t left_out_ = 0;
};

}  // namespace clpost

#pragma once
// Writing what the planner planned: the spindle during a thread, the machine's feed limits for
// every synchronized move, a multi-pass plan through the machine's emitter, and the synchronized
// moves of single-pass and coupled threads. Internal to the interpreter.
#include <string>
#include <string_view>

#include "interpreter/post_state.h"

namespace clpost {

// Where a thread's diagnostics go: a statement's location and its line text.
struct CutSite {
  SourceLoc loc;
  std::string_view line;
};

// Before a thread: the spindle must turn, and at a constant speed (constant surface speed is
// turned into the rpm at the thread's largest radius `radius` and restored by
// end_thread_spindle). False (reported at `at`) when the thread cannot be cut.
bool begin_thread_spindle(PostState& s, double radius, CutSite at);
// The spindle speed a thread whose largest radius is `radius` is cut at (the one
// begin_thread_spindle sets): the rpm in force, or the one constant surface speed gives there;
// 0 when the spindle is stopped.
double thread_rpm(const PostState& s, double radius);
void end_thread_spindle(PostState& s);

// Whether the machine can feed the synchronized move `from` → `to` at `lead` × the thread's rpm:
// the axis of the larger travel moves the lead per revolution, the other one in proportion.
// False (reported at `at`) when an axis limit or the feed limit is exceeded.
bool check_thread_feed(PostState& s, Vec2 from, Vec2 to, double lead, CutSite at);

// A multi-pass plan: spindle, feed limits, then the machine's emitter.
void cut_multi_thread(PostState& s, ThreadPlan& plan, const SavedLines& lines);
// One synchronized move of a single-pass or coupled thread (`plan` is its plan so far; `travel`
// the length of its path cut before this move, for a variable lead), checked against the feed
// limits. False (reported at `at`) when it cannot be cut.
bool cut_path_move(PostState& s, const ThreadPlan& plan, const ThreadPass& pass, double travel,
                   CutSite at);
// The warning at `at` when no length of the thread has the right lead (planner/run_in.h).
void warn_no_right_lead(PostState& s, const ThreadPlan& plan, CutSite at);
// A planned thread is done: counted and handed to the on_thread callback.
void thread_planned(PostState& s, const ThreadPlan& plan);

}  // namespace clpost

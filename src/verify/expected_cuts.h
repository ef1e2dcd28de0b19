#pragma once
// What the plan says the control must cut: every thread's passes (or a coupled / single-pass
// thread's synchronized path) as one flat list, in the plan's cutting order.
#include <vector>

#include "planner/thread_plan.h"

namespace clpost {

struct ExpectedCut {
  size_t thread = 0;  // index into the plans
  int pass = 0;       // the plan's pass number n (the depth ladder index: starts share it)
  int start = 0;
  double depth = 0;
  double shift = 0;
  double start_angle = 0;
  Vec2 from, to, end;
  // Coupled / single-pass / chained threads: every synchronized move's end (a chain's pass: its
  // segments, then a threaded pull-out).
  std::vector<Vec2> chain;
  PassKind kind = PassKind::kRough;
  bool path = false;  // a coupled or single-pass thread's synchronized path
};

std::vector<ExpectedCut> expected_cuts(const std::vector<ThreadPlan>& plans);

}  // namespace clpost

#pragma once
// The synchronized cuts of a thread, as a control will cut them or as the plan says, so that a
// cycle's expansion (its control's law applied to the words we write) can be compared with the
// plan pass by pass. Also what `clpost verify` compares.
#include <string>
#include <vector>

#include "machine/machine.h"
#include "planner/thread_plan.h"

namespace clpost {

struct Cut {
  int start = 0;              // start index, 0-based
  double depth = 0;           // cumulative depth below the thread surface
  Vec2 from;                  // synchronized cut start (CL frame, x radius)
  Vec2 to;                    // synchronized cut end
  Vec2 end;                   // after the pull-out (== to when there is none)
  std::vector<Vec2> corners;  // a chained thread: the vertices between from and to, in order
};

// The plan's passes as cuts, in cutting order.
std::vector<Cut> plan_cuts(const ThreadPlan& plan);

// The largest difference between a cut and the plan that still counts as equal, CL units:
// threading.tolerance, or one least increment of the machine's Z format.
double cut_tolerance(const Machine& m);

struct CutCompareOptions {
  double tolerance = 0.001;
  // The control cuts every pass of start 1, then of start 2, … (CYCLE99) while the plan
  // interleaves them: compare start by start.
  bool start_by_start = false;
};

// The first difference between the control's cuts and the plan's, as one line naming the pass
// and the numbers ("pass 3: depth 0.8120, plan 0.8000"), or "" when they agree.
std::string compare_cuts(const std::vector<Cut>& control, const std::vector<Cut>& plan,
                         const CutCompareOptions& o);

}  // namespace clpost

#pragma once
// The depth ladder of a multi-pass thread: the cumulative depth of every pass from DEPTH, CUTS,
// STEP, FINCUT and the OPTION law (threading.md section 5, docs/threading.md).
#include <string_view>
#include <vector>

#include "planner/thread_plan.h"
#include "planner/thread_words.h"
#include "reader/statement.h"
#include "support/diagnostics.h"

namespace clpost {

struct DepthLadder {
  double depth = 0;      // D, the full thread depth (0 for CUTS,1 alone: a pass on the contour)
  double allowance = 0;  // f, FINCUT allowance
  double roughing_depth = 0;    // R = D - f, reached exactly by the last roughing pass
  int roughing = 0;             // roughing passes
  int finishing = 0;            // FINCUT passes at D
  std::vector<double> depths;   // cumulative depth of every pass, roughing then FINCUT
  std::vector<PassKind> kinds;  // rough / finish / spring, per pass
};

// Sums are compared with DEPTH within this (CL units).
inline constexpr double kDepthTolerance = 1e-6;
// A remainder below this (CL units) adds no pass.
inline constexpr double kRemainderTolerance = 1e-9;

// Cumulative roughing depths of the OPTION law with `count` passes over `roughing` (R):
// 0: R*i*(2c-i+1)/(c*(c+1)); 1, 2: R*sqrt(i/c); 3, 4: R*i/c. The last is R exactly.
std::vector<double> option_ladder_by_count(int option, double roughing, int count);
// Passes the OPTION law needs over R when the first step is `first_step` (s):
// 0: max(1, ceil(2R/s - 1)); 1, 2: ceil((R/s)^2); 3, 4: ceil(R/s); one less when the last pass
// would remove less than kRemainderTolerance. A double: it can be huge for a tiny step.
double option_count_for_first_step(int option, double roughing, double first_step);
// Cumulative roughing depths with first step s and `count` from option_count_for_first_step:
// 0: step_i = s - (i-1)*delta, delta = 2(s*c - R)/(c(c-1)); 1, 2: min(R, s*sqrt(i));
// 3, 4: min(R, i*s). The last is R exactly.
std::vector<double> option_ladder_by_first_step(int option, double roughing, double first_step,
                                                int count);

// Builds the ladder for THREAD/ON words `w` with infeed law `option`. Errors are reported at the
// word concerned (`lines` holds the THREAD/ON statement) or, when no word is concerned, at
// `on_loc` (`on_word` names the statement, e.g. "THREAD/ON").
bool make_depth_ladder(const ThreadWords& w, int option, const SavedLines& lines, SourceLoc on_loc,
                       std::string_view on_word, DepthLadder& out, Diagnostics& diags);

}  // namespace clpost

#pragma once
// Flank (edge) infeed of a multi-pass thread (threading.md section 6): how far each pass is
// shifted along the cutting direction. Internal to planner/.
#include <vector>

namespace clpost {

struct FlankShifts {
  std::vector<double> sigma;  // the shift of every pass of the depth ladder (0: plunged straight)
  double max = 0;             // the largest shift: every pass ends this much before P2
};

// The shifts of the passes at cumulative `depths`: sigma_i = d_i tan(a/2) for OPTION 1 and 3
// (single edge), for the even-numbered passes only with OPTION 2 and 4 (alternating edges); none
// with OPTION 0 or a CUTANG (degrees) that is not a multiple of 90.
FlankShifts flank_shifts(const std::vector<double>& depths, int option, double cutang,
                         double tool_angle);

}  // namespace clpost

// Flank infeed: threading.md section 6 (flank_shift.h).
#include "planner/flank_shift.h"

#include <algorithm>
#include <cmath>

#include "planner/plan_report.h"
#include "support/angles.h"
#include "support/vec2_math.h"

namespace clpost {

namespace {

bool is_axis_angle(double deg_value) {
  const double r = std::fabs(std::fmod(deg_value, 90.0));
  return r < plan_report::kAngleEps || 90 - r < plan_report::kAngleEps;
}

}  // namespace

FlankShifts flank_shifts(const std::vector<double>& depths, int option, double cutang,
                         double tool_angle) {
  const size_t npass = depths.size();
  FlankShifts s;
  s.sigma.assign(npass, 0);
  if (option != 0 && is_axis_angle(cutang)) {
    const double k = std::tan(radians(tool_angle / 2));
    const bool single_edge = option == 1 || option == 3;
    for (size_t i = 0; i < npass; ++i) {
      const int pass_no = static_cast<int>(i) + 1;
      if (single_edge || pass_no % 2 == 0) s.sigma[i] = depths[i] * k;
    }
  }
  s.max = npass ? *std::max_element(s.sigma.begin(), s.sigma.end()) : 0;
  return s;
}

}  // namespace clpost

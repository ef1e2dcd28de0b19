#include "plot/nice_step.h"

#include <cmath>
#include <initializer_list>

namespace clpost {

double nice_step(double approx) {
  if (!std::isfinite(approx) || approx <= 0) return 1;
  const double p = std::pow(10.0, std::floor(std::log10(approx)));
  for (const double m : {1.0, 2.0, 5.0, 10.0})
    if (m * p >= approx * (1 - 1e-9)) return m * p;
  return 10 * p;
}

double nice_floor(double limit) {
  if (!std::isfinite(limit) || limit <= 0) return 1;
  const double p = std::pow(10.0, std::floor(std::log10(limit)));
  for (const double m : {10.0, 5.0, 2.0, 1.0})
    if (m * p <= limit * (1 + 1e-9)) return m * p;
  return p;
}

}  // namespace clpost

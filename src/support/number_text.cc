#include "support/number_text.h"

#include <fmt/format.h>

#include <cmath>

namespace clpost {

std::string num_text(double v) {
  if (!std::isfinite(v) || std::fabs(v) >= 1e12) return fmt::format("{:.6g}", v);
  std::string s = fmt::format("{:.6f}", v);
  while (!s.empty() && s.back() == '0') s.pop_back();
  if (!s.empty() && s.back() == '.') s.pop_back();
  if (s == "-0") s = "0";
  return s;
}

}  // namespace clpost

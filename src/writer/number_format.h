#pragma once
#include <cmath>
#include <cstddef>
#include <cstdint>
#include <string>

#include "machine/machine.h"

namespace clpost {

// Appends `value` written in format `f` to `out` ("12.", "0.5", "-.25", "1500", "1.500").
// Negative zero after rounding is written as zero.
void append_number(std::string& out, double value, const NumberFormat& f);

// The most characters put_number() writes in format `f`: a sign, the 309 whole digits of the
// largest double, the point and the decimals, with room to spare.
inline size_t max_number_chars(const NumberFormat& f) {
  return 320 + static_cast<size_t>(f.decimals > 0 ? f.decimals : 0);
}
// The same as append_number(), written at `out` (room for max_number_chars(f) characters);
// returns the end of what it wrote.
char* put_number(char* out, double value, const NumberFormat& f);

namespace number_format_detail {

constexpr double kPow10[] = {1e0,  1e1,  1e2,  1e3,  1e4,  1e5,  1e6,  1e7,  1e8,  1e9,  1e10, 1e11,
                             1e12, 1e13, 1e14, 1e15, 1e16, 1e17, 1e18, 1e19, 1e20, 1e21, 1e22};

// std::round (half away from zero), the same value bit for bit, without a libm call.
inline double round_half_away(double x) {
  if (!(std::fabs(x) < 0x1p52)) return std::round(x);  // already whole, or not finite
  const double whole = static_cast<double>(static_cast<int64_t>(x));  // towards zero, exact
  const double frac = x - whole;                                      // exact
  const double r = frac >= 0.5 ? whole + 1 : frac <= -0.5 ? whole - 1 : whole;
  return std::copysign(r, x);  // -0.4 gives -0., as std::round does
}

}  // namespace number_format_detail

// `value` rounded to what format `f` writes (so modal suppression compares what is written):
// std::round(value · scale · 10^decimals) / 10^decimals, inline (it runs for every axis word).
inline double rounded(double value, const NumberFormat& f) {
  using namespace number_format_detail;
  const double p =
      f.decimals >= 0 && f.decimals <= 22 ? kPow10[f.decimals] : std::pow(10.0, f.decimals);
  return round_half_away(value * f.scale * p) / p;
}

}  // namespace clpost

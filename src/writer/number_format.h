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
// `value` written in format `f`, as a string of its own (for templates and messages).
inline std::string number_text(double value, const NumberFormat& f) {
  std::string s;
  append_number(s, value, f);
  return s;
}

// The most characters put_number() writes in format `f`: a sign, the 309 whole digits of the
// largest double, the point and the decimals, with room to spare.
inline size_t max_number_chars(const NumberFormat& f) {
  return 320 + static_cast<size_t>(f.decimals > 0 ? f.decimals : 0);
}
// The same as append_number(), written at `out` (room for max_number_chars(f) characters);
// returns the end of what it wrote.
char* put_number(char* out, double value, const NumberFormat& f);

// A value as format `f` writes it, worked out once: for modal suppression (a word is left out
// when its text would be the text written last) and for writing it.
struct WrittenNumber {
  double value = 0;     // as given (unscaled)
  uint64_t digits = 0;  // |value|·scale·10^decimals, rounded as printf rounds the exact value
  bool negative = false;
  bool exact = false;  // false: `digits` unknown (an exact tie, huge, not finite): fmt writes it
};

namespace number_format_detail {
constexpr double kPow10[] = {1e0, 1e1, 1e2,  1e3,  1e4,  1e5,  1e6,  1e7,
                             1e8, 1e9, 1e10, 1e11, 1e12, 1e13, 1e14, 1e15};

// `v` (finite, >= 0) rounded to `decimals` digits as the integer v·10^decimals, exactly as
// printf/fmt round the exact binary value: false when this cannot tell (an exact tie, or too
// large).
bool scaled_digits_slow(double v, double p, double t, uint64_t& q);
inline bool scaled_digits(double v, int decimals, uint64_t& q) {
  if (decimals < 0 || decimals > 15) return false;
  const double p = kPow10[decimals];
  const double t = v * p;           // one rounding: |t - v·p| <= ulp(t)/2
  if (!(t < 0x1p50)) return false;  // ulp(t) <= 1/4: 0.5 lies on t's grid
  q = static_cast<uint64_t>(t);     // floor: t >= 0 (an integer conversion, not a libm call)
  const double frac = t - static_cast<double>(q);  // exact (Sterbenz)
  if (frac > 0.5) {
    ++q;  // frac >= 0.5 + ulp: the exact value is above the half too
  } else if (frac == 0.5) {
    return scaled_digits_slow(v, p, t, q);
  }
  return true;
}
}  // namespace number_format_detail

inline WrittenNumber written(double value, const NumberFormat& f) {
  WrittenNumber w;
  w.value = value;
  const double v = value * f.scale;
  if (std::isfinite(v) && number_format_detail::scaled_digits(std::fabs(v), f.decimals, w.digits)) {
    w.exact = true;
    w.negative = std::signbit(v) && w.digits != 0;  // no "-0"
  }
  return w;
}

// Whether `a` and `b` (in one format) are written with the same text: the same value, or the
// same digits. Different values of which either is not exact are taken for different texts:
// such a word is written again rather than wrongly left out.
inline bool same_text(const WrittenNumber& a, const WrittenNumber& b) {
  return a.value == b.value ||
         (a.exact && b.exact && a.digits == b.digits && a.negative == b.negative);
}

// put_number() for a value already worked out.
char* put_written(char* out, const WrittenNumber& w, const NumberFormat& f);

}  // namespace clpost

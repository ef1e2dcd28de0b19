#include "reader/number.h"

#include <charconv>
#include <cstdint>
#include <system_error>

#include "support/text.h"

namespace clpost::reader {

// Exact powers of ten.
constexpr double kPow10[] = {1e0,  1e1,  1e2,  1e3,  1e4,  1e5,  1e6,  1e7,  1e8,  1e9,  1e10, 1e11,
                             1e12, 1e13, 1e14, 1e15, 1e16, 1e17, 1e18, 1e19, 1e20, 1e21, 1e22};

NumberStatus parse_number(std::string_view text, double& value) {
  const size_t n = text.size();
  size_t i = 0;
  if (i < n && (text[i] == '+' || text[i] == '-')) ++i;
  size_t digits = 0;
  size_t frac_digits = 0;
  uint64_t mantissa = 0;  // the digits as an integer while it has at most 19 of them
  while (i < n && is_digit(text[i])) mantissa = mantissa * 10 + (text[i++] - '0'), ++digits;
  if (i < n && text[i] == '.') {
    ++i;
    while (i < n && is_digit(text[i]))
      mantissa = mantissa * 10 + (text[i++] - '0'), ++digits, ++frac_digits;
  }
  if (digits == 0) return NumberStatus::kInvalid;
  if (i == n && digits <= 15 && frac_digits <= 22) {
    // The common case, `12.3456`: the mantissa (< 10^15 < 2^53) and 10^k are exact doubles, so
    // one division is correctly rounded — the same value from_chars gives (Clinger's fast path).
    const double v = static_cast<double>(mantissa) / kPow10[frac_digits];
    value = text[0] == '-' ? -v : v;
    return NumberStatus::kOk;
  }
  if (i < n && (text[i] == 'e' || text[i] == 'E')) {
    ++i;
    if (i < n && (text[i] == '+' || text[i] == '-')) ++i;
    size_t exp_digits = 0;
    while (i < n && is_digit(text[i])) ++i, ++exp_digits;
    if (exp_digits == 0) return NumberStatus::kInvalid;
  }
  if (i != n) return NumberStatus::kInvalid;

  // from_chars takes no leading '+'.
  const char* first = text.data() + (text[0] == '+' ? 1 : 0);
  const char* last = text.data() + n;
  double v = 0;
  auto [ptr, ec] = std::from_chars(first, last, v, std::chars_format::general);
  if (ec == std::errc::result_out_of_range) return NumberStatus::kOutOfRange;
  if (ec != std::errc() || ptr != last) return NumberStatus::kInvalid;
  value = v;
  return NumberStatus::kOk;
}

bool looks_numeric(std::string_view text) {
  for (char c : text) {
    if (!(is_digit(c) || c == '.' || c == 'e' || c == 'E' || c == '+' || c == '-')) return false;
  }
  return true;
}

}  // namespace clpost::reader

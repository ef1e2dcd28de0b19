#include "writer/number_format.h"

#include <fmt/format.h>

#include <algorithm>
#include <charconv>
#include <cmath>
#include <cstdint>
#include <cstring>
#include <iterator>

namespace clpost {

bool number_format_detail::scaled_digits_slow(double v, double p, double t, uint64_t& q) {
  // t = v·p lies exactly on a half: which side the exact product lies on is its rounding
  // error, exactly.
  const double err = std::fma(v, p, -t);
  if (err == 0) return false;  // an exact tie (printf rounds it half to even): leave it to fmt
  if (err > 0) ++q;
  return true;
}

namespace {

using number_format_detail::scaled_digits;

constexpr char kDigitPairs[] =
    "00010203040506070809101112131415161718192021222324252627282930313233343536373839"
    "40414243444546474849505152535455565758596061626364656667686970717273747576777879"
    "8081828384858687888990919293949596979899";

// Puts the `n` lowest decimal digits of `q` (zeros included) before `p`, two at a time; `q`
// keeps the digits above them.
char* put_low_digits(char* p, uint64_t& q, int n) {
  for (; n >= 2; n -= 2, q /= 100)
    p = static_cast<char*>(std::memcpy(p - 2, kDigitPairs + 2 * (q % 100), 2));
  if (n > 0) *--p = static_cast<char>('0' + q % 10), q /= 10;
  return p;
}

// Writes q = |value|·10^decimals (rounded, q < 2^50) at `out` as format `f` says, built from
// the right in a small buffer: fraction digits (trailing zeros trimmed unless kept), the point,
// the whole digits. At most 19 characters; the copy moves a fixed 24 (a couple of moves, no
// library call), which put_number's room allows. Returns the end of the number.
char* put_scaled(char* out, uint64_t q, bool negative, const NumberFormat& f) {
  constexpr size_t kCopy = 24;
  char buf[2 * kCopy];
  char* const end = buf + kCopy;
  int nd = f.decimals;  // fraction digits written
  if (!f.trailing_zeros)
    while (nd > 0 && q % 10 == 0) q /= 10, --nd;
  char* p = put_low_digits(end, q, nd);
  if (nd > 0 || (f.decimals > 0 && f.decimal_point)) *--p = '.';
  if (q != 0) {
    while (q >= 10) p = put_low_digits(p, q, 2);
    if (q != 0) *--p = static_cast<char>('0' + q);
  } else if (f.leading_zero || nd == 0) {
    *--p = '0';
  }
  if (negative) *--p = '-';
  std::memset(end, 0, kCopy);  // what is copied past the number is defined
  std::memcpy(out, p, kCopy);
  return out + (end - p);
}

// The general path: fmt's digits, reshaped. Out of line, so that the hot path in
// put_number() needs no stack frame for fmt.
[[gnu::noinline]] char* put_with_fmt(char* out, double v, const NumberFormat& f) {
  fmt::memory_buffer buf;
  fmt::format_to(std::back_inserter(buf), "{:.{}f}", v, f.decimals);
  std::string_view s(buf.data(), buf.size());
  const bool negative = !s.empty() && s[0] == '-';
  if (negative) s.remove_prefix(1);
  // Whole and fractional digits.
  size_t dot = s.find('.');
  std::string_view whole = dot == std::string_view::npos ? s : s.substr(0, dot);
  std::string_view frac = dot == std::string_view::npos ? std::string_view() : s.substr(dot + 1);
  if (!f.trailing_zeros)
    while (!frac.empty() && frac.back() == '0') frac.remove_suffix(1);
  bool zero = whole.find_first_not_of('0') == std::string_view::npos &&
              frac.find_first_not_of('0') == std::string_view::npos;
  if (negative && !zero) *out++ = '-';
  if (f.leading_zero || whole != "0" || frac.empty())
    out = std::copy(whole.begin(), whole.end(), out);
  if (!frac.empty()) {
    *out++ = '.';
    out = std::copy(frac.begin(), frac.end(), out);
  } else if (f.decimals > 0 && f.decimal_point) {
    *out++ = '.';
  }
  return out;
}

}  // namespace

char* put_written(char* out, const WrittenNumber& w, const NumberFormat& f) {
  if (w.exact) return put_scaled(out, w.digits, w.negative, f);
  return put_with_fmt(out, w.value * f.scale, f);
}

char* put_number(char* out, double value, const NumberFormat& f) {
  return put_written(out, written(value, f), f);
}

void append_number(std::string& out, double value, const NumberFormat& f) {
  const size_t at = out.size();
  out.resize(at + max_number_chars(f));
  char* const end = put_number(out.data() + at, value, f);
  out.resize(static_cast<size_t>(end - out.data()));
}

}  // namespace clpost

#include "writer/number_format.h"

#include <fmt/format.h>

#include <charconv>
#include <cmath>
#include <cstdint>
#include <iterator>

namespace clpost {

namespace {

// 10^n, exact for every n here (powers of ten up to 1e22 are exact doubles).
constexpr double kPow10[] = {1e0,  1e1,  1e2,  1e3,  1e4,  1e5,  1e6,  1e7,  1e8,  1e9,  1e10, 1e11,
                             1e12, 1e13, 1e14, 1e15, 1e16, 1e17, 1e18, 1e19, 1e20, 1e21, 1e22};
constexpr uint64_t kPow10Int[] = {1ull,
                                  10ull,
                                  100ull,
                                  1000ull,
                                  10000ull,
                                  100000ull,
                                  1000000ull,
                                  10000000ull,
                                  100000000ull,
                                  1000000000ull,
                                  10000000000ull,
                                  100000000000ull,
                                  1000000000000ull,
                                  10000000000000ull,
                                  100000000000000ull,
                                  1000000000000000ull};

double pow10(int n) {
  return n >= 0 && n <= 22 ? kPow10[n] : std::pow(10.0, n);
}

// `v` (finite, >= 0) rounded to `decimals` digits as the integer v·10^decimals, exactly as
// printf/fmt round the exact binary value: false when the fast path cannot tell (an exact tie, or
// too large), and the caller formats with fmt.
bool scaled_digits(double v, int decimals, uint64_t& q) {
  if (decimals < 0 || decimals > 15) return false;
  const double p = kPow10[decimals];
  const double t = v * p;           // one rounding: |t - v·p| <= ulp(t)/2
  if (!(t < 0x1p50)) return false;  // ulp(t) <= 1/4: 0.5 lies on t's grid
  const double whole = std::floor(t);
  const double frac = t - whole;  // exact (Sterbenz)
  q = static_cast<uint64_t>(whole);
  if (frac > 0.5) {
    ++q;  // frac >= 0.5 + ulp: the exact value is above the half too
  } else if (frac == 0.5) {
    // Which side of the half the exact product lies on: its rounding error, exactly.
    const double err = std::fma(v, p, -t);
    if (err == 0) return false;  // an exact tie (printf rounds it half to even): leave it to fmt
    if (err > 0) ++q;
  }
  return true;
}

}  // namespace

double rounded(double value, const NumberFormat& f) {
  const double p = pow10(f.decimals);
  return std::round(value * f.scale * p) / p;
}

void append_number(std::string& out, double value, const NumberFormat& f) {
  const double v = value * f.scale;
  uint64_t q = 0;
  if (std::isfinite(v) && scaled_digits(std::fabs(v), f.decimals, q)) {
    // The hot path: what the general path below makes of fmt's digits, straight from q.
    const uint64_t p = kPow10Int[f.decimals];
    const uint64_t whole = q / p;
    uint64_t frac = q % p;
    int nd = f.decimals;  // fraction digits written
    if (!f.trailing_zeros)
      while (nd > 0 && frac % 10 == 0) frac /= 10, --nd;
    char buf[48];
    char* end = buf;
    if (std::signbit(v) && q != 0) *end++ = '-';
    if (f.leading_zero || whole != 0 || nd == 0) end = std::to_chars(end, buf + 24, whole).ptr;
    if (nd > 0) {
      *end++ = '.';
      for (int i = nd - 1; i >= 0; --i, frac /= 10) end[i] = static_cast<char>('0' + frac % 10);
      end += nd;
    } else if (f.decimals > 0 && f.decimal_point) {
      *end++ = '.';
    }
    out.append(buf, static_cast<size_t>(end - buf));
    return;
  }
  char buf[64];
  auto r = fmt::format_to_n(buf, sizeof buf, "{:.{}f}", v, f.decimals);
  std::string_view s(buf, std::min(r.size, sizeof buf));
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
  if (negative && !zero) out += '-';
  if (f.leading_zero || whole != "0" || frac.empty()) out.append(whole);
  if (!frac.empty()) {
    out += '.';
    out.append(frac);
  } else if (f.decimals > 0 && f.decimal_point) {
    out += '.';
  }
}

}  // namespace clpost

#include "writer/number_format.h"

#include <fmt/format.h>

#include <cmath>
#include <iterator>

namespace clpost {

double rounded(double value, const NumberFormat& f) {
  double p = std::pow(10.0, f.decimals);
  return std::round(value * f.scale * p) / p;
}

void append_number(std::string& out, double value, const NumberFormat& f) {
  char buf[64];
  auto r = fmt::format_to_n(buf, sizeof buf, "{:.{}f}", value * f.scale, f.decimals);
  size_t len = std::min(r.size, sizeof buf);
  std::string_view s(buf, len);
  bool negative = !s.empty() && s[0] == '-';
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

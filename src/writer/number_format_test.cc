#include "writer/number_format.h"

#include <fmt/format.h>
#include <gtest/gtest.h>

#include <cmath>
#include <cstdint>
#include <cstring>
#include <string>
#include <vector>

namespace clpost {
namespace {

TEST(NumberFormat, TrailingZerosTrimmedPointKept) {
  NumberFormat f;  // 3 decimals, no trailing zeros, decimal point, leading zero
  EXPECT_EQ(number_text(12.0, f), "12.");
  EXPECT_EQ(number_text(1.5, f), "1.5");
  EXPECT_EQ(number_text(0.25, f), "0.25");
  EXPECT_EQ(number_text(-0.25, f), "-0.25");
  EXPECT_EQ(number_text(0, f), "0.");
}

TEST(NumberFormat, RoundsAndNeverWritesNegativeZero) {
  NumberFormat f;
  EXPECT_EQ(number_text(1.23456, f), "1.235");
  EXPECT_EQ(number_text(-0.0004, f), "0.");  // rounds to zero: no "-0."
  EXPECT_EQ(number_text(-0.0005000001, f), "-0.001");
  EXPECT_EQ(number_text(39.99999999, f), "40.");
}

TEST(NumberFormat, VariantsFromMachineFiles) {
  NumberFormat trailing{3, true, true, true, 1};
  EXPECT_EQ(number_text(1.5, trailing), "1.500");
  NumberFormat no_point{3, false, false, true, 1};
  EXPECT_EQ(number_text(12.0, no_point), "12");
  NumberFormat no_lead{3, false, true, false, 1};
  EXPECT_EQ(number_text(0.5, no_lead), ".5");
  EXPECT_EQ(number_text(-0.5, no_lead), "-.5");
  EXPECT_EQ(number_text(0, no_lead), "0.");
  NumberFormat integer{0, false, true, true, 1};
  EXPECT_EQ(number_text(1199.6, integer), "1200");
  NumberFormat micrometres{0, false, false, true, 1000};  // Fanuc G76 Q in least increments
  EXPECT_EQ(number_text(0.15, micrometres), "150");
}

// append_number before its hand-made fast path: every digit from fmt's "{:.{}f}".
std::string reference(double value, const NumberFormat& f) {
  char buf[64];
  auto r = fmt::format_to_n(buf, sizeof buf, "{:.{}f}", value * f.scale, f.decimals);
  std::string_view s(buf, std::min(r.size, sizeof buf));
  bool negative = !s.empty() && s[0] == '-';
  if (negative) s.remove_prefix(1);
  size_t dot = s.find('.');
  std::string_view whole = dot == std::string_view::npos ? s : s.substr(0, dot);
  std::string_view frac = dot == std::string_view::npos ? std::string_view() : s.substr(dot + 1);
  if (!f.trailing_zeros)
    while (!frac.empty() && frac.back() == '0') frac.remove_suffix(1);
  bool zero = whole.find_first_not_of('0') == std::string_view::npos &&
              frac.find_first_not_of('0') == std::string_view::npos;
  std::string out;
  if (negative && !zero) out += '-';
  if (f.leading_zero || whole != "0" || frac.empty()) out.append(whole);
  if (!frac.empty()) {
    out += '.';
    out.append(frac);
  } else if (f.decimals > 0 && f.decimal_point) {
    out += '.';
  }
  return out;
}

TEST(NumberFormat, SameDigitsAsFmtEverywhere) {
  // Halves at the rounding digit (exact ties and near ties), CL-style 4-decimal values written
  // with 3 decimals, large and tiny values, every format variant.
  std::vector<double> values = {
      0.5,    1.5,     2.5,       0.0005,        1.0005,      1.0865,       2.0865, 0.125,  0.375,
      -0.125, -2.5,    1e-9,      -1e-9,         123456.7895, 1e15,         -1e16,  4.5e17, 0.0,
      -0.0,   99.9995, 0.1 + 0.2, 1.00049999999, 37.9125 * 2, -82.04599999, 2.675,  1.005,  1.115};
  uint64_t x = 88172645463325252ull;  // xorshift64: deterministic
  for (int i = 0; i < 200000; ++i) {
    x ^= x << 13, x ^= x >> 7, x ^= x << 17;
    const double scale = std::pow(10.0, static_cast<int>(x % 7)) / 1000.0;
    const double v = (static_cast<double>(x >> 11) / 9007199254740992.0 - 0.5) * 2000.0 * scale;
    values.push_back(v);
    values.push_back(std::round(v * 1e4) / 1e4);  // 4 decimals, like CL files
    values.push_back(std::round(v * 2e3) / 2e3);  // ties at the third decimal
  }
  for (int decimals : {0, 1, 2, 3, 4, 6}) {
    for (bool trailing : {false, true}) {
      for (bool lead : {false, true}) {
        NumberFormat f{decimals, trailing, !trailing, lead, decimals == 0 ? 1000.0 : 1.0};
        for (double v : values)
          ASSERT_EQ(number_text(v, f), reference(v, f)) << v << " " << decimals;
      }
    }
  }
}

// same_text() is what modal suppression asks: whether two values are written alike. It must
// agree with the text itself, near halves above all (0.0055 is written 0.005: its exact binary
// value lies below the half, though 0.0055 · 1000 rounds to 5.5).
TEST(NumberFormat, SameTextIsTheSameText) {
  NumberFormat f;
  std::vector<double> values = {0.0, -0.0, 0.0055, 0.005, 0.006, -0.0004, 1.0005, 1.001, 2.5, 0.5};
  uint64_t x = 0x2545F4914F6CDD1Dull;
  for (int i = 0; i < 20000; ++i) {
    x ^= x << 13, x ^= x >> 7, x ^= x << 17;
    const double v = (static_cast<double>(x >> 11) / 9007199254740992.0 - 0.5) * 20;
    values.push_back(std::round(v * 2e3) / 2e3);  // halves at the third decimal
    values.push_back(std::round(v * 1e4) / 1e4);  // 4 decimals, like CL files
  }
  for (int decimals : {0, 3}) {
    NumberFormat g{decimals, false, true, true, 1};
    for (size_t i = 1; i < values.size(); ++i) {
      const double a = values[i - 1], b = values[i];
      const WrittenNumber wa = written(a, g), wb = written(b, g);
      if (wa.exact && wb.exact) {
        ASSERT_EQ(same_text(wa, wb), reference(a, g) == reference(b, g)) << a << " " << b;
      } else {
        // An exact tie is written again, unless it is the very same value.
        ASSERT_EQ(same_text(wa, wb), a == b) << a << " " << b;
      }
    }
  }
  EXPECT_FALSE(written(2.5, NumberFormat{0, false, true, true, 1}).exact);  // a true tie: fmt
  EXPECT_FALSE(written(NAN, f).exact);
  EXPECT_FALSE(written(1e300, f).exact);
  const WrittenNumber w = written(-0.0004, f);  // rounds to zero: no "-0."
  EXPECT_TRUE(w.exact);
  EXPECT_EQ(w.digits, 0u);
  EXPECT_FALSE(w.negative);
  EXPECT_EQ(written(0.0055, f).digits, 5u);
  NumberFormat micrometres{0, false, false, true, 1000};
  EXPECT_EQ(written(0.1504, micrometres).digits, 150u);
}

TEST(NumberFormat, HugeValuesAreWrittenWhole) {
  // fmt's digits of the exact binary value: 101 whole digits, then the point (a 64-character
  // buffer used to cut them short).
  NumberFormat f;
  EXPECT_EQ(number_text(1e100, f),
            "10000000000000000159028911097599180468360808563945281389781327557747838772170381060"
            "813469985856815104.");
  EXPECT_EQ(number_text(-1.7976931348623157e308, f).size(), 1u + 309u + 1u);
  NumberFormat nine{9, true, true, true, 1};
  EXPECT_EQ(number_text(-1.7976931348623157e308, nine).size(), 1u + 309u + 1u + 9u);
  EXPECT_LE(1u + 309u + 1u + 9u, max_number_chars(nine));
}

TEST(NumberFormat, PutNumberWritesInPlaceAndReturnsTheEnd) {
  // The longest fast-path number (sign, whole digits, point, 9 decimals) and a short one, each
  // written into a buffer full of '#': the characters after the returned end are not part of it.
  NumberFormat nine{9, true, true, true, 1};
  std::string buf(max_number_chars(nine) + 8, '#');
  char* end = put_number(buf.data() + 3, -999999.123456789, nine);
  EXPECT_EQ(std::string(buf.data(), end), "###-999999.123456789");
  end = put_number(buf.data(), 0.25, NumberFormat{});
  EXPECT_EQ(std::string(buf.data(), end), "0.25");
}

TEST(NumberFormat, NotFiniteValuesAsFmtWritesThem) {
  NumberFormat f;
  EXPECT_EQ(number_text(INFINITY, f), reference(INFINITY, f));
  EXPECT_EQ(number_text(-INFINITY, f), reference(-INFINITY, f));
  EXPECT_EQ(number_text(NAN, f), reference(NAN, f));
}

}  // namespace
}  // namespace clpost

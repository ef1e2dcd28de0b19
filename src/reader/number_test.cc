#include "reader/number.h"

#include <gtest/gtest.h>

#include <bit>
#include <charconv>
#include <cstdint>
#include <string>

namespace clpost::reader {
namespace {

double parsed(std::string_view text) {
  double v = -12345;
  EXPECT_EQ(parse_number(text, v), NumberStatus::kOk) << text;
  return v;
}

TEST(Number, AptForms) {
  EXPECT_EQ(parsed("1."), 1.0);
  EXPECT_EQ(parsed(".5"), 0.5);
  EXPECT_EQ(parsed("-0.5"), -0.5);
  EXPECT_EQ(parsed("+2"), 2.0);
  EXPECT_EQ(parsed("1E3"), 1000.0);
  EXPECT_EQ(parsed("1.5e-3"), 0.0015);
  EXPECT_EQ(parsed("-.5"), -0.5);
  EXPECT_EQ(parsed("5.e+2"), 500.0);
  EXPECT_EQ(parsed("0"), 0.0);
  EXPECT_EQ(parsed("-7.2290790757"), -7.2290790757);
}

TEST(Number, Invalid) {
  for (std::string_view bad :
       {"1.2.3", "--1",   "+-1", "1e",  "1e+", "1E-",  ".",   "-",    "+",  "-.", "e5",
        ".e5",   "1e5.0", "1-",  "1..", "inf", "-inf", "nan", "0x10", "1 ", ""}) {
    double v = 42;
    EXPECT_EQ(parse_number(bad, v), NumberStatus::kInvalid) << bad;
    EXPECT_EQ(v, 42) << bad;
  }
}

TEST(Number, OutOfRange) {
  double v = 0;
  EXPECT_EQ(parse_number("1e400", v), NumberStatus::kOutOfRange);
  EXPECT_EQ(parse_number("-1e400", v), NumberStatus::kOutOfRange);
  EXPECT_EQ(parse_number("1e-400", v), NumberStatus::kOutOfRange);
  EXPECT_EQ(parse_number("1e308", v), NumberStatus::kOk);
  EXPECT_EQ(v, 1e308);
}

TEST(Number, LooksNumeric) {
  EXPECT_TRUE(looks_numeric("1.2.3"));
  EXPECT_TRUE(looks_numeric("--1"));
  EXPECT_TRUE(looks_numeric("1e"));
  EXPECT_FALSE(looks_numeric("10_SVERL_63_N2"));
  EXPECT_FALSE(looks_numeric("1ST"));
  EXPECT_FALSE(looks_numeric("nan"));
}

TEST(Number, SameValueAsFromCharsForEveryPlainDecimal) {
  // Plain decimals take a fast path (mantissa / 10^k); it must agree with from_chars bit for bit.
  uint64_t x = 0x9E3779B97F4A7C15ull;
  for (int i = 0; i < 300000; ++i) {
    x ^= x << 13, x ^= x >> 7, x ^= x << 17;
    const int whole_digits = static_cast<int>(x % 9);
    const int frac_digits = static_cast<int>((x >> 8) % 12);
    std::string text = (x >> 20) % 2 ? "-" : "";
    uint64_t d = x >> 24;
    for (int k = 0; k < whole_digits; ++k, d /= 10) text += static_cast<char>('0' + d % 10);
    text += '.';
    for (int k = 0; k < frac_digits; ++k, d /= 7) text += static_cast<char>('0' + d % 10);
    if (whole_digits + frac_digits == 0) text += '5';
    double expected = 0;
    const char* first = text.data();
    std::from_chars(first, text.data() + text.size(), expected);
    double v = 0;
    ASSERT_EQ(parse_number(text, v), NumberStatus::kOk) << text;
    ASSERT_EQ(std::bit_cast<uint64_t>(v), std::bit_cast<uint64_t>(expected)) << text;
  }
  for (std::string_view text : {"0.1", "-0.0", "-0.0000", "37.9125", "999999999999999.9",
                                "0.000000000000000000001", "123456789012345", "1234567890123456"}) {
    double expected = 0, v = 0;
    std::from_chars(text.data(), text.data() + text.size(), expected);
    ASSERT_EQ(parse_number(text, v), NumberStatus::kOk) << text;
    EXPECT_EQ(std::bit_cast<uint64_t>(v), std::bit_cast<uint64_t>(expected)) << text;
  }
}

}  // namespace
}  // namespace clpost::reader

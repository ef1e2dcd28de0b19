#include "reader/number.h"

#include <gtest/gtest.h>

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

}  // namespace
}  // namespace clpost::reader

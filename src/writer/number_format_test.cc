#include "writer/number_format.h"

#include <gtest/gtest.h>

namespace clpost {
namespace {

std::string fmt_num(double v, NumberFormat f) {
  std::string s;
  append_number(s, v, f);
  return s;
}

TEST(NumberFormat, TrailingZerosTrimmedPointKept) {
  NumberFormat f;  // 3 decimals, no trailing zeros, decimal point, leading zero
  EXPECT_EQ(fmt_num(12.0, f), "12.");
  EXPECT_EQ(fmt_num(1.5, f), "1.5");
  EXPECT_EQ(fmt_num(0.25, f), "0.25");
  EXPECT_EQ(fmt_num(-0.25, f), "-0.25");
  EXPECT_EQ(fmt_num(0, f), "0.");
}

TEST(NumberFormat, RoundsAndNeverWritesNegativeZero) {
  NumberFormat f;
  EXPECT_EQ(fmt_num(1.23456, f), "1.235");
  EXPECT_EQ(fmt_num(-0.0004, f), "0.");  // rounds to zero: no "-0."
  EXPECT_EQ(fmt_num(-0.0005000001, f), "-0.001");
  EXPECT_EQ(fmt_num(39.99999999, f), "40.");
}

TEST(NumberFormat, VariantsFromMachineFiles) {
  NumberFormat trailing{3, true, true, true, 1};
  EXPECT_EQ(fmt_num(1.5, trailing), "1.500");
  NumberFormat no_point{3, false, false, true, 1};
  EXPECT_EQ(fmt_num(12.0, no_point), "12");
  NumberFormat no_lead{3, false, true, false, 1};
  EXPECT_EQ(fmt_num(0.5, no_lead), ".5");
  EXPECT_EQ(fmt_num(-0.5, no_lead), "-.5");
  EXPECT_EQ(fmt_num(0, no_lead), "0.");
  NumberFormat integer{0, false, true, true, 1};
  EXPECT_EQ(fmt_num(1199.6, integer), "1200");
  NumberFormat micrometres{0, false, false, true, 1000};  // Fanuc G76 Q in least increments
  EXPECT_EQ(fmt_num(0.15, micrometres), "150");
}

TEST(NumberFormat, RoundedMatchesWhatIsWritten) {
  NumberFormat f;
  EXPECT_DOUBLE_EQ(rounded(1.23456, f), 1.235);
  NumberFormat micrometres{0, false, false, true, 1000};
  EXPECT_DOUBLE_EQ(rounded(0.1504, micrometres), 150);
}

}  // namespace
}  // namespace clpost

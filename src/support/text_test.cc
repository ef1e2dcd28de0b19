#include "support/text.h"

#include <gtest/gtest.h>

namespace clpost {
namespace {

static_assert(is_digit('0') && is_digit('9') && !is_digit('a') && !is_digit('/'));
static_assert(!is_digit(':') && !is_digit(static_cast<char>(0xb2)));  // no locale's superscript 2

TEST(Text, TrimDropsBlanksAtBothEnds) {
  EXPECT_EQ(trim(" \tG1 X5\t "), "G1 X5");
  EXPECT_EQ(trim("  "), "");
  EXPECT_EQ(trim(""), "");
  EXPECT_EQ(trim("a\r"), "a\r");  // a CR is no blank
}

TEST(Text, TrimDropsTheExtraCharactersOnlyAtTheEnd) {
  EXPECT_EQ(trim(" a \r \r", "\r"), "a");
  EXPECT_EQ(trim("\r a", "\r"), "\r a");  // leading: blanks only
  EXPECT_EQ(trim(" \r ", "\r"), "");
}

}  // namespace
}  // namespace clpost

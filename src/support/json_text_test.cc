#include "support/json_text.h"

#include <gtest/gtest.h>

namespace clpost {
namespace {

TEST(JsonText, EscapesQuotesControlsAndBadUtf8) {
  EXPECT_EQ(json_string("a\"b\\c"), "\"a\\\"b\\\\c\"");
  EXPECT_EQ(json_string("l1\nl2\r\t"), "\"l1\\nl2\\r\\t\"");
  EXPECT_EQ(json_string(std::string_view("\x01\x7f", 2)), "\"\\u0001\\u007f\"");
  EXPECT_EQ(json_string("M\xc3\xa9tal"), "\"M\xc3\xa9tal\"");  // valid UTF-8 kept
  EXPECT_EQ(json_string("\xff\xc3"), "\"\\ufffd\\ufffd\"");    // invalid bytes replaced
}

}  // namespace
}  // namespace clpost

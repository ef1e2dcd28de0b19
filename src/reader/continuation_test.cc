#include "reader/continuation.h"

#include <gtest/gtest.h>

#include <string>

namespace clpost::reader {
namespace {

TEST(Continuation, CodePart) {
  bool c = true;
  EXPECT_EQ(code_part("GOTO/1,2,3", &c), "GOTO/1,2,3");
  EXPECT_FALSE(c);
  EXPECT_EQ(code_part("CIRCLE / 1, 2,  $", &c), "CIRCLE / 1, 2,  ");
  EXPECT_TRUE(c);
  EXPECT_EQ(code_part("FINCUT, 3,$", &c), "FINCUT, 3,");
  EXPECT_TRUE(c);
  EXPECT_EQ(code_part("LOADTL / 4,  OSETNO,  4 $$-> THREAD TOOL $", &c), "LOADTL / 4,  OSETNO,  4");
  EXPECT_FALSE(c);
  EXPECT_EQ(code_part("GOTO/1,$ $$ note", &c), "GOTO/1,");
  EXPECT_TRUE(c);
  EXPECT_EQ(code_part("GOTO/1,$$", &c), "GOTO/1,");
  EXPECT_FALSE(c);
  EXPECT_EQ(code_part("$$ comment", &c), "");
  EXPECT_FALSE(c);
  EXPECT_EQ(code_part("$", &c), "");
  EXPECT_TRUE(c);
  EXPECT_EQ(code_part("", &c), "");
  EXPECT_FALSE(c);
}

TEST(Continuation, DoubleDollarInQuotesIsNotAComment) {
  bool c = true;
  EXPECT_EQ(code_part("SYN/'TLAXIS','$$*TLAXIS'", &c), "SYN/'TLAXIS','$$*TLAXIS'");
  EXPECT_FALSE(c);
  EXPECT_EQ(code_part("SYN/'A', \"$$\" $$ note $", &c), "SYN/'A', \"$$\"");
  EXPECT_FALSE(c);
  EXPECT_EQ(code_part("SYN/'A$$B',$", &c), "SYN/'A$$B',");
  EXPECT_TRUE(c);
  // A quote inside a word opens nothing: the `$$` after it starts a comment.
  EXPECT_EQ(code_part("PART_OPE/Phase d'usinage $$ note '", &c), "PART_OPE/Phase d'usinage");
  EXPECT_FALSE(c);
  // An open quote at the end of a line continued with `$` (CATIA wraps long text).
  EXPECT_EQ(code_part("TPRINT/'Turning Tool $", &c), "TPRINT/'Turning Tool ");
  EXPECT_TRUE(c);
}

TEST(Continuation, CommentContinues) {
  EXPECT_TRUE(comment_continues("$$-> CSYS / 1.0, 0.0,  $"));
  EXPECT_TRUE(comment_continues("            0.0, 1.0, $\t "));
  EXPECT_FALSE(comment_continues("            0.0, 1.0"));
  EXPECT_FALSE(comment_continues("$$-> END / "));
  EXPECT_FALSE(comment_continues("$$"));
  EXPECT_FALSE(comment_continues("$$$$$$$$$$"));
  EXPECT_TRUE(comment_continues("$$ a $"));
  EXPECT_FALSE(comment_continues("$$ a $$"));
}

TEST(Continuation, Lines) {
  EXPECT_TRUE(is_blank_line(""));
  EXPECT_TRUE(is_blank_line(" \t "));
  EXPECT_FALSE(is_blank_line(" x"));
  EXPECT_TRUE(is_comment_line("  $$ x"));
  EXPECT_TRUE(is_comment_line("$$"));
  EXPECT_FALSE(is_comment_line("$ $"));
  EXPECT_FALSE(is_comment_line("GOTO/1 $$ x"));
}

// The streaming form must agree with the in-memory form on every line, however it is cut.
TEST(Continuation, LineTailAgreesWithWholeLine) {
  const std::string alphabet = "$ a,\t'/";
  constexpr int kSize = 7;
  std::string line;
  for (int n = 0; n < kSize * kSize * kSize * kSize * kSize * kSize; ++n) {
    line.clear();
    for (int k = n, i = 0; i < 6; ++i, k /= kSize) line += alphabet[k % kSize];
    bool code = false;
    code_part(line, &code);
    const bool comment = comment_continues(line);
    for (size_t cut = 0; cut <= line.size(); ++cut) {
      LineTail tail;
      tail.feed(std::string_view(line).substr(0, cut));
      tail.feed(std::string_view(line).substr(cut));
      EXPECT_EQ(tail.code_continues(), code) << '"' << line << '"' << cut;
      EXPECT_EQ(tail.comment_continues(), comment) << '"' << line << '"' << cut;
    }
  }
}

}  // namespace
}  // namespace clpost::reader

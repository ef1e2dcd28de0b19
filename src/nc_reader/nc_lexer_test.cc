#include "nc_reader/nc_lexer.h"

#include <gtest/gtest.h>

namespace clpost {
namespace {

NcSyntax fanuc() {
  return NcSyntax{"N", "(", ")"};
}
NcSyntax siemens() {
  return NcSyntax{"N", "; ", ""};
}
NcSyntax heidenhain() {
  return NcSyntax{"N ", "[", "]"};
}

NcBlock lex(std::string_view line, const NcSyntax& s) {
  NcBlock b;
  NcLexError e;
  EXPECT_TRUE(lex_nc_line(line, 7, s, b, e)) << e.col << ": " << e.message;
  return b;
}

std::string lex_error(std::string_view line, const NcSyntax& s) {
  NcBlock b;
  NcLexError e;
  EXPECT_FALSE(lex_nc_line(line, 7, s, b, e)) << line;
  return std::to_string(e.col) + ": " + e.message;
}

// LinuxCNC's spindle number (M3 $1 S2000: the live tool of linuxcnc-lathe-c) is a word.
TEST(NcLexer, LinuxcncSpindleNumber) {
  NcBlock b = lex("M3 $1 S2000", fanuc());
  ASSERT_EQ(b.words.size(), 3u);
  EXPECT_EQ(b.words[1].address, "$");
  EXPECT_EQ(b.words[1].value, 1);
  EXPECT_EQ(b.words[1].col, 4u);
  EXPECT_EQ(lex_error("M5 $", fanuc()), "4: '$' has no value");
}

TEST(NcLexer, WordsAfterTheBlockNumber) {
  NcBlock b = lex("N200 G76 X14.16 Z-20. P920 Q376 F1.5", fanuc());
  ASSERT_EQ(b.words.size(), 6u);
  EXPECT_EQ(b.line, 7u);
  EXPECT_EQ(b.words[0].address, "G");
  EXPECT_EQ(b.words[0].value, 76);
  EXPECT_EQ(b.words[0].col, 6u);
  EXPECT_EQ(b.words[2].address, "Z");
  EXPECT_EQ(b.words[2].text, "-20.");
  EXPECT_EQ(b.words[2].value, -20);
  EXPECT_EQ(b.words[3].text, "920");
  EXPECT_DOUBLE_EQ(b.words[5].value, 1.5);
  EXPECT_EQ(b.find("Q")->value, 376);
  EXPECT_EQ(b.find("U"), nullptr);
}

TEST(NcLexer, KeepsLeadingZerosInTheText) {
  NcBlock b = lex("N190 G76 P010060 Q100 R0.081", fanuc());
  EXPECT_EQ(b.find("P")->text, "010060");
  EXPECT_EQ(b.find("P")->value, 10060);
}

TEST(NcLexer, UnspacedWordsAndLowerCase) {
  NcBlock b = lex("g0x20.z5", fanuc());
  ASSERT_EQ(b.words.size(), 3u);
  EXPECT_EQ(b.words[1].address, "X");
  EXPECT_EQ(b.words[1].value, 20);
  EXPECT_EQ(b.words[2].address, "Z");
  EXPECT_EQ(b.words[2].col, 7u);
}

TEST(NcLexer, CommentsInParenthesesAnywhere) {
  NcBlock b = lex("N70 (THREAD LINE 12: 5 PASSES) G0 X1 (END)", fanuc());
  ASSERT_EQ(b.comments.size(), 2u);
  EXPECT_EQ(b.comments[0], "THREAD LINE 12: 5 PASSES");
  EXPECT_EQ(b.comments[1], "END");
  ASSERT_EQ(b.words.size(), 2u);
}

TEST(NcLexer, SiemensSemicolonCommentsEqualsWordsAndBareWords) {
  NcBlock b = lex("N370 G33 Z-29.469 K3 SF=180 ; start 2", siemens());
  ASSERT_EQ(b.words.size(), 4u);
  EXPECT_EQ(b.words[3].address, "SF=");
  EXPECT_EQ(b.words[3].value, 180);
  ASSERT_EQ(b.comments.size(), 1u);
  EXPECT_EQ(b.comments[0], "start 2");
  NcBlock d = lex("N10 G18 G71 G40 G90 DIAMON", siemens());
  ASSERT_EQ(d.words.size(), 5u);
  EXPECT_EQ(d.words[4].address, "DIAMON");
  EXPECT_FALSE(d.words[4].has_value());
  EXPECT_EQ(lex(";comment without a blank", siemens()).comments[0], "comment without a blank");
}

TEST(NcLexer, CallsWithTheirArgumentsAndColumns) {
  NcBlock b = lex("N60 CYCLE99(0, 24, -25, \"a, b\", , 1.299)", siemens());
  ASSERT_EQ(b.calls.size(), 1u);
  const NcCall& c = b.calls[0];
  EXPECT_EQ(c.name, "CYCLE99");
  EXPECT_EQ(c.col, 5u);
  ASSERT_EQ(c.args.size(), 6u);
  EXPECT_EQ(c.args[2], "-25");
  EXPECT_EQ(c.args[3], "\"a, b\"");
  EXPECT_EQ(c.args[4], "");
  EXPECT_EQ(c.args[5], "1.299");
  EXPECT_EQ(c.cols[1], 16u);
}

TEST(NcLexer, HeidenhainBlockNumbersWithABlankAndTwoLetterAddresses) {
  NcBlock b = lex("N 250 G31 F1.5 U0.92 IC6 V0 H1 A30 D1 Q0 C0 BD0 B0 P0 K0", heidenhain());
  ASSERT_EQ(b.words.size(), 14u);
  EXPECT_EQ(b.words[0].address, "G");
  EXPECT_EQ(b.find("IC")->value, 6);
  EXPECT_EQ(b.find("BD")->value, 0);
  EXPECT_EQ(lex("[METRIC]", heidenhain()).comments[0], "METRIC");
}

TEST(NcLexer, IsoCommentsInAnotherDialect) {
  NcBlock b = lex("N 180 M19 (orient spindle) [note]", heidenhain());
  ASSERT_EQ(b.comments.size(), 2u);
  EXPECT_EQ(b.comments[0], "orient spindle");
  EXPECT_EQ(b.comments[1], "note");
  ASSERT_EQ(b.words.size(), 1u);
}

TEST(NcLexer, ProgramDelimiters) {
  EXPECT_TRUE(lex("%", fanuc()).program_delimiter);
  EXPECT_TRUE(lex("%1.nc", heidenhain()).program_delimiter);
  EXPECT_FALSE(lex("O0001", fanuc()).program_delimiter);
}

// The block's one-letter addresses, a bit each, for the look-ups that a block without the letter
// answers at once; the words of longer addresses (IC, DIAMON) go through the words.
TEST(NcLexer, OneLetterAddressesAsBits) {
  NcBlock b = lex("N10 g1 X5 IC3 DIAMON Z-1 (Y2)", siemens());
  EXPECT_EQ(b.letters,
            NcBlock::letter_bit("G") | NcBlock::letter_bit("X") | NcBlock::letter_bit("Z"));
  EXPECT_EQ(NcBlock::letter_bit("G"), 1u << 6);
  EXPECT_EQ(NcBlock::letter_bit("IC"), 0u);
  EXPECT_EQ(b.find("Z")->value, -1);
  EXPECT_EQ(b.find("IC")->value, 3);
  EXPECT_NE(b.find("DIAMON"), nullptr);
  EXPECT_EQ(b.find("Y"), nullptr);
  EXPECT_EQ(b.find("N"), nullptr);
  // The next block read into it keeps none of these.
  NcLexError e;
  ASSERT_TRUE(lex_nc_line("M3", 8, siemens(), b, e));
  EXPECT_EQ(b.letters, NcBlock::letter_bit("M"));
  EXPECT_EQ(b.find("X"), nullptr);
}

TEST(NcLexer, CarriageReturnAndTrailingBlanks) {
  NcBlock b = lex("G1 X5 \r", fanuc());
  ASSERT_EQ(b.words.size(), 2u);
  EXPECT_EQ(b.words[1].text, "5");
}

TEST(NcLexer, ErrorsNameTheColumnAndTheText) {
  EXPECT_EQ(lex_error("G1 X1.2.3 Z0", fanuc()), "4: invalid number 'X1.2.3'");
  EXPECT_EQ(lex_error("G1 X-- Z0", fanuc()), "4: invalid number 'X--'");
  EXPECT_EQ(lex_error("G1 X1 (open", fanuc()), "7: comment has no closing ')'");
  EXPECT_EQ(lex_error("CYCLE99(1, 2", siemens()), "1: 'CYCLE99(' has no closing ')'");
  EXPECT_EQ(lex_error("G1 #1=5", fanuc()), "4: unexpected '#'");
  EXPECT_EQ(lex_error("SF= Z1", siemens()), "1: 'SF=' has no value");
  // A word in error is not left in the block.
  NcBlock b;
  NcLexError e;
  EXPECT_FALSE(lex_nc_line("G1 X1.2.3", 7, fanuc(), b, e));
  ASSERT_EQ(b.words.size(), 1u);
  EXPECT_EQ(b.words[0].address, "G");
}

}  // namespace
}  // namespace clpost

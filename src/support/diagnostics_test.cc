#include "support/diagnostics.h"

#include <gtest/gtest.h>

#include <string>

namespace clpost {
namespace {

std::string only(const Diagnostics& d) {
  EXPECT_EQ(d.kept().size(), 1u);
  return d.kept().empty() ? "" : d.render(d.kept().front());
}

TEST(Diagnostics, LineColumnTextAndCaret) {
  Diagnostics d("part.apt");
  d.error({3, 7}, "GOTO/1,,3", "empty argument");
  EXPECT_EQ(only(d),
            "part.apt:3:7: error: empty argument\n"
            "  GOTO/1,,3\n"
            "        ^\n");
  EXPECT_EQ(d.error_count(), 1u);
  EXPECT_TRUE(d.has_errors());
}

TEST(Diagnostics, WithoutColumnThereIsNoCaret) {
  Diagnostics d("part.apt");
  d.warning({12, 0}, "FINI", "text after FINI");
  EXPECT_EQ(only(d),
            "part.apt:12: warning: text after FINI\n"
            "  FINI\n");
  EXPECT_EQ(d.warning_count(), 1u);
  EXPECT_FALSE(d.has_errors());
}

TEST(Diagnostics, WithoutLineOnlyTheFileIsNamed) {
  Diagnostics d("part.apt");
  d.warning({}, "", "no FINI at the end of the file");
  EXPECT_EQ(only(d), "part.apt: warning: no FINI at the end of the file\n");
}

TEST(Diagnostics, TabsStayTabsUnderTheCaretAndLineEndsBecomeSpaces) {
  Diagnostics d("m.yaml");
  d.error({1, 4}, "\tab\r", "here");
  EXPECT_EQ(only(d),
            "m.yaml:1:4: error: here\n"
            "  \tab \n"
            "  \t  ^\n");
}

TEST(Diagnostics, AColumnPastTheEndPutsTheCaretAfterTheText) {
  Diagnostics d("m.yaml");
  d.error({2, 9}, "ab", "unexpected end");
  EXPECT_EQ(only(d),
            "m.yaml:2:9: error: unexpected end\n"
            "  ab\n"
            "    ^\n");
}

TEST(Diagnostics, StrictTurnsWarningsIntoErrors) {
  Diagnostics d("part.apt");
  d.set_warnings_are_errors(true);
  d.warning({5, 1}, "FOO/1", "unknown statement 'FOO'");
  EXPECT_EQ(d.error_count(), 1u);
  EXPECT_EQ(d.warning_count(), 0u);
  EXPECT_EQ(only(d),
            "part.apt:5:1: error: unknown statement 'FOO'\n"
            "  FOO/1\n"
            "  ^\n");
}

TEST(Diagnostics, OnlyTheFirst200AreKeptButAllAreCounted) {
  Diagnostics d("part.apt");
  for (uint32_t i = 1; i <= 205; ++i) d.error({i, 1}, "X", "bad");
  EXPECT_EQ(d.kept().size(), Diagnostics::kMaxKept);
  EXPECT_EQ(d.dropped(), 5u);
  EXPECT_EQ(d.error_count(), 205u);
  const std::string all = d.render_all();
  EXPECT_TRUE(all.starts_with("part.apt:1:1: error: bad\n  X\n  ^\npart.apt:2:1: error: bad\n"));
  EXPECT_TRUE(
      all.ends_with("part.apt:200:1: error: bad\n  X\n  ^\n"
                    "part.apt: note: 5 more diagnostics not shown\n"));
}

// A long line keeps 200 characters: from its start when the column is near it...
TEST(Diagnostics, ALongLineIsCutAfterAWindowFromItsStart) {
  Diagnostics d("big.apt");
  d.error({1, 5}, std::string(1000, 'a'), "bad");
  EXPECT_EQ(only(d), "big.apt:1:5: error: bad\n  " + std::string(200, 'a') + "...\n" + "      ^\n");
}

// ...else around the column, 80 characters before it, so the caret points at the right text.
TEST(Diagnostics, ALongLineKeepsAWindowAroundAFarColumn) {
  Diagnostics d("big.apt");
  const std::string line = std::string(499, 'a') + 'X' + std::string(500, 'b');
  d.error({1, 500}, line, "bad");
  ASSERT_EQ(d.kept().size(), 1u);
  EXPECT_EQ(d.kept()[0].first_col, 420u);  // 500 - 80
  EXPECT_EQ(only(d),
            "big.apt:1:500: error: bad\n"
            "  ..." +
                std::string(80, 'a') + 'X' + std::string(119, 'b') + "...\n" + "     " +
                std::string(80, ' ') + "^\n");
}

// A column at the very end of a long line shows the line's last 200 characters, not cut after.
TEST(Diagnostics, ALongLineShowsItsEndForAColumnAtTheEnd) {
  Diagnostics d("big.apt");
  d.error({1, 1001}, std::string(800, 'a') + std::string(200, 'z'), "unexpected end of line");
  EXPECT_EQ(only(d),
            "big.apt:1:1001: error: unexpected end of line\n"
            "  ..." +
                std::string(200, 'z') + "\n" + "     " + std::string(200, ' ') + "^\n");
}

// Binary input (a CLDATA file): record and byte, the record's APT text without a caret, a long
// one cut at its start's first 200 characters whatever the byte offset.
TEST(Diagnostics, BinaryRecordsRenderRecordAndByte) {
  Diagnostics d("part.tap");
  d.set_binary_records(true);
  d.error(SourceLoc{22, 761}, "CUTCOM/LENGTH,1", "unknown CUTCOM word 'LENGTH'");
  d.note(SourceLoc{64, 0}, {}, "1 bytes after FINI ignored");
  d.warning(SourceLoc{}, {}, "no place");
  d.error(SourceLoc{3, 5000}, "PPRINT " + std::string(300, 'x'), "long");
  EXPECT_EQ(d.render_all(),
            "part.tap: record 22 (byte 760): error: unknown CUTCOM word 'LENGTH'\n"
            "  CUTCOM/LENGTH,1\n"
            "part.tap: record 64: note: 1 bytes after FINI ignored\n"
            "part.tap: warning: no place\n"
            "part.tap: record 3 (byte 4999): error: long\n"
            "  PPRINT " +
                std::string(193, 'x') + "...\n");
}

}  // namespace
}  // namespace clpost

#include "verify/cut_alignment.h"

#include <gtest/gtest.h>

#include <string>

namespace clpost {
namespace {

// Aligns two strings: equal letters cost 0, a letter and its upper case 1 (the same item with
// different numbers), other letters 2. Returns the pairs as "ab" columns: '-' for a gap.
std::string align(const std::string& a, const std::string& b, size_t slack = 32) {
  auto cost = [&](size_t i, size_t j) {
    if (a[i] == b[j]) return 0;
    return std::toupper(a[i]) == std::toupper(b[j]) ? 1 : 2;
  };
  std::string out;
  for (const AlignedPair& p : align_sequences(a.size(), b.size(), cost, slack)) {
    out += p.a >= 0 ? a[static_cast<size_t>(p.a)] : '-';
    out += p.b >= 0 ? b[static_cast<size_t>(p.b)] : '-';
    out += ' ';
  }
  return out;
}

TEST(CutAlignment, EqualSequencesPairOneToOne) {
  EXPECT_EQ(align("abc", "abc"), "aa bb cc ");
}

TEST(CutAlignment, ADroppedItemIsAGapNotAChainOfSubstitutions) {
  EXPECT_EQ(align("abcde", "abde"), "aa bb c- dd ee ");
  EXPECT_EQ(align("abcde", "abXcde"), "aa bb -X cc dd ee ");
}

TEST(CutAlignment, AChangedItemIsASubstitution) {
  EXPECT_EQ(align("abcde", "abCde"), "aa bb cC dd ee ");
}

TEST(CutAlignment, EmptySides) {
  EXPECT_EQ(align("", "ab"), "-a -b ");
  EXPECT_EQ(align("ab", ""), "a- b- ");
  EXPECT_EQ(align("", ""), "");
}

TEST(CutAlignment, ANarrowBandStillCoversTheLengthDifference) {
  // 40 items, the last 30 missing: the band is the difference plus the slack.
  const std::string a(40, 'a');
  const std::string b(10, 'a');
  const std::string r = align(a, b, 2);
  size_t gaps = 0;
  for (size_t i = 1; i < r.size(); i += 3) gaps += r[i] == '-';
  EXPECT_EQ(gaps, 30u);
}

}  // namespace
}  // namespace clpost

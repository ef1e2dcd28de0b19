#include "support/ring.h"

#include <gtest/gtest.h>

namespace clpost {
namespace {

// Elements come out in the order they went in, indexed from the front, across the array's end
// and through its growth (16, then 32 places).
TEST(Ring, FirstInFirstOutAcrossTheEndAndGrowth) {
  Ring<int> r;
  EXPECT_TRUE(r.empty());
  for (int i = 0; i < 10; ++i) r.push_back(i);
  for (int i = 0; i < 6; ++i) r.pop_front();
  // 6..9 at places 6..9; 10..21 wrap round to places 10..15 and 0..5 (16 places, full).
  for (int i = 10; i < 22; ++i) r.push_back(i);
  ASSERT_EQ(r.size(), 16u);
  EXPECT_EQ(r.front(), 6);
  EXPECT_EQ(r[15], 21);
  r.push_back(22);  // grows: 6..22 in order from place 0
  ASSERT_EQ(r.size(), 17u);
  for (size_t i = 0; i < r.size(); ++i) EXPECT_EQ(r[i], static_cast<int>(6 + i)) << i;
  r[0] = 60;
  EXPECT_EQ(r.front(), 60);
  const Ring<int> copy = r;
  while (!r.empty()) r.pop_front();
  EXPECT_EQ(copy.size(), 17u);
  EXPECT_EQ(copy[16], 22);
  r.push_back(7);
  EXPECT_EQ(r.front(), 7);
  EXPECT_EQ(r.size(), 1u);
}

// Grown to the size it usually holds and no further, then doubling past it.
TEST(Ring, GrowsToItsUsualSizeFirst) {
  Ring<int> r(20);
  for (int i = 0; i < 20; ++i) r.push_back(i);  // 16 places, then 20
  r.pop_front();
  r.pop_front();
  r.push_back(20);  // wraps round into place 0
  r.push_back(21);
  for (size_t i = 0; i < r.size(); ++i) EXPECT_EQ(r[i], static_cast<int>(2 + i)) << i;
  r.push_back(22);  // 40 places
  ASSERT_EQ(r.size(), 21u);
  for (size_t i = 0; i < r.size(); ++i) EXPECT_EQ(r[i], static_cast<int>(2 + i)) << i;
}

}  // namespace
}  // namespace clpost

// HEIDENHAIN G31 law as clpost assumes it (heidenhain_law.h, unverified), with hand numbers.
#include "controls/heidenhain/heidenhain_law.h"

#include <gtest/gtest.h>

namespace clpost {
namespace {

constexpr double kTol = 1e-6;

void expect_cut(const Cut& c, double depth, Vec2 from, Vec2 to) {
  EXPECT_NEAR(c.depth, depth, kTol);
  EXPECT_NEAR(c.from.x, from.x, kTol);
  EXPECT_NEAR(c.from.z, from.z, kTol);
  EXPECT_NEAR(c.to.x, to.x, kTol);
  EXPECT_NEAR(c.to.z, to.z, kTol);
}

HeidenhainG31 m16(int v, int h, int ic, int q) {
  HeidenhainG31 w;
  w.f = 1.5;
  w.u = 0.92;
  w.ic = ic;
  w.v = v;
  w.h = h;
  w.a = 30;
  w.q = q;
  w.from = {8, 2};
  w.to = {8, -20};
  return w;
}

TEST(HeidenhainG31Law, ConstantCrossSectionOffsetTowardMinusZ) {
  // G31 F1.5 U0.92 IC4 V0 H1 A30 Q1 on X16 Z2 -> X16 Z-20: depths 0.92·√(n/4) = 0.46, 0.650538,
  // 0.796743, 0.92, then one air cut at 0.92. H1 (toward -Z, the cutting direction): offsets
  // d·tan 30 = 0.265581, 0.375589, 0.46, 0.531162; every cut ends 0.531162 short of its offset
  // end, so the deepest ends at Z-20.
  std::vector<Cut> c = expand_heidenhain_g31(m16(0, 1, 4, 1), G31FlankCodes{});
  ASSERT_EQ(c.size(), 5u);
  expect_cut(c[0], 0.46, {7.54, 1.734419}, {7.54, -19.734419});
  expect_cut(c[1], 0.650538, {7.349462, 1.624411}, {7.349462, -19.844427});
  expect_cut(c[3], 0.92, {7.08, 1.468838}, {7.08, -20});
  expect_cut(c[4], 0.92, {7.08, 1.468838}, {7.08, -20});
}

TEST(HeidenhainG31Law, ConstantInfeedAlternating) {
  // V1 H3 IC4: 0.23, 0.46, 0.69, 0.92; odd cuts plunged, even ones offset by d·tan 30 =
  // 0.265581 (cut 2) and 0.531162 (cut 4, the largest, taken off every end).
  std::vector<Cut> c = expand_heidenhain_g31(m16(1, 3, 4, 0), G31FlankCodes{});
  ASSERT_EQ(c.size(), 4u);
  expect_cut(c[0], 0.23, {7.77, 2}, {7.77, -19.468838});
  expect_cut(c[1], 0.46, {7.54, 1.734419}, {7.54, -19.734419});
  expect_cut(c[2], 0.69, {7.31, 2}, {7.31, -19.468838});
  expect_cut(c[3], 0.92, {7.08, 1.468838}, {7.08, -20});
}

TEST(HeidenhainG31Law, InternalTowardPlusZ) {
  // BD1, bore 13.9175 from Z-26 to Z0, U1.083 IC1 V1 H2 (toward +Z): one cut at 13.9175 +
  // 1.083 = 15.0005, offset 1.083·tan 30 = 0.625270 toward +Z.
  HeidenhainG31 w;
  w.f = 2;
  w.u = 1.083;
  w.ic = 1;
  w.v = 1;
  w.h = 2;
  w.a = 30;
  w.bd = 1;
  w.from = {13.9175, -26};
  w.to = {13.9175, 0};
  std::vector<Cut> c = expand_heidenhain_g31(w, G31FlankCodes{});
  ASSERT_EQ(c.size(), 1u);
  expect_cut(c[0], 1.083, {15.0005, -25.374730}, {15.0005, 0});
}

TEST(HeidenhainG31Law, WordsOutsideTheLaw) {
  std::string err;
  HeidenhainG31 w = m16(2, 1, 4, 0);
  EXPECT_TRUE(expand_heidenhain_g31(w, G31FlankCodes{}, &err).empty());
  EXPECT_EQ(err, "infeed type V2 is not expanded");
  w = m16(0, 1, 4, 0);
  w.k = 2;
  EXPECT_TRUE(expand_heidenhain_g31(w, G31FlankCodes{}, &err).empty());
  EXPECT_EQ(err, "K (run-out length) is not expanded");
}

}  // namespace
}  // namespace clpost

// The CYCLE99 law (cycle99_law.h) on hand-computed cases. Points are CL frame: x a radius.
#include "controls/sinumerik/cycle99_law.h"

#include <gtest/gtest.h>

namespace clpost {
namespace {

constexpr double kEps = 1e-6;

// M16x1.5 external from Z2 to Z-20 on diameter 16.
Cycle99Words m16() {
  Cycle99Words w;
  w.spl = 2;
  w.dm1 = 16;
  w.fpl = -20;
  w.dm2 = 16;
  w.tdep = 0.92;
  w.nrc = 4;
  w.pit = 1.5;
  w.vari = kVariExternalConstantSection;
  return w;
}

void expect_cut(const Cut& c, int start, double depth, Vec2 from, Vec2 to, Vec2 end) {
  EXPECT_EQ(c.start, start);
  EXPECT_NEAR(c.depth, depth, kEps);
  EXPECT_NEAR(c.from.x, from.x, kEps);
  EXPECT_NEAR(c.from.z, from.z, kEps);
  EXPECT_NEAR(c.to.x, to.x, kEps);
  EXPECT_NEAR(c.to.z, to.z, kEps);
  EXPECT_NEAR(c.end.x, end.x, kEps);
  EXPECT_NEAR(c.end.z, end.z, kEps);
}

TEST(Cycle99Law, ConstantCrossSectionWithRearFlankInfeed) {
  Cycle99Words w = m16();
  w.iang = 30;
  Cycle99Expansion e = expand_cycle99(w);
  ASSERT_EQ(e.alarm, "");
  ASSERT_EQ(e.cuts.size(), 4u);
  // d_i = 0.92 sqrt(i/4) = 0.46, 0.650538, 0.796743, 0.92; shift d tan 30 = 0.265581, 0.375588,
  // 0.46, 0.531162 in the cutting direction (-Z); the full-depth cut ends at FPL, the others
  // 0.531162 - shift earlier.
  expect_cut(e.cuts[0], 0, 0.46, {7.54, 1.734419}, {7.54, -19.734419}, {7.54, -19.734419});
  expect_cut(e.cuts[1], 0, 0.650538, {7.349462, 1.624412}, {7.349462, -19.844426},
             {7.349462, -19.844426});
  expect_cut(e.cuts[2], 0, 0.796743, {7.203257, 1.54}, {7.203257, -19.928838},
             {7.203257, -19.928838});
  expect_cut(e.cuts[3], 0, 0.92, {7.08, 1.468838}, {7.08, -20}, {7.08, -20});
}

TEST(Cycle99Law, ConstantInfeedFinishingAllowanceAndIdlePasses) {
  Cycle99Words w = m16();
  w.vari = kVariExternalConstantInfeed;
  w.tdep = 1;
  w.fal = 0.1;
  w.nrc = 3;
  w.nid = 2;
  Cycle99Expansion e = expand_cycle99(w);
  ASSERT_EQ(e.cuts.size(), 6u);  // 3 roughing + FAL in one cut + 2 idle passes
  // Roughing 0.9 in 3: 0.3, 0.6, 0.9; then 1 (FAL) and 1, 1 (NID); radial (IANG 0).
  const double depths[] = {0.3, 0.6, 0.9, 1, 1, 1};
  for (size_t i = 0; i < 6; ++i) {
    expect_cut(e.cuts[i], 0, depths[i], {8 - depths[i], 2}, {8 - depths[i], -20},
               {8 - depths[i], -20});
  }
}

TEST(Cycle99Law, NoFinishingCutWithoutAllowance) {
  Cycle99Words w = m16();
  w.vari = kVariExternalConstantInfeed;
  w.nrc = 2;
  w.nid = 1;
  Cycle99Expansion e = expand_cycle99(w);
  ASSERT_EQ(e.cuts.size(), 3u);  // 0.46, 0.92, then one idle pass at 0.92
  EXPECT_NEAR(e.cuts[0].depth, 0.46, kEps);
  EXPECT_NEAR(e.cuts[1].depth, 0.92, kEps);
  EXPECT_NEAR(e.cuts[2].depth, 0.92, kEps);
}

TEST(Cycle99Law, InternalThreadGoesOutward) {
  Cycle99Words w = m16();
  w.vari = kVariInternalConstantInfeed;
  w.dm1 = w.dm2 = 27.835;  // tap hole of M30x2
  w.tdep = 1.083;
  w.nrc = 1;
  Cycle99Expansion e = expand_cycle99(w);
  ASSERT_EQ(e.cuts.size(), 1u);
  // 13.9175 + 1.083 = 15.0005
  expect_cut(e.cuts[0], 0, 1.083, {15.0005, 2}, {15.0005, -20}, {15.0005, -20});
}

TEST(Cycle99Law, RunOutEndsAtFpl) {
  Cycle99Words w = m16();
  w.vari = kVariExternalConstantInfeed;
  w.nrc = 2;
  w.rop = 1.5;
  Cycle99Expansion e = expand_cycle99(w);
  ASSERT_EQ(e.cuts.size(), 2u);
  // The cut ends 1.5 before FPL (Z-18.5) and runs out 1.5 along -Z and 1.5 outward (45 degrees).
  expect_cut(e.cuts[0], 0, 0.46, {7.54, 2}, {7.54, -18.5}, {9.04, -20});
  expect_cut(e.cuts[1], 0, 0.92, {7.08, 2}, {7.08, -18.5}, {8.58, -20});
}

TEST(Cycle99Law, RunInStartsBeforeSpl) {
  Cycle99Words w = m16();
  w.vari = kVariExternalConstantInfeed;
  w.nrc = 1;
  w.app = 2;
  Cycle99Expansion e = expand_cycle99(w);
  ASSERT_EQ(e.cuts.size(), 1u);
  expect_cut(e.cuts[0], 0, 0.92, {7.08, 4}, {7.08, -20}, {7.08, -20});
}

TEST(Cycle99Law, FrontFlankInfeedShiftsAgainstTheCut) {
  Cycle99Words w = m16();
  w.vari = kVariExternalConstantInfeed;
  w.tdep = 0.9;
  w.nrc = 2;
  w.iang = -30;
  Cycle99Expansion e = expand_cycle99(w);
  ASSERT_EQ(e.cuts.size(), 2u);
  // d 0.45, 0.9; shift -0.259808, -0.519615 (toward +Z); full depth ends at FPL, so the first
  // cut ends 0.259808 past it.
  expect_cut(e.cuts[0], 0, 0.45, {7.55, 2.259808}, {7.55, -20.259808}, {7.55, -20.259808});
  expect_cut(e.cuts[1], 0, 0.9, {7.1, 2.519615}, {7.1, -20}, {7.1, -20});
}

TEST(Cycle99Law, StartsAreCutOneAfterTheOther) {
  Cycle99Words w = m16();
  w.vari = kVariExternalConstantInfeed;
  w.nrc = 2;
  w.numth = 3;
  Cycle99Expansion e = expand_cycle99(w);
  ASSERT_EQ(e.cuts.size(), 6u);
  const int starts[] = {0, 0, 1, 1, 2, 2};
  for (size_t i = 0; i < 6; ++i) {
    EXPECT_EQ(e.cuts[i].start, starts[i]);
    EXPECT_NEAR(e.cuts[i].depth, i % 2 ? 0.92 : 0.46, kEps);
  }
}

TEST(Cycle99Law, TaperDepthIsParaxial) {
  // Radius 10.5 at Z2 to 9.8125 at Z-20 (1:32 on the radius); thread line length
  // sqrt(0.6875^2 + 22^2) = 22.010740; cos = 22 / 22.010740 = 0.999512.
  Cycle99Words w;
  w.spl = 2;
  w.dm1 = 21;
  w.fpl = -20;
  w.dm2 = 19.625;
  w.tdep = 1.1;
  w.nrc = 1;
  w.vari = kVariExternalConstantInfeed;
  w.psys = 20;
  Cycle99Expansion e = expand_cycle99(w);
  ASSERT_EQ(e.cuts.size(), 1u);
  // 1.1 along -X; at right angles to the line 1.1 x 0.999512 = 1.099463.
  expect_cut(e.cuts[0], 0, 1.099463, {9.4, 2}, {8.7125, -20}, {8.7125, -20});
}

TEST(Cycle99Law, FaceThreadCutsTowardMinusZ) {
  Cycle99Words w;
  w.spl = w.fpl = 0;
  w.dm1 = 80;
  w.dm2 = 40;
  w.tdep = 1.2;
  w.nrc = 2;
  w.vari = kVariExternalConstantInfeed;
  w.psys = 10;
  Cycle99Expansion e = expand_cycle99(w);
  ASSERT_EQ(e.cuts.size(), 2u);
  expect_cut(e.cuts[0], 0, 0.6, {40, -0.6}, {20, -0.6}, {20, -0.6});
  expect_cut(e.cuts[1], 0, 1.2, {40, -1.2}, {20, -1.2}, {20, -1.2});
}

TEST(Cycle99Law, WrongVariIsAlarm61002) {
  Cycle99Words w = m16();
  w.vari = 3;
  Cycle99Expansion e = expand_cycle99(w);
  EXPECT_TRUE(e.cuts.empty());
  EXPECT_EQ(e.alarm, "alarm 61002: machining type defined incorrectly (VARI 3)");
}

TEST(Cycle99Law, LeadFromPitAndPita) {
  Cycle99Words w = m16();
  EXPECT_DOUBLE_EQ(cycle99_lead(w, false), 1.5);
  w.pita = 2;
  w.pit = 13;
  EXPECT_NEAR(cycle99_lead(w, false), 1.953846, kEps);  // 25.4 / 13
  EXPECT_NEAR(cycle99_lead(w, true), 0.076923, kEps);   // 1 / 13 in
  w.pita = 7;
  EXPECT_EQ(cycle99_lead(w, false), 0);
}

}  // namespace
}  // namespace clpost

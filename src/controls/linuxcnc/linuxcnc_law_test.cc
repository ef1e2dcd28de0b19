// LinuxCNC G76 law, numbers by hand from the interpreter's source (convert_threading_cycle);
// every case below was also run through rs274 -g (linuxcnc-uspace), whose printout (4 decimals)
// is quoted next to the hand numbers.
#include "controls/linuxcnc/linuxcnc_law.h"

#include <gtest/gtest.h>

namespace clpost {
namespace {

constexpr double kTol = 1e-6;

void expect_cut(const Cut& c, double depth, Vec2 from, Vec2 to, Vec2 end) {
  EXPECT_NEAR(c.depth, depth, kTol);
  EXPECT_NEAR(c.from.x, from.x, kTol);
  EXPECT_NEAR(c.from.z, from.z, kTol);
  EXPECT_NEAR(c.to.x, to.x, kTol);
  EXPECT_NEAR(c.to.z, to.z, kTol);
  EXPECT_NEAR(c.end.x, end.x, kTol);
  EXPECT_NEAR(c.end.z, end.z, kTol);
}

TEST(LinuxcncG76Law, DegressionTwoExternalWithCompoundAngle) {
  // Drive line X18 (radius 9) at Z2: G76 P1.5 Z-20 I-2 J0.92 K1.84 R2 Q30 H0 in G7.
  // Radius frame: I -1 (crest 8), J 0.46, K 0.92. Depths 0.46·√n while below 0.92:
  // 0.46, 0.650538, 0.796743; 0.46·√4 = 0.92 is not below K, so the loop stops and the one
  // (H0 + 1) full-depth pass follows: 4 cuts. x = 8 - d.
  // zoff = d·tan 30 = 0.265581, 0.375589, 0.46, 0.531162; from z = 2 - zoff;
  // target z = -20 + 0.92·tan 30 = -19.468838, to z = target - zoff.
  // rs274: (7.5400, 1.7344 -> -19.7344), (7.3495, 1.6244 -> -19.8444),
  //        (7.2033, 1.5400 -> -19.9288), (7.0800, 1.4688 -> -20.0000).
  LinuxcncG76 w;
  w.p = 1.5;
  w.z = -20;
  w.i = -2;
  w.j = 0.92;
  w.k = 1.84;
  w.r = 2;
  w.q = 30;
  std::vector<Cut> c = expand_linuxcnc_g76(w, {9, 2}, true);
  ASSERT_EQ(c.size(), 4u);
  expect_cut(c[0], 0.46, {7.54, 1.734419}, {7.54, -19.734419}, {7.54, -19.734419});
  expect_cut(c[1], 0.650538, {7.349462, 1.624411}, {7.349462, -19.844427}, {7.349462, -19.844427});
  expect_cut(c[2], 0.796743, {7.203257, 1.54}, {7.203257, -19.928838}, {7.203257, -19.928838});
  expect_cut(c[3], 0.92, {7.08, 1.468838}, {7.08, -20}, {7.08, -20});
}

TEST(LinuxcncG76Law, SpringPassesGiveHPlusOneAtFullDepth) {
  // Same block with H2: three cuts at K after the three below it (rs274: 7.0800 three times).
  LinuxcncG76 w;
  w.p = 1.5;
  w.z = -20;
  w.i = -2;
  w.j = 0.92;
  w.k = 1.84;
  w.r = 2;
  w.h = 2;
  std::vector<Cut> c = expand_linuxcnc_g76(w, {9, 2}, true);
  ASSERT_EQ(c.size(), 6u);
  for (size_t n = 3; n < 6; ++n) expect_cut(c[n], 0.92, {7.08, 2}, {7.08, -20}, {7.08, -20});
  // Q absent: radial, every cut from Z2 to Z-20.
  expect_cut(c[0], 0.46, {7.54, 2}, {7.54, -20}, {7.54, -20});
}

TEST(LinuxcncG76Law, InternalConstantDepth) {
  // Drive line X22 (radius 11) at Z2: G76 P2 Z-24 I5.835 J0.9 K2.166 R1 Q30 H0.
  // I 2.9175 > 0: internal, bore at 13.9175, cuts at 13.9175 + d. J 0.45, K 1.083, R1:
  // 0.45, 0.9, then 1.35 is not below 1.083: full depth. zoff = d·tan 30 = 0.259808, 0.519615,
  // 0.625270; target = -24 + 0.625270.
  // rs274: (14.3675, 1.7402 -> -23.6345), (14.8175, 1.4804 -> -23.8943),
  //        (15.0005, 1.3747 -> -24.0000).
  LinuxcncG76 w;
  w.p = 2;
  w.z = -24;
  w.i = 5.835;
  w.j = 0.9;
  w.k = 2.166;
  w.r = 1;
  w.q = 30;
  std::vector<Cut> c = expand_linuxcnc_g76(w, {11, 2}, true);
  ASSERT_EQ(c.size(), 3u);
  expect_cut(c[0], 0.45, {14.3675, 1.740192}, {14.3675, -23.634538}, {14.3675, -23.634538});
  expect_cut(c[1], 0.9, {14.8175, 1.480385}, {14.8175, -23.894345}, {14.8175, -23.894345});
  expect_cut(c[2], 1.083, {15.0005, 1.374730}, {15.0005, -24}, {15.0005, -24});
}

TEST(LinuxcncG76Law, CuttingTowardPlusZShiftsTowardPlusZ) {
  // Drive line radius 11 at Z-30: G76 P2 Z5 I-2 J1 K2 R2 Q30. Z > start: the angle changes
  // sign, so the shift still follows the cut. Depths 0.5, 0.707107, 0.866025, 1.
  // from z = -30 + d·tan 30; to z = 5 - (1 - d)·tan 30.
  // rs274: (9.5000, -29.7113 -> 4.7113), (9.2929, -29.5918 -> 4.8309),
  //        (9.1340, -29.5000 -> 4.9226), (9.0000, -29.4226 -> 5.0000).
  LinuxcncG76 w;
  w.p = 2;
  w.z = 5;
  w.i = -2;
  w.j = 1;
  w.k = 2;
  w.r = 2;
  w.q = 30;
  std::vector<Cut> c = expand_linuxcnc_g76(w, {11, -30}, true);
  ASSERT_EQ(c.size(), 4u);
  expect_cut(c[0], 0.5, {9.5, -29.711325}, {9.5, 4.711325}, {9.5, 4.711325});
  expect_cut(c[1], 0.707107, {9.292893, -29.591752}, {9.292893, 4.830898}, {9.292893, 4.830898});
  expect_cut(c[3], 1, {9, -29.422650}, {9, 5}, {9, 5});
}

TEST(LinuxcncG76Law, ExitTaperRisesByTheFullDepthOverE) {
  // The first block with E1.5 L2: the straight part stops E before the cut's end, then the
  // taper rises by K (0.92) to it. First cut: straight to -19.734419 + 1.5 = -18.234419,
  // taper to (7.54 + 0.92, -19.734419). rs274: STRAIGHT_FEED(7.5400, -18.2344) then
  // STRAIGHT_FEED(8.4600, -19.7344) at lead 1.759659 (= 1.5·hypot(1.5, 0.92)/1.5).
  LinuxcncG76 w;
  w.p = 1.5;
  w.z = -20;
  w.i = -2;
  w.j = 0.92;
  w.k = 1.84;
  w.r = 2;
  w.q = 30;
  w.e = 1.5;
  w.l = 2;
  std::vector<Cut> c = expand_linuxcnc_g76(w, {9, 2}, true);
  ASSERT_EQ(c.size(), 4u);
  expect_cut(c[0], 0.46, {7.54, 1.734419}, {7.54, -18.234419}, {8.46, -19.734419});
  expect_cut(c[3], 0.92, {7.08, 1.468838}, {7.08, -18.5}, {8, -20});
}

TEST(LinuxcncG76Law, RadiusModeAndQMinusOne) {
  // G8 (radius mode): I, J, K are radii. Q-1 is the control's "no angle".
  // Drive 9 at Z0, I-1 J0.3 K0.6 R1 Q-1: 0.3 then 0.6 (0.3·2 is not below 0.6).
  LinuxcncG76 w;
  w.p = 1;
  w.z = -10;
  w.i = -1;
  w.j = 0.3;
  w.k = 0.6;
  w.r = 1;
  w.q = -1;
  std::vector<Cut> c = expand_linuxcnc_g76(w, {9, 0}, false);
  ASSERT_EQ(c.size(), 2u);
  expect_cut(c[0], 0.3, {7.7, 0}, {7.7, -10}, {7.7, -10});
  expect_cut(c[1], 0.6, {7.4, 0}, {7.4, -10}, {7.4, -10});
}

TEST(LinuxcncG76Law, TheControlsRefusals) {
  LinuxcncG76 w;
  w.p = 1.5;
  w.z = -20;
  w.i = -2;
  w.j = 0.5;
  w.k = 1.8;
  std::string err;
  w.i = 0;
  EXPECT_TRUE(expand_linuxcnc_g76(w, {9, 2}, true, &err).empty());
  EXPECT_EQ(err, "In G76, I must not be 0");
  w.i = -2;
  w.j = 0;
  EXPECT_TRUE(expand_linuxcnc_g76(w, {9, 2}, true, &err).empty());
  EXPECT_EQ(err, "In G76, J must be greater than 0");
  w.j = 1.8;
  EXPECT_TRUE(expand_linuxcnc_g76(w, {9, 2}, true, &err).empty());
  EXPECT_EQ(err, "In G76, K must be greater than J");
}

}  // namespace
}  // namespace clpost

// The Fanuc G76 / G92 and Haas G76 laws alone, with hand-computed numbers (fanuc_law.h,
// haas_law.h; controllers.md "Fanuc (system A lathe)", "Haas lathe").
#include "controls/fanuc/fanuc_law.h"

#include <gtest/gtest.h>

#include <cmath>

#include "controls/haas/haas_law.h"

namespace clpost {
namespace {

constexpr double kTan30 = 0.5773502691896257;

void expect_depths(const std::vector<double>& got, const std::vector<double>& want) {
  ASSERT_EQ(got.size(), want.size());
  for (size_t i = 0; i < want.size(); ++i) EXPECT_NEAR(got[i], want[i], 5e-7) << "pass " << i + 1;
}

TEST(FanucG76Law, SquareRootLadderStopsAtKMinusDThenMPassesAtK) {
  // M16x1.5, 6 planned cuts over k = 0.92: Δd = ceil(920/√6 µm) = ceil(375.59) = 376 µm;
  // d = ceil(920 - 920·√(5/6) µm) = ceil(80.16) = 81 µm, so roughing stops at 0.839; m = 1.
  // 0.376·√1 = 0.376, ·√2 = 0.531744, ·√3 = 0.651251, ·√4 = 0.752, ·√5 = 0.840762 ≥ 0.839 -> 0.839.
  FanucG76Words w;
  w.height = 0.92;
  w.allowance = 0.081;
  w.first_cut = 0.376;
  w.finish_passes = 1;
  expect_depths(fanuc_g76_depths(w), {0.376, 0.531744, 0.651251, 0.752, 0.839, 0.92});
}

TEST(FanucG76Law, IncrementBelowMinimumIsRaised) {
  // k 1.0, d 0, Δd 0.4, Δdmin 0.2: 0.4; max(0.565685, 0.6) = 0.6; max(0.69282, 0.8) = 0.8;
  // max(0.8, 1.0) = 1.0 = k - d (roughing ends); then m = 2 passes at 1.0.
  FanucG76Words w;
  w.height = 1.0;
  w.allowance = 0;
  w.first_cut = 0.4;
  w.min_cut = 0.2;
  w.finish_passes = 2;
  expect_depths(fanuc_g76_depths(w), {0.4, 0.6, 0.8, 1.0, 1.0, 1.0});
}

TEST(FanucG76Law, WordsThatCannotEndGiveNoPasses) {
  FanucG76Words w;
  w.height = 1.0;
  w.first_cut = 0;
  w.min_cut = 0;
  EXPECT_TRUE(fanuc_g76_depths(w).empty());
  EXPECT_TRUE(fanuc_g76_tool_angle_ok(29));
  EXPECT_FALSE(fanuc_g76_tool_angle_ok(45));
}

TEST(FanucG76Law, PassesStartOnTheFlankAndEndAtZ) {
  // External, crest radius 8: X = 2·(8 - 0.92) = 14.16, Z -20, tool at A (radius 9.3, Z 2).
  // Pass 1 at 0.376: shift 0.376·tan 30 = 0.217084 -> from (7.624, 1.782916), to (7.624, -20).
  FanucG76Words w;
  w.x = 14.16;
  w.z = -20;
  w.height = 0.92;
  w.allowance = 0.081;
  w.first_cut = 0.376;
  w.tool_angle = 60;
  w.lead = 1.5;
  std::vector<Cut> c = expand_fanuc_g76(w, {9.3, 2}, CycleLaw{});
  ASSERT_EQ(c.size(), 6u);
  EXPECT_NEAR(c[0].from.x, 7.624, 1e-9);
  EXPECT_NEAR(c[0].from.z, 2 - 0.376 * kTan30, 1e-9);
  EXPECT_NEAR(c[0].from.z, 1.782916, 1e-6);
  EXPECT_NEAR(c[0].to.x, 7.624, 1e-9);
  EXPECT_NEAR(c[0].to.z, -20, 1e-12);
  EXPECT_NEAR(c[0].depth, 0.376, 1e-12);
  // The last pass at k: X 7.08, shift 0.92·tan 30 = 0.531162.
  EXPECT_NEAR(c[5].from.x, 7.08, 1e-9);
  EXPECT_NEAR(c[5].from.z, 1.468838, 1e-6);
  // Shifted ends (threading.cycle_pass_end: shifted): pass 1 ends 0.531162 - 0.217084 = 0.314078
  // before Z.
  CycleLaw shifted;
  shifted.shifted_end = true;
  c = expand_fanuc_g76(w, {9.3, 2}, shifted);
  EXPECT_NEAR(c[0].to.z, -19.685922, 1e-6);
  EXPECT_NEAR(c[5].to.z, -20, 1e-12);
}

TEST(FanucG76Law, ChamferIsARunOutEndingAtZ) {
  // r = 10 tenths of a 1.5 lead = 1.5 at 45°: the pass leaves its line 1.5 before Z -21.5 and
  // reaches Z -21.5 1.5 further out.
  FanucG76Words w;
  w.x = 14.16;
  w.z = -21.5;
  w.height = 0.92;
  w.first_cut = 0.92;
  w.finish_passes = 1;
  w.chamfer = 10;
  w.tool_angle = 0;
  w.lead = 1.5;
  std::vector<Cut> c = expand_fanuc_g76(w, {9.3, 2}, CycleLaw{});
  ASSERT_EQ(c.size(), 2u);
  EXPECT_NEAR(c[0].from.z, 2, 1e-12);  // a = 0: radial
  EXPECT_NEAR(c[0].to.x, 7.08, 1e-9);
  EXPECT_NEAR(c[0].to.z, -20, 1e-9);
  EXPECT_NEAR(c[0].end.x, 8.58, 1e-9);
  EXPECT_NEAR(c[0].end.z, -21.5, 1e-12);
}

TEST(FanucG76Law, InternalAndTaper) {
  // Internal M30x2: bore radius 13.9175, k 1.083 -> X = 2·(13.9175 + 1.083) = 30.001; tool at
  // radius 12. A pass at 0.3 lies at 13.9175 + 0.3 = 14.2175 and its shift runs toward -Z.
  FanucG76Words w;
  w.x = 30.001;
  w.z = -24;
  w.height = 1.083;
  w.first_cut = 0.3;
  w.allowance = 0.783;  // roughing to 0.3 only
  w.finish_passes = 1;
  w.tool_angle = 60;
  std::vector<Cut> c = expand_fanuc_g76(w, {12, 2}, CycleLaw{});
  ASSERT_EQ(c.size(), 2u);
  EXPECT_NEAR(c[0].from.x, 14.2175, 1e-9);
  EXPECT_NEAR(c[0].from.z, 2 - 0.3 * kTan30, 1e-9);
  EXPECT_NEAR(c[1].to.x, 15.0005, 1e-9);
  // Taper: the full-depth radius is 7 at Z -20 and 7 + 0.5 at Z 2 (R 0.5 = start - end); slope
  // 0.5/22; radial depth 1 at cos = 22/√(22² + 0.5²) = 0.999742 -> reported depth 0.999742.
  FanucG76Words t;
  t.x = 14;
  t.z = -20;
  t.taper = 0.5;
  t.height = 1;
  t.first_cut = 1;
  t.finish_passes = 1;
  t.tool_angle = 0;
  c = expand_fanuc_g76(t, {10, 2}, CycleLaw{});
  ASSERT_EQ(c.size(), 2u);
  EXPECT_NEAR(c[0].from.x, 7.5, 1e-9);
  EXPECT_NEAR(c[0].to.x, 7, 1e-9);
  EXPECT_NEAR(c[0].depth, 22 / std::sqrt(22 * 22 + 0.25), 1e-9);
}

TEST(G92Law, OneCutPerBlockFromTheStartPointZ) {
  // S (radius 9.5, Z 1.782916), X15.248 Z-20: cut from (7.624, 1.782916) to (7.624, -20), depth
  // 8 - 7.624 = 0.376 below the line (8, 2)-(8, -20).
  G92Pass p;
  p.start = {9.5, 1.782916};
  p.words.x = 15.248;
  p.words.z = -20;
  p.words.lead = 1.5;
  // Taper R -0.5 from S (12, 2): X15 -> end radius 7.5, start radius 7.5 - 0.5 = 7. Q180000 of a
  // 2-start thread: start index 1.
  G92Pass q;
  q.start = {12, 2};
  q.words.x = 15;
  q.words.z = -20;
  q.words.taper = -0.5;
  q.words.start_angle = 180;
  std::vector<Cut> c = expand_g92({p, q}, true, {8, 2}, {8, -20}, 2);
  ASSERT_EQ(c.size(), 2u);
  EXPECT_NEAR(c[0].from.x, 7.624, 1e-12);
  EXPECT_NEAR(c[0].from.z, 1.782916, 1e-12);
  EXPECT_NEAR(c[0].to.z, -20, 1e-12);
  EXPECT_NEAR(c[0].depth, 0.376, 1e-12);
  EXPECT_EQ(c[0].start, 0);
  EXPECT_NEAR(c[1].from.x, 7, 1e-12);
  EXPECT_NEAR(c[1].to.x, 7.5, 1e-12);
  EXPECT_EQ(c[1].start, 1);
}

TEST(HaasG76Law, P1IsTheSquareRootLawAndP3ConstantDepth) {
  // P1, K 0.92, D 0.376, setting 86 = 0: 0.376·√n up to n = 5 (0.840762); 0.376·√6 = 0.921008
  // ≥ 0.92 -> 0.92. No pass after it (no finish allowance).
  HaasG76Words w;
  w.height = 0.92;
  w.first_cut = 0.376;
  w.mode = 1;
  HaasSettings s;
  expect_depths(haas_g76_depths(w, s), {0.376, 0.531744, 0.651251, 0.752, 0.840762, 0.92});
  // P3, D 0.23: 0.23, 0.46, 0.69, 0.92.
  w.first_cut = 0.23;
  w.mode = 3;
  expect_depths(haas_g76_depths(w, s), {0.23, 0.46, 0.69, 0.92});
}

TEST(HaasG76Law, SettingsFinishAllowanceAndMinimumCut) {
  // K 1, setting 86 = 0.2, D 0.4 (P1): roughing to 0.8: 0.4, 0.565685, 0.69282, 0.8; then 1.
  HaasG76Words w;
  w.height = 1;
  w.first_cut = 0.4;
  HaasSettings s;
  s.finish_allowance = 0.2;
  expect_depths(haas_g76_depths(w, s), {0.4, 0.565685, 0.69282, 0.8, 1});
  // Setting 99 = 0.15, no allowance: 0.4; max(0.565685, 0.55); max(0.69282, 0.715685);
  // max(0.8, 0.865685); max(0.894427, 1.015685) ≥ 1 -> 1.
  s.finish_allowance = 0;
  s.min_cut = 0.15;
  expect_depths(haas_g76_depths(w, s), {0.4, 0.565685, 0.715685, 0.865685, 1});
}

TEST(HaasG76Law, ChamferFromSettingsAndStartAngle) {
  // Setting 95 = 1 lead of 1.5 at 45°, Q 120° of 3 starts = start index 1.
  HaasG76Words w;
  w.x = 14.16;
  w.z = -21.5;
  w.height = 0.92;
  w.first_cut = 0.92;
  w.tool_angle = 0;
  w.lead = 1.5;
  w.start_angle = 120;
  HaasSettings s;
  s.chamfer = 1;
  std::vector<Cut> c = expand_haas_g76(w, {9.3, 2}, s, CycleLaw{}, 3);
  ASSERT_EQ(c.size(), 1u);
  EXPECT_EQ(c[0].start, 1);
  EXPECT_NEAR(c[0].to.z, -20, 1e-9);
  EXPECT_NEAR(c[0].end.x, 8.58, 1e-9);
}

}  // namespace
}  // namespace clpost

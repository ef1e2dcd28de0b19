// Fanuc G76 two-block cycle and the G92 loop on machine fanuc-0i-t: exact blocks, each mismatch
// reason, the extra spring pass note and the fallback: error diagnostic. Numbers by hand.
#include "controls/fanuc/fanuc_emitter.h"

#include <gtest/gtest.h>

#include "controls/fanuc/fanuc_test_util.h"

namespace clpost {
namespace {

using testing::load;
using testing::thread_on;

// M16x1.5 external, radius 8 from Z2 to Z-20, tool at (10, 5); clear line 1.5·√3/2 = 1.299038
// above the crest: A = (9.299038, 2) -> X18.598 Z2.
constexpr Vec2 kP0{10, 5};
const std::vector<Vec2> kM16{{8, 2}, {8, -20}};

std::string fanuc_fit(const std::string& on, std::vector<std::string> sets = {},
                      const std::vector<Vec2>& gotos = kM16, Vec2 p0 = kP0) {
  Machine m = load("fanuc-0i-t", sets);
  testing::Threaded t = thread_on(m, on, p0, gotos);
  return FanucG76Emitter().fit(t.plan, m).mismatch;
}

TEST(FanucG76, SixCutsOption1) {
  // Heights 0.92·√(i/6): 0.375586, 0.531162, 0.650538, 0.751177, 0.839841, 0.92.
  // k = 920 µm; one pass at k -> m = 1; d = ceil(0.92 - 0.839841) = 0.081 (roughing stops at
  // 0.839); Δd = ceil(375.586 µm) = 376; law 0.376, 0.531744, 0.651251, 0.752, clamp 0.839:
  // smallest increment 0.752 - 0.651251 = 0.100749 -> Δdmin 100 µm. X = 2·(8 - 0.92) = 14.16.
  // Pass 1's plan end is 0.531162 - 0.216845 = 0.314317 short of Z-20: the fixed-end note.
  Machine m = load("fanuc-0i-t");
  testing::Threaded t = thread_on(m, "THREAD/ON,MMPR,1.5,DEPTH,0.92,CUTS,6,OPTION,1", kP0, kM16);
  ASSERT_TRUE(t.ok) << t.diags;
  EXPECT_EQ(t.nc,
            "(G76 ENDS EVERY PASS AT Z-20.; THE PLAN ENDS THE SHALLOWER PASSES UP TO 0.3143 "
            "EARLIER THREADING.ACCEPT_PASS_END)\n"
            "G0 X18.598 Z2.\n"
            "G76 P010060 Q100 R0.081\n"
            "G76 X14.16 Z-20. P920 Q376 F1.5\n");
}

TEST(FanucG76, FinishAllowanceSpringPassAndChamfer) {
  // M20x2.5 (radius 10, Z0 to Z-30), DEPTH 1.534, CUTS 5, FINCUT 2,0.1, CHAMFR 2.5 at 45°:
  // R = 1.434, heights 1.434·√(i/5): 0.641304, 0.906941, 1.110773, 1.282613, 1.434; then 2 at
  // 1.534 -> m = 2, d = 0.1, Δd = 642 µm; law 0.642, 0.907925, 1.111977, 1.284, clamp 1.434:
  // smallest increment 1.284 - 1.111977 = 0.172023 -> Δdmin 172. r = 2.5/(0.1·2.5) = 10.
  // Z where the chamfer ends: -30 - 2.5 = -32.5; X = 2·(10 - 1.534) = 16.932.
  // Clear line: the pull-out tops out at 2.5 - 0.641304 = 1.858696 < 2.165064 (2.5·√3/2), so
  // A = (12.165064, 0) -> X24.33 Z0.
  Machine m = load("fanuc-0i-t");
  testing::Threaded t =
      thread_on(m, "THREAD/ON,MMPR,2.5,DEPTH,1.534,CUTS,5,FINCUT,2,0.1,OPTION,1,CHAMFR,2.5",
                {13, 5}, {{10, 0}, {10, -30}});
  ASSERT_TRUE(t.ok) << t.diags;
  EXPECT_EQ(t.nc,
            "(G76 ENDS EVERY PASS AT Z-32.5; THE PLAN ENDS THE SHALLOWER PASSES UP TO 0.5154 "
            "EARLIER THREADING.ACCEPT_PASS_END)\n"
            "G0 X24.33 Z0.\n"
            "G76 P021060 Q172 R0.1\n"
            "G76 X16.932 Z-32.5 P1534 Q642 F2.5\n");
}

TEST(FanucG76, OnePassNeedsTheExtraSpringPass) {
  // DEPTH 0.3 alone: one pass; G76 cuts roughing to k - d and then m >= 1 passes at k.
  EXPECT_EQ(fanuc_fit("THREAD/ON,MMPR,1.5,DEPTH,0.3,OPTION,1"),
            "one pass at full depth: G76 cuts at least two (roughing to k - d, then m >= 1 at k) "
            "and threading.extra_spring_passes is off");
  // Allowed: d = 0, Δd = k = 300 µm, m = 1, no roughing increment -> Δdmin 0; X = 2·7.7.
  Machine m = load("fanuc-0i-t", {"threading.extra_spring_passes=true"});
  testing::Threaded t = thread_on(m, "THREAD/ON,MMPR,1.5,DEPTH,0.3,OPTION,1", kP0, kM16);
  ASSERT_TRUE(t.ok) << t.diags;
  EXPECT_EQ(t.nc,
            "(G76 ADDS ONE SPRING PASS AT FULL DEPTH THREADING.EXTRA_SPRING_PASSES)\n"
            "G0 X18.598 Z2.\n"
            "G76 P010060 Q0 R0.\n"
            "G76 X15.4 Z-20. P300 Q300 F1.5\n");
}

TEST(FanucG76, MismatchReasons) {
  EXPECT_EQ(fanuc_fit("THREAD/ON,MMPR,1.5,DEPTH,0.92,CUTS,5,OPTION,0"),
            "OPTION 0, steps shrinking by a constant amount: G76 cuts depths Q x root n");
  EXPECT_EQ(fanuc_fit("THREAD/ON,MMPR,1.5,DEPTH,0.92,CUTS,4,OPTION,3"),
            "OPTION 3, constant depth: G76 cuts depths Q x root n");
  EXPECT_EQ(fanuc_fit("THREAD/ON,MMPR,1.5,DEPTH,0.92,CUTS,4,OPTION,4"),
            "OPTION 4, constant depth: G76 cuts depths Q x root n");
  EXPECT_EQ(fanuc_fit("THREAD/ON,MMPR,1.5,DEPTH,0.92,CUTS,6,OPTION,2"),
            "OPTION 2 alternates flanks: G76 infeeds along one flank");
  EXPECT_EQ(fanuc_fit("THREAD/ON,MMPR,1.5,MULTRD,2,DEPTH,0.92,CUTS,4,OPTION,1"),
            "2 starts: G76 has no start-angle word (G92 with Q cuts them)");
  EXPECT_EQ(fanuc_fit("THREAD/ON,MMPR,1.5,DEPTH,0.92,CUTS,4,OPTION,1,TLANGL,45"),
            "tool angle 45: G76 takes 80, 60, 55, 30, 29 or 0");
  EXPECT_EQ(fanuc_fit("THREAD/ON,MMPR,1.5,DEPTH,0.92,CUTS,4,OPTION,1,CUTANG,210"),
            "CUTANG 210: G76 infeeds from a radial line (along the flank at half the tool angle)");
  EXPECT_EQ(fanuc_fit("THREAD/ON,MMPR,1.5,DEPTH,0.92,CUTS,4,OPTION,1,ATANGL,0,1.2"),
            "pull-out (X 1.2, Z 0) is not a chamfer along the thread: G76 has none");
  EXPECT_EQ(fanuc_fit("THREAD/ON,MMPR,1.5,DEPTH,0.92,CUTS,4,OPTION,1,CHAMFR,1.5,60"),
            "pull-out (X 2.598, Z -1.5) is not G76's 45 deg chamfer (threading.chamfer_angle)");
  EXPECT_EQ(fanuc_fit("THREAD/ON,MMPR,1.5,DEPTH,0.92,CUTS,4,OPTION,1,CHAMFR,1.6"),
            "chamfer 1.6 is not a whole number of tenths of the lead 1.5 (r 01-99 of G76)");
  // Face thread (Z0 face, radius 40 to 20, infeed along -Z).
  EXPECT_EQ(
      fanuc_fit("THREAD/ON,MMPR,2,DEPTH,1.2,CUTS,4,OPTION,1", {}, {{40, 0}, {20, 0}}, {42, 4}),
      "face thread: G76 threads along Z");
  // Constant steps under OPTION 1: not the root-n law (0.23, 0.46: 0.23·√2 = 0.325269).
  EXPECT_EQ(fanuc_fit("THREAD/ON,MMPR,1.5,CUTS,4,STEP,0.23,OPTION,1"),
            "G76 would cut pass 2: depth 0.3253, plan 0.4600");
  // The fixed pass end not accepted.
  EXPECT_EQ(fanuc_fit("THREAD/ON,MMPR,1.5,DEPTH,0.92,CUTS,6,OPTION,1",
                      {"threading.accept_pass_end=false"}),
            "G76 ends every pass at Z-20.; the plan ends the shallower passes up to 0.3143 "
            "earlier (threading.accept_pass_end is off)");
  // Shifted pass ends (threading.cycle_pass_end: shifted) equal the plan: no note needed.
  EXPECT_EQ(fanuc_fit("THREAD/ON,MMPR,1.5,DEPTH,0.92,CUTS,6,OPTION,1",
                      {"threading.cycle_pass_end=shifted"}),
            "");
}

TEST(FanucG92, ConstantDepthPassByPassWithFlankShifts) {
  // OPTION 3, 4 cuts of 0.23; shifts d·tan 30: 0.132791, 0.265581, 0.398372, 0.531162.
  // Pass i starts at Z 2 - σ_i (1.867, 1.734, 1.602, 1.469) and ends at -20 + σ_max - σ_i
  // (-19.602, -19.734, -19.867, -20); X = 2·(8 - d): 15.54, 15.08, 14.62, 14.16.
  Machine m = load("fanuc-0i-t");
  testing::Threaded t = thread_on(m, "THREAD/ON,MMPR,1.5,DEPTH,0.92,CUTS,4,OPTION,3", kP0, kM16);
  ASSERT_TRUE(t.ok) << t.diags;
  EXPECT_EQ(t.nc,
            "(G76 NOT USED: OPTION 3, CONSTANT DEPTH: G76 CUTS DEPTHS Q X ROOT N. G92 INSTEAD)\n"
            "G0 X18.598 Z1.867\n"
            "G92 X15.54 Z-19.602 F1.5\n"
            "G0 Z1.734\n"
            "G92 X15.08 Z-19.734 F1.5\n"
            "G0 Z1.602\n"
            "G92 X14.62 Z-19.867 F1.5\n"
            "G0 Z1.469\n"
            "G92 X14.16 Z-20. F1.5\n"
            "G0 X18.598 Z2.\n");
}

TEST(FanucG92, TwoStartsWithQ) {
  // 2 starts by spindle angle, pitch 1.5 lead 3, OPTION 1 4 cuts on radius 12 (Z0 to Z-25):
  // depths 0.46, 0.650538, 0.796743, 0.92 (0.92·√(i/4)); both starts of a pass share the start
  // point, so the second block gives only X and Q (Q180000 = 180°, Q0 written every time).
  Machine m = load("fanuc-0i-t");
  testing::Threaded t = thread_on(m, "THREAD/ON,MMPR,1.5,MULTRD,2,DEPTH,0.92,CUTS,4,OPTION,1",
                                  {15, 6}, {{12, 0}, {12, -25}});
  ASSERT_TRUE(t.ok) << t.diags;
  // Clear line 1.299038 above radius 12 -> X26.598; pass 1 shift 0.46·tan 30 = 0.265581 ->
  // Z-0.266, end -25 + 0.531162 - 0.265581 = -24.734; X 2·(12 - 0.46) = 23.08.
  EXPECT_EQ(t.nc.substr(0, t.nc.find("G0 Z-0.376")),
            "(G76 NOT USED: 2 STARTS: G76 HAS NO START-ANGLE WORD G92 WITH Q CUTS THEM. G92 "
            "INSTEAD)\n"
            "G0 X26.598 Z-0.266\n"
            "G92 X23.08 Z-24.734 F3. Q0\n"
            "X23.08 Q180000\n");
}

TEST(FanucG92, PullOutGoesToEmulation) {
  // A chamfer at 60°: G76 cannot say it (its chamfer is 45°), G92 cuts the control's own chamfer:
  // the comment names G76's reason and the emulation cuts the plan.
  Machine m = load("fanuc-0i-t");
  testing::Threaded t =
      thread_on(m, "THREAD/ON,MMPR,1.5,DEPTH,0.92,CUTS,4,OPTION,1,CHAMFR,1.5,60", kP0, kM16);
  ASSERT_TRUE(t.ok) << t.diags;
  EXPECT_EQ(t.nc.substr(0, t.nc.find('\n')),
            "(G76 NOT USED: PULL-OUT X 2.598, Z -1.5 IS NOT G76'S 45 DEG CHAMFER "
            "THREADING.CHAMFER_ANGLE. EMULATION INSTEAD)");
  Fit g92 = G92Emitter().fit(t.plan, m);
  EXPECT_EQ(g92.mismatch,
            "pull-out (X 2.598, Z -1.5): G92 cuts the control's own chamfer (a parameter), not "
            "the plan's");
}

TEST(FanucG92, FaceThreadIsNotAG92) {
  Machine m = load("fanuc-0i-t");
  testing::Threaded t =
      thread_on(m, "THREAD/ON,MMPR,2,DEPTH,1.2,CUTS,4,OPTION,3", {42, 4}, {{40, 0}, {20, 0}});
  EXPECT_EQ(G92Emitter().fit(t.plan, m).mismatch, "face thread: G92 threads along Z");
}

TEST(FanucG76, FallbackErrorStopsWithTheReason) {
  Machine m = load("fanuc-0i-t", {"threading.fallback=error"});
  testing::Threaded t = thread_on(m, "THREAD/ON,MMPR,1.5,DEPTH,0.92,CUTS,4,OPTION,3", kP0, kM16);
  EXPECT_FALSE(t.ok);
  EXPECT_EQ(t.nc, "");
  EXPECT_NE(t.diags.find("t.cl:2:1: error: machine 'fanuc-0i-t': G76 would not cut the planned "
                         "passes: OPTION 3, constant depth: G76 cuts depths Q x root n "
                         "(threading.fallback is 'error')"),
            std::string::npos)
      << t.diags;
}

}  // namespace
}  // namespace clpost

// linuxcnc-lathe's G76: exact blocks, every reason it is not used, the fallback comment and the
// fallback: error diagnostic. The law itself: linuxcnc_law_test.cc; against the real interpreter:
// tests/thread_matrix_test.cc.
#include "controls/linuxcnc/linuxcnc_emitter.h"

#include <gtest/gtest.h>

#include "emitters/emitter_test_util.h"

namespace clpost {
namespace {

using testing::emit_on;
using testing::plan_for;
using testing::shipped_machine;

const Vec2 kP0{10, 5}, kP1{8, 2}, kP2{8, -20};

std::string mismatch(const std::string& on, Vec2 p0 = kP0, std::vector<Vec2> gotos = {kP1, kP2}) {
  Machine m = shipped_machine("linuxcnc-lathe");
  LinuxcncG76Emitter e;
  return e.fit(plan_for(m, on, p0, gotos), m).mismatch;
}

TEST(LinuxcncG76Emitter, OptionOneWithASpringPass) {
  // M16x1.5, depth 0.92, 4 cuts of OPTION 1 (0.92·√(i/4): 0.46, 0.650538, 0.796743, 0.92) and
  // a spring pass. Clear line 1.5/(2 tan 30) = 1.299038 above the crest: drive line radius
  // 9.299038, X18.59808. I = 2·(8 - 9.29904) = -2.59808; J = 2·0.46 = 0.92 (0.46·√4 reaches K,
  // so the control cuts 3 + H1 + 1 = 5 passes); K = 2·0.92; Q = 30 (TLANGL 60 / 2).
  // After the cycle the tool is at the drive line at Z-20; the thread ends above its start.
  Machine m = shipped_machine("linuxcnc-lathe");
  ThreadPlan plan =
      plan_for(m, "THREAD/ON,MMPR,1.5,DEPTH,0.92,CUTS,4,OPTION,1,FINCUT,1", kP0, {kP1, kP2});
  testing::Emitted out = emit_on(m, plan);
  ASSERT_TRUE(out.ok) << out.diags;
  EXPECT_EQ(out.nc,
            "(G76 rapids its infeed and retract; the CL feeds the approach)\n"
            "G1 X18.59808 Z2. G95 F0.2\n"
            "G76 P1.5 Z-20. I-2.59808 J0.92 K1.84 R2 Q30. H1\n"
            "G0 X18.59808 Z2.\n");
}

TEST(LinuxcncG76Emitter, ConstantDepthAtRapid) {
  // OPTION 3, 4 cuts of 0.23 (J0.46 diameter, R1), TLANGL 55: Q27.5. Rapid approach: no note.
  Machine m = shipped_machine("linuxcnc-lathe");
  ThreadPlan plan = plan_for(m, "THREAD/ON,MMPR,1.5,DEPTH,0.92,CUTS,4,OPTION,3,TLANGL,55", kP0,
                             {kP1, kP2}, false);
  testing::Emitted out = emit_on(m, plan);
  ASSERT_TRUE(out.ok) << out.diags;
  EXPECT_EQ(out.nc,
            "G0 X18.59808 Z2.\n"
            "G76 P1.5 Z-20. I-2.59808 J0.46 K1.84 R1 Q27.5 H0\n"
            "G0 X18.59808 Z2.\n");
}

TEST(LinuxcncG76Emitter, ExitTaperAndJRoundedUp) {
  // CHAMFR 0.92 at 45°: the pull-out rises 0.92 = the depth over 0.92 along Z: E0.92 L2, and Z
  // is where the deepest pass's chamfer ends, -20 - 0.92. 5 cuts: J = 1.84/√5 = 0.8228730…
  // written rounded up to 0.822874 so that J·√5 is not below K (0.822873 would give
  // 0.822873·√5 = 1.8399993 < 1.84 and a sixth cut).
  Machine m = shipped_machine("linuxcnc-lathe");
  ThreadPlan plan =
      plan_for(m, "THREAD/ON,MMPR,1.5,DEPTH,0.92,CUTS,5,OPTION,1,CHAMFR,0.92", kP0, {kP1, kP2});
  testing::Emitted out = emit_on(m, plan);
  ASSERT_TRUE(out.ok) << out.diags;
  EXPECT_NE(out.nc.find("G76 P1.5 Z-20.92 I-2.59808 J0.822874 K1.84 R2 Q30. H0 E0.92 L2\n"),
            std::string::npos)
      << out.nc;
}

TEST(LinuxcncG76Emitter, AngledInfeedIsTheCompoundAngle) {
  // CUTANG 210 with radial steps of 0.4 (OPTION 1 from a first step: 0.4·√n, 6 cuts): no flank
  // shift, the plunge itself goes 30° back: Q30, and the deepest pass ends 0.92·tan 30 =
  // 0.531162 past P2, so Z-20.53116.
  Machine m = shipped_machine("linuxcnc-lathe");
  ThreadPlan plan =
      plan_for(m, "THREAD/ON,MMPR,1.5,DEPTH,0.92,STEP,0.4,OPTION,1,CUTANG,210", kP0, {kP1, kP2});
  testing::Emitted out = emit_on(m, plan);
  ASSERT_TRUE(out.ok) << out.diags;
  EXPECT_NE(out.nc.find("G76 P1.5 Z-20.53116 I-2.59808 J0.8 K1.84 R2 Q30. H0\n"), std::string::npos)
      << out.nc;
}

TEST(LinuxcncG76Emitter, InternalTowardPlusZ) {
  // Bore radius 13.9175 from Z-26 to Z0, depth 1.083 in 5 cuts; the tool waits at radius 11.
  // Clear line 2/(2 tan 30) = 1.732051 inside the bore: drive radius 12.185449, X24.3709;
  // I = 2·(13.9175 - 12.18545) = 3.4641 > 0 (internal); J = 2.166/√5 = 0.9686647 -> 0.968665.
  Machine m = shipped_machine("linuxcnc-lathe");
  ThreadPlan plan = plan_for(m, "THREAD/ON,MMPR,2,DEPTH,1.083,CUTS,5,OPTION,1", {11, -30},
                             {{13.9175, -26}, {13.9175, 0}});
  testing::Emitted out = emit_on(m, plan);
  ASSERT_TRUE(out.ok) << out.diags;
  EXPECT_NE(out.nc.find("G1 X24.3709 Z-26. G95 F0.2\n"
                        "G76 P2. Z0. I3.4641 J0.968665 K2.166 R2 Q30. H0\n"),
            std::string::npos)
      << out.nc;
}

TEST(LinuxcncG76Emitter, WhatG76CannotSay) {
  EXPECT_EQ(mismatch("THREAD/ON,MMPR,1.5,DEPTH,0.92,CUTS,4,OPTION,2"),
            "G76 cuts every pass on one flank; OPTION 2 alternates flanks");
  EXPECT_EQ(mismatch("THREAD/ON,MMPR,1.5,MULTRD,2,DEPTH,0.92,CUTS,4,OPTION,1"),
            "G76 has no start word; the thread has 2 starts");
  EXPECT_EQ(mismatch("THREAD/ON,MMPR,1.5,DEPTH,0.92,CUTS,4,OPTION,1", {13, 6},
                     {{10.5, 2}, {9.8125, -20}}),
            "G76 has no taper word; this is a taper thread");
  EXPECT_EQ(mismatch("THREAD/ON,MMPR,2,DEPTH,1.2,CUTS,4,OPTION,3", {42, 4}, {{40, 0}, {20, 0}}),
            "G76 threads along Z only; this is a face thread");
  EXPECT_EQ(mismatch("THREAD/ON,MMPR,1.5,DEPTH,0.3"),
            "G76 needs a first cut J below the full depth K; every pass of the plan is at depth "
            "0.3000");
  // OPTION 0, 5 cuts: 0.306667, 0.552, ...; G76 with J 0.306667 and R2 cuts 0.433689 second.
  EXPECT_EQ(mismatch("THREAD/ON,MMPR,1.5,DEPTH,0.92,CUTS,5,OPTION,0"),
            "G76's depth law, J times the R-th root of n, is not OPTION 0's steps decreasing by a "
            "constant amount; with R2, pass 2: depth 0.4337, plan 0.5520");
  // FINCUT 1, 0.3 after 4 OPTION 1 cuts to 0.62: G76 goes on with 0.31·√5 = 0.693187 < 0.92.
  EXPECT_EQ(mismatch("THREAD/ON,MMPR,1.5,DEPTH,0.92,CUTS,4,OPTION,1,FINCUT,1,0.3"),
            "G76 has no finish allowance, FINCUT: with R2, pass 5: depth 0.6932, plan 0.9200");
  // 45° chamfer of 1.5 rises 1.5; the exit taper rises by the depth.
  EXPECT_EQ(mismatch("THREAD/ON,MMPR,1.5,DEPTH,0.92,CUTS,4,OPTION,1,CHAMFR,1.5"),
            "G76's exit taper rises by the thread depth 0.9200; the plan's pull-out rises 1.5000");
  EXPECT_EQ(mismatch("THREAD/ON,MMPR,1.5,DEPTH,0.92,CUTS,4,OPTION,1,ATANGL,0,1.2"),
            "G76's exit taper runs along the thread; the plan pulls straight out by X2.4000 "
            "Z0.0000");
  // A 0.92 chamfer at 20°: the rise would need 0.92·tan 20 = 0.334852; it is fed with G1.
  EXPECT_EQ(mismatch("THREAD/ON,MMPR,1.5,DEPTH,0.92,CUTS,4,OPTION,1,CHAMFR,0.92,20"),
            "the plan feeds its pull-out with G1, 20.0 degrees to the thread is outside 30..60; "
            "G76 threads its exit taper");
}

TEST(LinuxcncG76Emitter, FallbackCommentThenEmulation) {
  Machine m = shipped_machine("linuxcnc-lathe");
  ThreadPlan plan = plan_for(m, "THREAD/ON,MMPR,1.5,DEPTH,0.92,CUTS,4,OPTION,2", kP0, {kP1, kP2});
  testing::Emitted out = emit_on(m, plan);
  ASSERT_TRUE(out.ok) << out.diags;
  EXPECT_EQ(out.nc.substr(0, out.nc.find('\n', out.nc.find('\n') + 1) + 1),
            "(G76 not used: G76 cuts every pass on one flank; OPTION 2 alternates flanks. "
            "emulation instead)\n"
            "(pass 1 depth 0.4600 rough)\n");
  EXPECT_EQ(out.nc.find("G76 P"), std::string::npos);
}

TEST(LinuxcncG76Emitter, FallbackErrorNamesTheLineAndTheDifference) {
  Machine m = shipped_machine("linuxcnc-lathe", {"threading.fallback=error"});
  ThreadPlan plan = plan_for(m, "THREAD/ON,MMPR,1.5,DEPTH,0.92,CUTS,5,OPTION,0", kP0, {kP1, kP2});
  testing::Emitted out = emit_on(m, plan);
  EXPECT_FALSE(out.ok);
  EXPECT_EQ(out.nc, "");
  EXPECT_EQ(out.diags,
            "t.cl:2:1: error: machine 'linuxcnc-lathe': G76 would not cut the planned passes: "
            "G76's depth law, J times the R-th root of n, is not OPTION 0's steps decreasing by a "
            "constant amount; with R2, pass 2: depth 0.4337, plan 0.5520 (threading.fallback is "
            "'error')\n"
            "  THREAD/ON\n"
            "  ^\n");
}

}  // namespace
}  // namespace clpost

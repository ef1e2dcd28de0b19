// heidenhain-pilot's G31: exact blocks, the reasons it is not used, the fallback comment and the
// fallback: error diagnostic.
#include "controls/heidenhain/heidenhain_emitter.h"

#include <gtest/gtest.h>

#include "emitters/emitter_test_util.h"

namespace clpost {
namespace {

using testing::emit_on;
using testing::plan_for;
using testing::shipped_machine;

const Vec2 kP0{10, 5}, kP1{8, 2}, kP2{8, -20};

std::string mismatch(const std::string& on, Vec2 p0 = kP0, std::vector<Vec2> gotos = {kP1, kP2}) {
  Machine m = shipped_machine("heidenhain-pilot", {"block_numbers.enabled=false"});
  HeidenhainG31Emitter e;
  return e.fit(plan_for(m, on, p0, gotos), m).mismatch;
}

TEST(HeidenhainG31Emitter, OptionOneWithAirCuts) {
  // 5 cuts of OPTION 1 to 0.92 and two spring passes: IC5 (the first cut at U is the 5th), Q2,
  // V0, H1 (the cuts move toward -Z), A = 60/2. Contour X16 Z2 -> X16 Z-20. The tool first goes
  // to the clear line, 1.299038 above the crest (X18.598).
  Machine m = shipped_machine("heidenhain-pilot", {"block_numbers.enabled=false"});
  ThreadPlan plan =
      plan_for(m, "THREAD/ON,MMPR,1.5,DEPTH,0.92,CUTS,5,OPTION,1,FINCUT,2", kP0, {kP1, kP2});
  testing::Emitted out = emit_on(m, plan);
  ASSERT_TRUE(out.ok) << out.diags;
  EXPECT_EQ(out.nc,
            "[G31 infeed law and flank offsets as clpost assumes them, unverified]\n"
            "G1 X18.598 Z2. G95 F0.2\n"
            "G31 F1.5 U0.92 IC5 V0 H1 A30. D1 Q2 C0. BD0 B0. P0. K0.\n"
            "G0 X16. Z2.\n"
            "G1 X16. Z-20.\n"
            "G80\n"
            "G0 X18.598 Z2.\n");
}

TEST(HeidenhainG31Emitter, OptionFourIsConstantInfeedAlternating) {
  Machine m = shipped_machine("heidenhain-pilot", {"block_numbers.enabled=false"});
  ThreadPlan plan = plan_for(m, "THREAD/ON,MMPR,1.5,DEPTH,0.92,CUTS,4,OPTION,4", kP0, {kP1, kP2});
  testing::Emitted out = emit_on(m, plan);
  ASSERT_TRUE(out.ok) << out.diags;
  EXPECT_NE(out.nc.find("G31 F1.5 U0.92 IC4 V1 H3 A30. D1 Q0 C0. BD0 B0. P0. K0.\n"),
            std::string::npos)
      << out.nc;
}

TEST(HeidenhainG31Emitter, RunInAndRunOut) {
  const std::string on = "THREAD/ON,MMPR,1.5,DEPTH,0.92,CUTS,4,OPTION,4";
  // A number is taken from the start of the CL's thread: B2, the contour from Z 2 - 2 = 0, so
  // that the cuts still start at the CL's Z 2.
  Machine num =
      shipped_machine("heidenhain-pilot", {"block_numbers.enabled=false", "threading.run_in=2"});
  testing::Emitted n = emit_on(num, plan_for(num, on, kP0, {kP1, kP2}));
  ASSERT_TRUE(n.ok) << n.diags;
  EXPECT_NE(n.nc.find("BD0 B2. P0. K0.\nG0 X16. Z0.\nG1 X16. Z-20.\n"), std::string::npos) << n.nc;
  // `auto` at 1000 rpm, lead 1.5: V = 25 mm/s, δ1 = 0.825 x 3.615170 = 2.982515 (B2.983) before
  // the CL's Z 2, δ2 = 0.825 (P0.825) after the contour's end, Z -20 + 0.825 = -19.175.
  Machine aut =
      shipped_machine("heidenhain-pilot", {"block_numbers.enabled=false", "threading.run_in=auto"});
  testing::Emitted a =
      emit_on(aut, plan_for(aut, on, kP0, {kP1, kP2}, true, LengthUnit::kMm, 1000));
  ASSERT_TRUE(a.ok) << a.diags;
  EXPECT_NE(a.nc.find("BD0 B2.983 P0.825 K0.\nG0 X16. Z2.\nG1 X16. Z-19.175\n"), std::string::npos)
      << a.nc;
}

TEST(HeidenhainG31Emitter, WhatG31IsNotUsedFor) {
  EXPECT_EQ(mismatch("THREAD/ON,MMPR,1.5,DEPTH,0.92,CUTS,4,OPTION,0"),
            "G31 has no infeed type for OPTION 0, steps decreasing by a constant amount");
  EXPECT_EQ(mismatch("THREAD/ON,MMPR,1.5,MULTRD,2,DEPTH,0.92,CUTS,4,OPTION,1"),
            "G31's multi-start order and spacing, D and C, are not documented; the thread has 2 "
            "starts");
  EXPECT_EQ(mismatch("THREAD/ON,MMPR,1.5,DEPTH,0.92,CUTS,4,OPTION,1,CHAMFR,1.5"),
            "G31's run-out K geometry is not documented; the plan has a pull-out");
  EXPECT_EQ(mismatch("THREAD/ON,MMPR,1.5,DEPTH,0.92,CUTS,4,OPTION,1,CUTANG,210"),
            "G31 feeds in radially or by its flank offset H; CUTANG 210 is not mapped");
  // FINCUT 1, 0.1: roughing 0.82·√(i/4) then 0.92; G31 V0 IC5 cuts 0.92·√(1/5) = 0.411437 first.
  EXPECT_EQ(mismatch("THREAD/ON,MMPR,1.5,DEPTH,0.92,CUTS,4,OPTION,1,FINCUT,1,0.1"),
            "G31 has no finish allowance, FINCUT: pass 1: depth 0.4114, plan 0.4100");
}

TEST(HeidenhainG31Emitter, FallbackIsTheG33Loop) {
  Machine m = shipped_machine("heidenhain-pilot", {"block_numbers.enabled=false"});
  ThreadPlan plan = plan_for(m, "THREAD/ON,MMPR,1.5,DEPTH,0.92,CUTS,4,OPTION,0", kP0, {kP1, kP2});
  testing::Emitted out = emit_on(m, plan);
  ASSERT_TRUE(out.ok) << out.diags;
  EXPECT_EQ(out.nc.substr(0, out.nc.find('\n') + 1),
            "[G31 not used: G31 has no infeed type for OPTION 0, steps decreasing by a constant "
            "amount. G33 loop instead]\n");
  EXPECT_NE(out.nc.find("G33 Z-20. F1.5\n"), std::string::npos) << out.nc;
}

TEST(HeidenhainG31Emitter, FallbackError) {
  Machine m = shipped_machine("heidenhain-pilot",
                              {"block_numbers.enabled=false", "threading.fallback=error"});
  ThreadPlan plan = plan_for(m, "THREAD/ON,MMPR,1.5,DEPTH,0.92,CUTS,4,OPTION,0", kP0, {kP1, kP2});
  testing::Emitted out = emit_on(m, plan);
  EXPECT_FALSE(out.ok);
  EXPECT_EQ(out.diags,
            "t.cl:2:1: error: machine 'heidenhain-pilot': G31 would not cut the planned passes: "
            "G31 has no infeed type for OPTION 0, steps decreasing by a constant amount "
            "(threading.fallback is 'error')\n"
            "  THREAD/ON\n"
            "  ^\n");
}

}  // namespace
}  // namespace clpost

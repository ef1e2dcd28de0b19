// Haas one-block G76 on machine haas-st: exact blocks, the OPTION -> P mapping, the settings
// (86, 95) as mismatches, multi-start by Q. Numbers by hand.
#include "controls/haas/haas_emitter.h"

#include <gtest/gtest.h>

#include "controls/fanuc/fanuc_test_util.h"

namespace clpost {
namespace {

using testing::load;
using testing::thread_on;

constexpr Vec2 kP0{10, 5};
const std::vector<Vec2> kM16{{8, 2}, {8, -20}};

std::string haas_fit(const std::string& on, std::vector<std::string> sets = {}) {
  Machine m = load("haas-st", sets);
  testing::Threaded t = thread_on(m, on, kP0, kM16);
  return HaasG76Emitter().fit(t.plan, m).mismatch;
}

TEST(HaasG76, Option1IsP1) {
  // Heights 0.92·√(i/6); D = ceil(0.375586) = 0.376; law 0.376·√n: 0.840762 at n = 5 (plan
  // 0.839841, 0.9 µm), 0.921008 ≥ 0.92 at n = 6 -> 0.92. K 0.92, X 2·7.08, A60, P1.
  Machine m = load("haas-st");
  testing::Threaded t = thread_on(m, "THREAD/ON,MMPR,1.5,DEPTH,0.92,CUTS,6,OPTION,1", kP0, kM16);
  ASSERT_TRUE(t.ok) << t.diags;
  EXPECT_EQ(t.nc,
            "(G76 ENDS EVERY PASS AT Z-20.; THE PLAN ENDS THE SHALLOWER PASSES UP TO 0.3143 "
            "EARLIER THREADING.ACCEPT_PASS_END)\n"
            "G0 X18.598 Z2.\n"
            "G76 X14.16 Z-20. K0.92 D0.376 A60 P1 F1.5\n");
}

TEST(HaasG76, Option3IsP3) {
  // 4 cuts of 0.23: D0.23, P3.
  Machine m = load("haas-st");
  testing::Threaded t = thread_on(m, "THREAD/ON,MMPR,1.5,DEPTH,0.92,CUTS,4,OPTION,3", kP0, kM16);
  ASSERT_TRUE(t.ok) << t.diags;
  EXPECT_EQ(t.nc.substr(t.nc.find("G0")),
            "G0 X18.598 Z2.\n"
            "G76 X14.16 Z-20. K0.92 D0.23 A60 P3 F1.5\n");
}

TEST(HaasG76, ThreeStartsOneBlockEachWithQ) {
  // Pitch 1 lead 3, 3 starts by angle, radius 12 from Z0 to Z-25, depth 0.613 in 3 cuts:
  // D = ceil(0.613/√3 = 0.353916) = 0.354; clear line 0.866025 above -> X25.732.
  Machine m = load("haas-st");
  testing::Threaded t = thread_on(m, "THREAD/ON,MMPR,1,MULTRD,3,DEPTH,0.613,CUTS,3,OPTION,1",
                                  {15, 6}, {{12, 0}, {12, -25}});
  ASSERT_TRUE(t.ok) << t.diags;
  EXPECT_EQ(t.nc.substr(t.nc.find("G0")),
            "G0 X25.732 Z0.\n"
            "G76 X22.774 Z-25. K0.613 D0.354 A60 P1 Q0 F3.\n"
            "G0 X25.732 Z0.\n"
            "G76 X22.774 Z-25. K0.613 D0.354 A60 P1 Q120000 F3.\n"
            "G0 X25.732 Z0.\n"
            "G76 X22.774 Z-25. K0.613 D0.354 A60 P1 Q240000 F3.\n");
  EXPECT_NE(t.nc.find("(G76 CUTS THE 3 STARTS ONE AFTER THE OTHER THE PLAN INTERLEAVES THEM)"),
            std::string::npos)
      << t.nc;
}

TEST(HaasG76, MismatchReasons) {
  EXPECT_EQ(haas_fit("THREAD/ON,MMPR,1.5,DEPTH,0.92,CUTS,5,OPTION,0"),
            "OPTION 0, steps shrinking by a constant amount: Haas G76 cuts D x root n with P1 or "
            "n x D with P3");
  EXPECT_EQ(haas_fit("THREAD/ON,MMPR,1.5,DEPTH,0.92,CUTS,6,OPTION,2"),
            "OPTION 2 alternates flanks: the control's alternating infeed P2 is not documented in "
            "our sources, unverified");
  EXPECT_EQ(haas_fit("THREAD/ON,MMPR,1.5,DEPTH,0.92,CUTS,4,FINCUT,1,0.05,OPTION,1"),
            "finish allowance 0.05 (FINCUT): the control's setting 86 "
            "(threading.haas_finish_allowance) is 0");
  EXPECT_EQ(haas_fit("THREAD/ON,MMPR,1.5,DEPTH,0.92,CUTS,4,FINCUT,2,0,OPTION,1"),
            "3 passes at full depth: Haas G76 cuts one (no spring passes)");
  EXPECT_EQ(haas_fit("THREAD/ON,MMPR,1.5,DEPTH,0.92,CUTS,4,OPTION,1,CHAMFR,1.5"),
            "pull-out (X 1.5, Z -1.5): the control's chamfer (setting 95, threading.haas_chamfer) "
            "is 0");
  EXPECT_EQ(haas_fit("THREAD/ON,MMPR,1.5,DEPTH,0.92,CUTS,4,OPTION,1", {"threading.haas_chamfer=1"}),
            "the plan has no pull-out; the control chamfers 1 leads (setting 95, "
            "threading.haas_chamfer)");
  EXPECT_EQ(haas_fit("THREAD/ON,MMPR,1.5,DEPTH,0.92,CUTS,4,OPTION,1,TLANGL,150"),
            "tool angle 150: A takes whole degrees 0-120");
  // The fixed pass end (Option1IsP1's note) not accepted: pass 1 of 6 at 0.92·√(1/6) shifted
  // 0.375586·tan 30 = 0.216845 ends 0.531162 - 0.216845 = 0.314317 before the deepest.
  EXPECT_EQ(haas_fit("THREAD/ON,MMPR,1.5,DEPTH,0.92,CUTS,6,OPTION,1",
                     {"threading.accept_pass_end=false"}),
            "G76 ends every pass at Z-20.; the plan ends the shallower passes up to 0.3143 "
            "earlier (threading.accept_pass_end is off)");
}

TEST(HaasG76, SettingsThatMatchThePlan) {
  // Setting 86 = 0.05 and a FINCUT 1,0.05 plan: R = 0.87, heights 0.87·√(i/4) = 0.435, ...;
  // D = 0.435, K = 0.92 -> roughing 0.435·√n clamped at 0.87 (n = 4), then one pass at 0.92.
  // Setting 95 = 1 lead with CHAMFR 1.5 at 45°: Z where the chamfer ends, -21.5.
  Machine m = load("haas-st", {"threading.haas_finish_allowance=0.05", "threading.haas_chamfer=1"});
  testing::Threaded t = thread_on(
      m, "THREAD/ON,MMPR,1.5,DEPTH,0.92,CUTS,4,FINCUT,1,0.05,OPTION,1,CHAMFR,1.5", kP0, kM16);
  ASSERT_TRUE(t.ok) << t.diags;
  EXPECT_NE(t.nc.find("G76 X14.16 Z-21.5 K0.92 D0.435 A60 P1 F1.5\n"), std::string::npos) << t.nc;
}

}  // namespace
}  // namespace clpost

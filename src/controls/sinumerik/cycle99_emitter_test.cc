// CYCLE99 on sinumerik-840d: plans made by the planner from CL text, the words and blocks
// written, every reason the cycle is not used, and the G33 loop it falls back to.
#include "controls/sinumerik/cycle99_emitter.h"

#include <gtest/gtest.h>

#include <cmath>
#include <numbers>

#include "controls/registry.h"
#include "emitters/planner_settings.h"
#include "machine/machine_loader.h"
#include "planner/planner_test_util.h"

namespace clpost {
namespace {

using testing::make_multi;
using testing::TestStatement;

Machine siemens(std::vector<std::string> sets = {}) {
  Machine m;
  std::string errors;
  sets.push_back("block_numbers.enabled=false");
  EXPECT_TRUE(
      load_machine("sinumerik-840d", {CLPOST_SOURCE_DIR}, sets, shipped_controls(), m, errors))
      << errors;
  return m;
}

// THREAD/ON,<words> on line 2 with P0 and the GOTOs, planned for machine `m`.
struct Case {
  explicit Case(const std::string& words) : on("THREAD/ON," + words, 2) {}
  TestStatement on;
  ThreadPlan plan;
  bool ok = false;
  std::string diags;
};

std::unique_ptr<Case> plan(const Machine& m, const std::string& words, Vec2 p0,
                           std::vector<Vec2> gotos, LengthUnit units = LengthUnit::kMm,
                           double rpm = 0) {
  auto c = std::make_unique<Case>(words);
  Diagnostics d("t.cl");
  testing::MultiCase mc = make_multi(c->on, units, p0, gotos, d);
  EXPECT_TRUE(mc.parsed) << d.render_all();
  mc.in.rpm = rpm;
  PlannerSettings s = planner_settings(m);
  c->ok = plan_multi_thread(mc.in, s, c->plan, d);
  c->diags = d.render_all();
  EXPECT_TRUE(c->ok) << c->diags;
  return c;
}

// M16x1.5 external, radius 8 from Z2 to Z-20, tool at X10 Z5 (radius).
std::unique_ptr<Case> m16(const Machine& m, const std::string& words,
                          std::optional<Vec2> p3 = std::nullopt) {
  std::vector<Vec2> g = {{8, 2}, {8, -20}};
  if (p3) g.push_back(*p3);
  return plan(m, "MMPR,1.5,DEPTH,0.92," + words, {10, 5}, g);
}

struct Out {
  std::string nc, diags;
  bool ok = false;
};

Out emit_with(Emitter& e, const Machine& m, const Case& c) {
  Out o;
  StringSink sink;
  NcProgram prog(m, sink);
  Diagnostics d("t.cl");
  SavedLines lines = c.on.saved();
  EmitContext ctx{d, lines, 800, 0.2, FeedMode::kPerRev};
  o.ok = e.emit(c.plan, prog, ctx);
  o.nc = sink.out;
  o.diags = d.render_all();
  return o;
}

Out emit_cycle(const Machine& m, const Case& c) {
  Cycle99Emitter e;
  return emit_with(e, m, c);
}

Out emit_chain(const Machine& m, const Case& c) {
  auto e = make_emitter(m);
  return emit_with(*e, m, c);
}

std::string mismatch(const Machine& m, const Case& c) {
  return cycle99_call(c.plan, m).mismatch;
}

// ---------------------------------------------------------------------------------------------
// Exact plans: the words and the block.

TEST(Cycle99Emitter, SingleFlankConstantCrossSection) {
  Machine m = siemens();
  auto c = m16(m, "CUTS,4,OPTION,1");
  Cycle99Call call = cycle99_call(c->plan, m);
  ASSERT_EQ(call.mismatch, "");
  EXPECT_TRUE(call.notes.empty());
  // OPTION 1: d = 0.92 sqrt(i/4), shift d tan 30 along the cut -> VARI 300103, IANG +30.
  // Clear line 1.5 / (2 tan 30) = 1.299038 above the crest: start X 2 x 9.299038 = 18.598, Z2.
  EXPECT_EQ(emit_cycle(m, *c).nc,
            "G0 X18.598 Z2\n"
            "CYCLE99(2, 16, -20, 16, 0, 0, 0.92, 0, 30, 0, 4, 0, 1.5, 300103, 0, 1.299, 0, 0, 0, "
            "0, 0, 0, 1, \"\", \"\", \"\", 0)\n");
}

TEST(Cycle99Emitter, InternalConstantInfeedWithFinishAndIdlePass) {
  Machine m = siemens();
  // M30x2 internal, tap hole radius 13.9175 (diameter 27.835), Z2 to Z-24, bar at X11.
  // R = 1.083 - 0.083 = 1 in 4 cuts of 0.25 (OPTION 3), finish at 1.083 (FAL 0.083), one spring
  // pass (NID 1). Clear line 2 / (2 tan 30) = 1.732051 inside the bore: X 2 x 12.185449.
  auto c = plan(m, "MMPR,2,DEPTH,1.083,CUTS,4,FINCUT,2,0.083,OPTION,3", {11, 5},
                {{13.9175, 2}, {13.9175, -24}});
  EXPECT_EQ(emit_cycle(m, *c).nc,
            "G0 X24.371 Z2\n"
            "CYCLE99(2, 27.835, -24, 27.835, 0, 0, 1.083, 0.083, 30, 0, 4, 1, 2, 300102, 0, "
            "1.7321, 0, 0, 0, 0, 0, 0, 1, \"\", \"\", \"\", 0)\n");
}

TEST(Cycle99Emitter, SpringPassesWithoutAllowanceAreIdlePasses) {
  Machine m = siemens();
  // FINCUT,2,0: roughing reaches 0.92, then two passes at 0.92 = NID 2, FAL 0.
  auto c = m16(m, "CUTS,4,FINCUT,2,0,OPTION,1");
  Cycle99Call call = cycle99_call(c->plan, m);
  ASSERT_EQ(call.mismatch, "");
  EXPECT_EQ(call.words.nrc, 4);
  EXPECT_EQ(call.words.nid, 2);
  EXPECT_EQ(call.words.fal, 0);
  EXPECT_DOUBLE_EQ(call.words.tdep, 0.92);
}

TEST(Cycle99Emitter, FinishAllowanceWithoutFinishPassCutsToTheRoughingDepth) {
  Machine m = siemens();
  // FINCUT,0,0.12: the plan stops at 0.92 - 0.12 = 0.8, so TDEP 0.8, FAL 0, NID 0.
  auto c = m16(m, "CUTS,4,FINCUT,0,0.12,OPTION,3");
  Cycle99Call call = cycle99_call(c->plan, m);
  ASSERT_EQ(call.mismatch, "");
  EXPECT_DOUBLE_EQ(call.words.tdep, 0.8);
  EXPECT_EQ(call.words.fal, 0);
  EXPECT_EQ(call.words.nid, 0);
  EXPECT_EQ(call.words.vari, kVariExternalConstantInfeed);
}

TEST(Cycle99Emitter, NegativeChamferIsTheRunOut) {
  Machine m = siemens();
  // CHAMFR,-1.5: every pass ends 1.5 early and runs out at 45 degrees to Z-20 = FPL, ROP 1.5.
  auto c = m16(m, "CUTS,4,OPTION,1,CHAMFR,-1.5");
  EXPECT_EQ(emit_cycle(m, *c).nc,
            "G0 X18.598 Z2\n"
            "CYCLE99(2, 16, -20, 16, 0, 1.5, 0.92, 0, 30, 0, 4, 0, 1.5, 300103, 0, 1.299, 0, 0, "
            "0, 0, 0, 0, 1, \"\", \"\", \"\", 0)\n");
}

TEST(Cycle99Emitter, MultiStartCutsStartByStartWithANote) {
  Machine m = siemens();
  // Two starts by spindle angle (start_angle_word): lead 3, NUMTH 2; the clear line uses the
  // pitch: 1.299.
  auto c = m16(m, "MULTRD,2,CUTS,4,OPTION,1");
  EXPECT_EQ(emit_chain(m, *c).nc,
            "; CYCLE99 cuts start by start: every pass of start 1, then of start 2\n"
            "G0 X18.598 Z2\n"
            "CYCLE99(2, 16, -20, 16, 0, 0, 0.92, 0, 30, 0, 4, 0, 3, 300103, 2, 1.299, 0, 0, 0, "
            "0, 0, 0, 1, \"\", \"\", \"\", 0)\n");
}

TEST(Cycle99Emitter, ThreadsPerInchArePita2) {
  Machine m = siemens();
  // 13 TPI in a metric program: lead 25.4 / 13 = 1.953846 mm; PIT 13, PITA 2.
  auto c = plan(m, "TPI,13,DEPTH,1.2,CUTS,3,OPTION,3", {10, 5}, {{8, 2}, {8, -20}});
  Cycle99Call call = cycle99_call(c->plan, m);
  ASSERT_EQ(call.mismatch, "");
  EXPECT_EQ(call.words.pita, 2);
  EXPECT_DOUBLE_EQ(call.words.pit, 13);
}

TEST(Cycle99Emitter, AngledInfeedIsIang) {
  Machine m = siemens();
  // CUTANG 210: 30 degrees off -X toward -Z (the cutting direction): IANG +30. The plunge is
  // along CUTANG, so pass i starts d tan 30 further along and the deepest pass ends
  // 0.92 tan 30 = 0.531162 past P2: FPL -20.531.
  auto c = m16(m, "CUTS,4,OPTION,3,CUTANG,210");
  Cycle99Call call = cycle99_call(c->plan, m);
  ASSERT_EQ(call.mismatch, "");
  EXPECT_DOUBLE_EQ(call.words.iang, 30);
  EXPECT_DOUBLE_EQ(call.words.fpl, -20.531);
  EXPECT_EQ(call.words.vari, kVariExternalConstantInfeed);
}

TEST(Cycle99Emitter, TaperAndFaceThreads) {
  Machine m = siemens();
  // Taper 1:32 on the radius: PSYS 20, DM1 21, DM2 19.625.
  auto taper = plan(m, "MMPR,1.814,DEPTH,1.1,CUTS,5,OPTION,1", {13, 6}, {{10.5, 2}, {9.8125, -20}});
  Cycle99Call t = cycle99_call(taper->plan, m);
  ASSERT_EQ(t.mismatch, "");
  EXPECT_EQ(t.words.psys, 20);
  EXPECT_DOUBLE_EQ(t.words.dm1, 21);
  EXPECT_DOUBLE_EQ(t.words.dm2, 19.625);
  // TDEP is paraxial: 1.1 / cos(atan(0.6875 / 22)) = 1.1 / 0.999512 = 1.100537 -> 1.1005.
  EXPECT_DOUBLE_EQ(t.words.tdep, 1.1005);
  // Face thread at Z0 from radius 40 to 20, infeed -Z: PSYS 10, DM1 80, DM2 40.
  auto face = plan(m, "MMPR,2,DEPTH,1.2,CUTS,4,OPTION,3", {42, 4}, {{40, 0}, {20, 0}});
  Cycle99Call f = cycle99_call(face->plan, m);
  ASSERT_EQ(f.mismatch, "");
  EXPECT_EQ(f.words.psys, 10);
  EXPECT_DOUBLE_EQ(f.words.dm1, 80);
  EXPECT_DOUBLE_EQ(f.words.dm2, 40);
  EXPECT_DOUBLE_EQ(f.words.spl, 0);
  EXPECT_DOUBLE_EQ(f.words.fpl, 0);
}

TEST(Cycle99Emitter, RunInMovesSplForward) {
  Machine m = siemens({"threading.run_in=2"});
  // APP 2: SPL 2 mm into the thread (Z0), so the cut still starts at the CL's Z2.
  auto c = m16(m, "CUTS,4,OPTION,3");
  Cycle99Call call = cycle99_call(c->plan, m);
  ASSERT_EQ(call.mismatch, "");
  EXPECT_DOUBLE_EQ(call.words.app, 2);
  EXPECT_DOUBLE_EQ(call.words.spl, 0);
}

TEST(Cycle99Emitter, RunInAutoLiesBeforeSpl) {
  Machine m = siemens({"threading.run_in=auto"});
  // 1000 rpm, lead 1.5: V = 25 mm/s, δ1 = 0.825 x 3.615170 = 2.982515. Every pass begins that
  // much before the CL's Z 2; SPL stays Z 2 and APP is δ1 (2.9825 at 4 decimals).
  auto c = plan(m, "MMPR,1.5,DEPTH,0.92,CUTS,4,OPTION,3", {10, 5}, {{8, 2}, {8, -20}},
                LengthUnit::kMm, 1000);
  EXPECT_NEAR(c->plan.passes.back().from.z, 2 + 2.982515 - 0.92 * std::tan(std::numbers::pi / 6),
              1e-6);
  Cycle99Call call = cycle99_call(c->plan, m);
  ASSERT_EQ(call.mismatch, "");
  EXPECT_DOUBLE_EQ(call.words.app, 2.9825);
  EXPECT_DOUBLE_EQ(call.words.spl, 2);
  EXPECT_DOUBLE_EQ(call.words.fpl, -20);
  EXPECT_DOUBLE_EQ(call.words.iang, 30);
}

// ---------------------------------------------------------------------------------------------
// Every reason CYCLE99 is not used.

TEST(Cycle99Emitter, Option0HasNoCycle99Law) {
  Machine m = siemens();
  // OPTION 0, 5 cuts: d1 = 0.92 x 1 x 10 / 30 = 0.306667; constant infeed gives 0.92 / 5.
  EXPECT_EQ(mismatch(m, *m16(m, "CUTS,5,OPTION,0")),
            "CYCLE99 has no infeed with steps decreasing by a constant amount (OPTION 0): VARI "
            "300101 (constant infeed) cuts pass 1: depth 0.1840, plan 0.3067");
  // One cut: every law gives the full depth, so the cycle is exact.
  EXPECT_EQ(mismatch(m, *m16(m, "CUTS,1,OPTION,0")), "");
}

TEST(Cycle99Emitter, AlternatingFlanks) {
  Machine m = siemens();
  // OPTION 2: odd passes straight, even ones shifted; pass 6 at 0.92 by 0.92 tan 30.
  EXPECT_EQ(mismatch(m, *m16(m, "CUTS,6,OPTION,2")),
            "CYCLE99 infeeds along one flank (IANG); OPTION 2 alternates the flanks (pass 1 "
            "shift 0.0000, pass 6 shift 0.5312)");
  EXPECT_EQ(mismatch(m, *m16(m, "CUTS,4,OPTION,4")),
            "CYCLE99 infeeds along one flank (IANG); OPTION 4 alternates the flanks (pass 1 "
            "shift 0.0000, pass 4 shift 0.5312)");
}

TEST(Cycle99Emitter, StepLadderIsNotTheCycleLaw) {
  Machine m = siemens();
  // STEP 0.3, OPTION 1: c = ceil((0.92/0.3)^2) = 10, d1 = 0.3; CYCLE99: 0.92 sqrt(1/10).
  EXPECT_EQ(mismatch(m, *m16(m, "STEP,0.3,OPTION,1")),
            "VARI 300103 (constant cross-section) cuts pass 1: depth 0.2909, plan 0.3000");
}

TEST(Cycle99Emitter, PullOutsPastTheThreadEnd) {
  Machine m = siemens();
  EXPECT_EQ(mismatch(m, *m16(m, "CUTS,4,OPTION,1,CHAMFR,1.5")),
            "CYCLE99 has no pull-out past the thread end, only the run-out ROP that ends at FPL "
            "(CL CHAMFR with a negative length); this pull-out moves (X 1.5, Z -1.5) from the "
            "pass end");
  EXPECT_EQ(mismatch(m, *m16(m, "CUTS,4,OPTION,1,ATANGL,0,1.2")),
            "CYCLE99 has no pull-out past the thread end, only the run-out ROP that ends at FPL "
            "(CL CHAMFR with a negative length); this pull-out moves (X 1.2, Z 0) from the pass "
            "end");
  EXPECT_EQ(mismatch(m, *m16(m, "CUTS,4,OPTION,1", Vec2{9.5, -21})),
            "CYCLE99 has no pull-out past the thread end, only the run-out ROP that ends at FPL "
            "(CL CHAMFR with a negative length); this pull-out moves (X 1.5, Z -1) from the pass "
            "end");
}

TEST(Cycle99Emitter, RunOutAtAnotherAngle) {
  Machine m = siemens();
  // CHAMFR,-1.5,30: 1.5 along the thread and 1.5 tan 30 = 0.866025 out.
  EXPECT_EQ(mismatch(m, *m16(m, "CUTS,4,OPTION,1,CHAMFR,-1.5,30")),
            "CYCLE99's run-out ROP leaves the thread at 45 degrees (unverified); this run-out "
            "rises 0.866025 over 1.5 (30 degrees)");
}

TEST(Cycle99Emitter, InfeedAngleOverHalfTheToolAngle) {
  Machine m = siemens();
  EXPECT_EQ(mismatch(m, *m16(m, "CUTS,4,OPTION,3,CUTANG,220")),
            "IANG 40.0000 is more than half the tool angle 60 (CYCLE99 allows at most 30)");
}

TEST(Cycle99Emitter, VariableLead) {
  Machine m = siemens();
  EXPECT_EQ(mismatch(m, *m16(m, "INCR,0.1,CUTS,4,OPTION,1")),
            "CYCLE99 cuts a constant lead; this lead grows (INCR) by 0.1 per revolution");
}

TEST(Cycle99Emitter, StartsByOffset) {
  Machine m = siemens({"threading.start_angle_word=false"});
  EXPECT_EQ(mismatch(m, *m16(m, "MULTRD,2,CUTS,4,OPTION,1")),
            "CYCLE99 spreads the 2 starts over the spindle angle (NUMTH); this plan offsets them "
            "by the pitch (threading.start_angle_word is false)");
}

TEST(Cycle99Emitter, FaceLikeTaperAndFaceTowardPlusZ) {
  Machine m = siemens();
  auto taper = plan(m, "MMPR,2,DEPTH,1.2,CUTS,4,OPTION,3", {42, 4}, {{40, 0}, {20, -2}});
  EXPECT_EQ(mismatch(m, *taper),
            "CYCLE99 takes a taper thread's lead along Z (unverified); this taper's lead is along "
            "X (X travel 20 > Z travel 2)");
  auto face = plan(m, "MMPR,2,DEPTH,1.2,CUTS,4,OPTION,3", {42, -4}, {{40, 0}, {20, 0}});
  EXPECT_EQ(mismatch(m, *face),
            "CYCLE99 cuts a face thread toward -Z (unverified); this one's infeed goes toward +Z");
}

TEST(Cycle99Emitter, ContourPassHasNoDepth) {
  Machine m = siemens();
  auto c = plan(m, "MMPR,1.5,CUTS,1", {10, 5}, {{8, 2}, {8, -20}});
  EXPECT_EQ(mismatch(m, *c),
            "CYCLE99 needs a thread depth (TDEP); this thread is one pass on the contour");
}

TEST(Cycle99Emitter, LeadRoundedAwayByTheFormat) {
  Machine m = siemens({"formats.cycle99_lead.decimals=1"});
  // PIT 1.814 written as 1.8: 0.014 x 22 / 1.814 = 12.1 turns -> 0.1698 at the thread end.
  auto c = plan(m, "MMPR,1.814,DEPTH,1.1,CUTS,5,OPTION,3", {10, 5}, {{8, 2}, {8, -20}});
  EXPECT_EQ(mismatch(m, *c),
            "the lead 1.814000 is written PIT 1.8 (PITA 1), 1.800000 (formats.cycle99_lead: 1 "
            "decimal): 0.1698 off over the thread's 12.1 turns, more than the tolerance 0.001");
}

// ---------------------------------------------------------------------------------------------
// The fallback: a G33 loop with K, SF= and G34/G35, and the comment saying why.

TEST(Cycle99Emitter, FallbackIsTheG33LoopWithAComment) {
  Machine m = siemens();
  auto c = m16(m, "CUTS,2,OPTION,2");
  Out o = emit_chain(m, *c);
  EXPECT_TRUE(o.ok);
  // Pass 1 straight at 0.92 sqrt(1/2) = 0.650538 (X 2 x 7.349462), ending 0.531162 before Z-20
  // (the shift of the deepest pass); pass 2 at 0.92 shifted 0.531162 (Z1.469), ends at Z-20.
  EXPECT_EQ(o.nc,
            "; CYCLE99 not used: CYCLE99 infeeds along one flank (IANG); OPTION 2 alternates the "
            "flanks (pass 1 shift 0.0000, pass 2 shift 0.5312). G33 loop instead\n"
            "; pass 1 depth 0.6505 rough\n"
            "G0 X18.598 Z2\n"
            "X14.699\n"
            "G33 Z-19.469 K1.5\n"
            "G0 X18.598\n"
            "; pass 2 depth 0.9200 rough\n"
            "Z1.469\n"
            "X14.16\n"
            "G33 Z-20 K1.5\n"
            "G0 X18.598\n"
            "Z2\n");
}

TEST(Cycle99Emitter, FallbackStartAngleIsSfEquals) {
  Machine m = siemens();
  auto c = m16(m, "MULTRD,2,CUTS,1,OPTION,2,CHAMFR,1.5");
  Out o = emit_chain(m, *c);
  // The SF= address is written as the machine names it, with the angle after it.
  EXPECT_NE(o.nc.find("G33 Z-20 K3 SF=0\n"), std::string::npos) << o.nc;
  EXPECT_NE(o.nc.find("G33 Z-20 K3 SF=180\n"), std::string::npos) << o.nc;
}

TEST(Cycle99Emitter, FallbackFaceThreadLeadIsI) {
  Machine m = siemens();
  // A face thread (X travel only) with alternating flanks: G33 X... I<lead>, never K.
  auto c = plan(m, "MMPR,2,DEPTH,1.2,CUTS,2,OPTION,4", {42, 4}, {{40, 0}, {20, 0}});
  Out o = emit_chain(m, *c);
  EXPECT_NE(o.nc.find("G33 X40 I2\n"), std::string::npos) << o.nc;
  EXPECT_EQ(o.nc.find(" K2"), std::string::npos) << o.nc;
}

TEST(Cycle99Emitter, VariableLeadIsG34OrG35) {
  Machine m = siemens();
  // Lead 1.5 growing 0.1 per revolution: G34 K1.5 F0.1 (F = |dK| per revolution).
  Out inc = emit_chain(m, *m16(m, "INCR,0.1,CUTS,1,OPTION,3"));
  EXPECT_NE(inc.nc.find("; CYCLE99 not used: CYCLE99 cuts a constant lead; this lead grows (INCR) "
                        "by 0.1 per revolution. G33 loop instead\n"),
            std::string::npos)
      << inc.nc;
  EXPECT_NE(inc.nc.find("G34 Z-20 K1.5 F0.1\n"), std::string::npos) << inc.nc;
  Out dec = emit_chain(m, *m16(m, "DECR,0.02,CUTS,1,OPTION,3"));
  EXPECT_NE(dec.nc.find("G35 Z-20 K1.5 F0.02\n"), std::string::npos) << dec.nc;
}

TEST(Cycle99Emitter, FallbackErrorNamesTheLineAndTheDifference) {
  Machine m = siemens({"threading.fallback=error"});
  auto c = m16(m, "CUTS,5,OPTION,0");
  Out o = emit_chain(m, *c);
  EXPECT_FALSE(o.ok);
  EXPECT_EQ(o.nc, "");
  EXPECT_EQ(o.diags,
            "t.cl:2:1: error: machine 'sinumerik-840d': CYCLE99 would not cut the planned passes: "
            "CYCLE99 has no infeed with steps decreasing by a constant amount (OPTION 0): VARI "
            "300101 (constant infeed) cuts pass 1: depth 0.1840, plan 0.3067 "
            "(threading.fallback is 'error')\n"
            "  THREAD/ON,MMPR,1.5,DEPTH,0.92,CUTS,5,OPTION,0\n"
            "  ^\n");
}

}  // namespace
}  // namespace clpost

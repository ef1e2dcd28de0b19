// Multi-pass thread planning: geometry, flank shifts, pull-outs, return, multi-start, errors.
// Unless a test says otherwise: mm, pitch 1.5 (default return height 1.5 / (2 tan 30) =
// 1.5 * sqrt(3) / 2 = 1.299038), P0 = (X 12, Z 5), P1 = (X 10, Z 2), P2 = (X 10, Z -20):
// an external turn thread 22 long cut toward -Z. THREAD/ON is on line 2, the GOTOs on 3, 4, 5...
#include "planner/planner.h"

#include <fmt/format.h>
#include <gtest/gtest.h>

#include <cmath>
#include <numbers>
#include <string>
#include <vector>

#include "planner/planner_test_util.h"
#include "support/angles.h"

namespace clpost {
namespace {

using testing::make_multi;
using testing::pitch_of;
using testing::TestStatement;

const double kH = 1.5 * std::sqrt(3.0) / 2;  // 1.299038: pitch / (2 tan 30)
const double kTan30 = 1 / std::sqrt(3.0);    // 0.577350
const Vec2 kP0{12, 5};
const Vec2 kP1{10, 2};
const Vec2 kP2{10, -20};

#define EXPECT_POINT(p, px, pz)           \
  do {                                    \
    EXPECT_NEAR((p).x, (px), 1e-9) << #p; \
    EXPECT_NEAR((p).z, (pz), 1e-9) << #p; \
  } while (0)

std::string messages(const Diagnostics& d) {
  std::string out;
  for (const Diagnostic& x : d.kept()) {
    const std::string s = d.render(x);
    out += s.substr(0, s.find('\n') + 1);
  }
  return out;
}

struct Planned {
  bool ok = false;
  ThreadPlan plan;
  std::string messages;
};

struct Geometry {
  Vec2 p0 = kP0;
  std::vector<Vec2> gotos = {kP1, kP2};
  PitchSpec modal = pitch_of(1.5);
  PlannerSettings settings;
  LengthUnit units = LengthUnit::kMm;
  std::string on_word = "THREAD/ON";
  std::string off_word = "THREAD/OFF";
  size_t first_arg = 1;  // 2 for OP/THREAD,TURN,...
};

Planned plan(const std::string& on_line, const Geometry& s = {}) {
  TestStatement on(on_line, 2);
  Diagnostics d("t.cl");
  testing::MultiCase c = make_multi(on, s.units, s.p0, s.gotos, d, s.first_arg);
  Planned r;
  if (!c.parsed) {
    ADD_FAILURE() << "words do not parse: " << on_line << "\n" << d.render_all();
    return r;
  }
  c.in.modal_pitch = s.modal;
  c.in.on_word = s.on_word;
  c.in.off_word = s.off_word;
  r.ok = plan_multi_thread(c.in, s.settings, r.plan, d);
  EXPECT_EQ(r.ok, !d.has_errors());
  r.messages = messages(d);
  return r;
}

std::vector<double> depths(const ThreadPlan& p) {
  std::vector<double> v;
  for (const ThreadPass& s : p.passes) v.push_back(s.depth);
  return v;
}

// --- Geometry. ---

TEST(Planner, ExternalTurnDefaults) {
  Planned r = plan("THREAD/ON,DEPTH,0.92,CUTS,3");
  ASSERT_TRUE(r.ok) << r.messages;
  const ThreadPlan& p = r.plan;
  EXPECT_EQ(p.form, ThreadForm::kMulti);
  EXPECT_EQ(p.kind, ThreadKind::kTurn);
  EXPECT_EQ(p.side, ThreadSide::kExternal);
  EXPECT_TRUE(p.lead_along_z);
  EXPECT_EQ(p.cutang, 180);  // default: along X toward the line from P0 (12 -> 10: -X)
  EXPECT_EQ(p.option, 0);
  EXPECT_EQ(p.tool_angle, 60);
  EXPECT_EQ(p.pitch.pitch, 1.5);
  EXPECT_EQ(p.lead, 1.5);
  EXPECT_EQ(p.depth, 0.92);
  EXPECT_EQ(p.loc.line, 2u);
  EXPECT_FALSE(p.pullout.has_value());
  EXPECT_NEAR(p.clearance, kH, 1e-12);
  // OPTION 0, c = 3, R = 0.92: d_i = 0.92 i (7 - i) / 12 -> 0.46, 0.766667, 0.92.
  ASSERT_EQ(p.passes.size(), 3u);
  const double d[] = {0.46, 0.92 * 10 / 12, 0.92};
  for (int i = 0; i < 3; ++i) {
    const ThreadPass& s = p.passes[i];
    EXPECT_EQ(s.n, i + 1);
    EXPECT_EQ(s.start, 0);
    EXPECT_EQ(s.kind, PassKind::kRough);
    EXPECT_NEAR(s.depth, d[i], 1e-12);
    EXPECT_EQ(s.shift, 0);
    // Depth d along -X from the crest line X 10.
    EXPECT_POINT(s.from, 10 - d[i], 2);
    EXPECT_POINT(s.to, 10 - d[i], -20);
    EXPECT_POINT(s.pullout_end, 10 - d[i], -20);
    // Clear line 1.299038 above the crest: X 11.299038.
    EXPECT_POINT(s.clear, 10 + kH, -20);
    EXPECT_POINT(s.approach, 10 + kH, 2);
  }
  EXPECT_POINT(p.end_position, 10 + kH, 2);
  EXPECT_POINT(p.p0, 12, 5);
  EXPECT_POINT(p.p1, 10, 2);
  EXPECT_POINT(p.p2, 10, -20);
}

TEST(Planner, InternalTurn) {
  // Bore X 5, tool inside at X 3: infeed +X (CUTANG 0), internal.
  Geometry s;
  s.p0 = {3, 5};
  s.gotos = {{5, 2}, {5, -20}};
  Planned r = plan("THREAD/ON,CUTS,2,0.4", s);
  ASSERT_TRUE(r.ok) << r.messages;
  const ThreadPlan& p = r.plan;
  EXPECT_EQ(p.cutang, 0);
  EXPECT_EQ(p.side, ThreadSide::kInternal);
  // 0.4, 0.8 outward into the wall: X 5.4, 5.8.
  EXPECT_POINT(p.passes[0].from, 5.4, 2);
  EXPECT_POINT(p.passes[1].to, 5.8, -20);
  // Clear line toward the axis: X 5 - 1.299038.
  EXPECT_POINT(p.passes[0].approach, 5 - kH, 2);
  EXPECT_POINT(p.passes[1].clear, 5 - kH, -20);
  EXPECT_POINT(p.end_position, 5 - kH, 2);
}

TEST(Planner, InternalByCutang) {
  Geometry s;
  s.p0 = {3, 5};
  s.gotos = {{5, 2}, {5, -20}};
  Planned r = plan("THREAD/ON,DEPTH,0.8,CUTANG,0", s);
  ASSERT_TRUE(r.ok) << r.messages;
  EXPECT_EQ(r.plan.side, ThreadSide::kInternal);
}

TEST(Planner, FaceThread) {
  // Face at Z 0 from X 10 down to X 2; tool in front at Z 3: infeed -Z (270), reported external.
  Geometry s;
  s.p0 = {12, 3};
  s.gotos = {{10, 0}, {2, 0}};
  Planned r = plan("THREAD/ON,CUTS,2,0.5", s);
  ASSERT_TRUE(r.ok) << r.messages;
  const ThreadPlan& p = r.plan;
  EXPECT_EQ(p.kind, ThreadKind::kFace);
  EXPECT_FALSE(p.lead_along_z);
  EXPECT_EQ(p.cutang, 270);
  EXPECT_EQ(p.side, ThreadSide::kExternal);
  EXPECT_POINT(p.passes[0].from, 10, -0.5);
  EXPECT_POINT(p.passes[0].to, 2, -0.5);
  EXPECT_POINT(p.passes[1].to, 2, -1);
  EXPECT_POINT(p.passes[0].approach, 10, kH);
  EXPECT_POINT(p.passes[1].clear, 2, kH);
  EXPECT_POINT(p.end_position, 10, kH);
}

TEST(Planner, FaceThreadFromBehind) {
  // Tool at Z -3 (a back face): infeed +Z (90).
  Geometry s;
  s.p0 = {12, -3};
  s.gotos = {{10, 0}, {2, 0}};
  Planned r = plan("THREAD/ON,DEPTH,1", s);
  ASSERT_TRUE(r.ok) << r.messages;
  EXPECT_EQ(r.plan.cutang, 90);
  EXPECT_EQ(r.plan.side, ThreadSide::kExternal);
  EXPECT_POINT(r.plan.passes[0].from, 10, 1);
}

TEST(Planner, TurnTaper) {
  // P1 (10, 2) -> P2 (11, -20): dX = 1, dZ = -22: taper, lead along Z, infeed -X.
  // t = (1, -22)/sqrt(485); n = (-22, -1)/sqrt(485) (n.u > 0 for u = -X); n.u = 22/sqrt(485).
  // A depth d is d / (n.u) = d sqrt(485) / 22 along -X.
  Geometry s;
  s.p0 = {14, 5};
  s.gotos = {{10, 2}, {11, -20}};
  Planned r = plan("THREAD/ON,DEPTH,1", s);
  ASSERT_TRUE(r.ok) << r.messages;
  const ThreadPlan& p = r.plan;
  const double r485 = std::sqrt(485.0);
  EXPECT_EQ(p.kind, ThreadKind::kTaper);
  EXPECT_TRUE(p.lead_along_z);
  EXPECT_EQ(p.cutang, 180);
  EXPECT_EQ(p.side, ThreadSide::kExternal);
  EXPECT_POINT(p.passes[0].from, 10 - r485 / 22, 2);
  EXPECT_POINT(p.passes[0].to, 11 - r485 / 22, -20);
  // approach = from - ((H + d)/(n.u)) u: X = 10 - sqrt(485)/22 + (H + 1) sqrt(485)/22.
  EXPECT_POINT(p.passes[0].approach, 10 + kH * r485 / 22, 2);
  // Clear and end: along the outward normal (22, 1)/sqrt(485), from depth 1 up to H.
  EXPECT_POINT(p.passes[0].clear, 11 - r485 / 22 + (kH + 1) * 22 / r485, -20 + (kH + 1) / r485);
  EXPECT_POINT(p.end_position, 10 + kH * 22 / r485, 2 + kH / r485);
}

TEST(Planner, FaceTaper) {
  // P1 (10, 0) -> P2 (2, -1): |dX| 8 > |dZ| 1: taper with the lead along X, infeed along Z.
  // The line at X 12 is at Z 0.25; P0 is at Z 3: infeed -Z (270). Reported external.
  Geometry s;
  s.p0 = {12, 3};
  s.gotos = {{10, 0}, {2, -1}};
  Planned r = plan("THREAD/ON,DEPTH,1", s);
  ASSERT_TRUE(r.ok) << r.messages;
  EXPECT_EQ(r.plan.kind, ThreadKind::kTaper);
  EXPECT_FALSE(r.plan.lead_along_z);
  EXPECT_EQ(r.plan.cutang, 270);
  EXPECT_EQ(r.plan.side, ThreadSide::kExternal);
  // n.u = 8/sqrt(65): a depth of 1 is sqrt(65)/8 along -Z.
  EXPECT_POINT(r.plan.passes[0].from, 10, -std::sqrt(65.0) / 8);
}

TEST(Planner, AngledCutang) {
  // CUTANG 150: u = (cos 150, sin 150) = (-0.866025, 0.5); n = -X; n.u = 0.866025.
  // A depth d is reached at d / 0.866025 along u = d * (-1, tan 30).
  Planned r = plan("THREAD/ON,DEPTH,2,CUTS,4,OPTION,1,CUTANG,150");
  ASSERT_TRUE(r.ok) << r.messages;
  const ThreadPlan& p = r.plan;
  EXPECT_EQ(p.cutang, 150);
  // OPTION 1, c = 4, R = 2: sqrt(i); no flank shift with an angled CUTANG.
  const double d[] = {1, std::sqrt(2.0), std::sqrt(3.0), 2};
  for (int i = 0; i < 4; ++i) {
    EXPECT_EQ(p.passes[i].shift, 0);
    EXPECT_POINT(p.passes[i].from, 10 - d[i], 2 + d[i] * kTan30);
    EXPECT_POINT(p.passes[i].to, 10 - d[i], -20 + d[i] * kTan30);
    // Every approach is at the clear line, back along u from the pass start:
    // P1 - (H / 0.866025) u = (10 + H, 2 - H tan 30) = (11.299038, 1.25).
    EXPECT_POINT(p.passes[i].approach, 10 + kH, 2 - kH * kTan30);
  }
  EXPECT_NEAR(kH * kTan30, 0.75, 1e-12);
}

TEST(Planner, CutangMustBeMoreThanTenDegreesOffTheLine) {
  Planned r = plan("THREAD/ON,DEPTH,1,CUTANG,265");
  EXPECT_FALSE(r.ok);
  EXPECT_EQ(r.messages,
            "t.cl:2:19: error: CUTANG 265 is only 5° off the thread line (direction 270° from (X "
            "10, Z 2) to (X 10, Z -20)); the infeed must be more than 10° off it\n");
  // Exactly 10 degrees is not enough.
  Planned ten = plan("THREAD/ON,DEPTH,1,CUTANG,100");
  EXPECT_FALSE(ten.ok);
  EXPECT_EQ(ten.messages,
            "t.cl:2:19: error: CUTANG 100 is only 10° off the thread line (direction 270° from (X "
            "10, Z 2) to (X 10, Z -20)); the infeed must be more than 10° off it\n");
  // Along the line itself.
  Planned along = plan("THREAD/ON,DEPTH,1,CUTANG,-90");
  EXPECT_FALSE(along.ok);
  EXPECT_EQ(along.messages,
            "t.cl:2:19: error: CUTANG -90 is only 0° off the thread line (direction 270° from (X "
            "10, Z 2) to (X 10, Z -20)); the infeed must be more than 10° off it\n");
  // 11 degrees is.
  Planned eleven = plan("THREAD/ON,DEPTH,1,CUTANG,101");
  EXPECT_TRUE(eleven.ok) << eleven.messages;
}

TEST(Planner, InitialPointOnTheLineNeedsCutang) {
  Geometry s;
  s.p0 = {10, 5};
  Planned r = plan("THREAD/ON,DEPTH,1", s);
  EXPECT_FALSE(r.ok);
  EXPECT_EQ(r.messages,
            "t.cl:2:1: error: cannot choose the infeed direction: the initial point (X 10, Z 5) is "
            "on the thread line; give CUTANG\n");
  Planned with = plan("THREAD/ON,DEPTH,1,CUTANG,180,RETURN,2", s);
  EXPECT_TRUE(with.ok) << with.messages;
}

TEST(Planner, MachineDefaultsForOptionAndToolAngle) {
  Geometry s;
  s.settings.default_option = 3;
  s.settings.default_tool_angle = 55;
  Planned r = plan("THREAD/ON,DEPTH,2,CUTS,4", s);
  ASSERT_TRUE(r.ok) << r.messages;
  EXPECT_EQ(r.plan.option, 3);
  EXPECT_EQ(r.plan.tool_angle, 55);
  // OPTION 3: 0.5, 1, 1.5, 2; single edge at 55/2: sigma_4 = 2 tan 27.5 = 1.041134.
  EXPECT_EQ(depths(r.plan), (std::vector<double>{0.5, 1, 1.5, 2}));
  EXPECT_NEAR(r.plan.passes[3].shift, 2 * std::tan(radians(27.5)), 1e-12);
  EXPECT_NEAR(r.plan.passes[3].shift, 1.041134, 1e-6);
  // The CL's words win over the machine's defaults.
  Planned w = plan("THREAD/ON,DEPTH,2,CUTS,4,OPTION,0,TLANGL,60", s);
  ASSERT_TRUE(w.ok) << w.messages;
  EXPECT_EQ(w.plan.option, 0);
  EXPECT_EQ(w.plan.tool_angle, 60);
  EXPECT_EQ(w.plan.passes[3].shift, 0);
}

// --- Flank shifts: sigma_i = d_i tan(a/2), pass from P1 + delta_i to P2 + delta_i - sigma_max t.

struct FlankCase {
  int option;
  std::vector<double> depth;
  std::vector<double> shift;
};

TEST(Planner, FlankShiftsAllOptions) {
  const double s2 = std::sqrt(2.0), s3 = std::sqrt(3.0);
  const FlankCase cases[] = {
      // Constant amount along CUTANG: no shift.
      {0, {0.8, 1.4, 1.8, 2}, {0, 0, 0, 0}},
      // Degressive, single edge: every pass shifted d tan 30:
      // 0.577350, 0.816497, 1, 1.154701.
      {1, {1, s2, s3, 2}, {kTan30, s2 * kTan30, s3 * kTan30, 2 * kTan30}},
      // Degressive, alternating: even passes only.
      {2, {1, s2, s3, 2}, {0, s2 * kTan30, 0, 2 * kTan30}},
      // Constant depth, single edge: 0.288675, 0.577350, 0.866025, 1.154701.
      {3, {0.5, 1, 1.5, 2}, {0.5 * kTan30, kTan30, 1.5 * kTan30, 2 * kTan30}},
      // Constant depth, alternating.
      {4, {0.5, 1, 1.5, 2}, {0, kTan30, 0, 2 * kTan30}},
  };
  for (const FlankCase& c : cases) {
    Planned r = plan(fmt::format("THREAD/ON,DEPTH,2,CUTS,4,OPTION,{}", c.option));
    ASSERT_TRUE(r.ok) << r.messages;
    const double sigma_max = c.option == 0 ? 0 : 2 * kTan30;
    for (size_t i = 0; i < 4; ++i) {
      const ThreadPass& p = r.plan.passes[i];
      EXPECT_NEAR(p.depth, c.depth[i], 1e-12) << "OPTION " << c.option << " pass " << i + 1;
      EXPECT_NEAR(p.shift, c.shift[i], 1e-12) << "OPTION " << c.option << " pass " << i + 1;
      // t = -Z: shifted passes start sigma_i further along -Z ...
      EXPECT_POINT(p.from, 10 - c.depth[i], 2 - c.shift[i]);
      // ... and end sigma_max - sigma_i short of P2, so the deepest ends exactly at Z -20.
      EXPECT_POINT(p.to, 10 - c.depth[i], -20 - c.shift[i] + sigma_max);
      // The approach is on the clear line above the shifted start.
      EXPECT_POINT(p.approach, 10 + kH, 2 - c.shift[i]);
    }
    EXPECT_NEAR(r.plan.passes[3].to.z, -20, 1e-12);
  }
}

TEST(Planner, FlankShiftOnFinishAndSpringPasses) {
  // OPTION 3, D 2, f 0.2: 0.6, 1.2, 1.8, finish 2, spring 2; single edge: shifts d tan 30.
  Planned r = plan("THREAD/ON,DEPTH,2,CUTS,3,OPTION,3,FINCUT,2,0.2");
  ASSERT_TRUE(r.ok) << r.messages;
  ASSERT_EQ(r.plan.passes.size(), 5u);
  EXPECT_EQ(r.plan.passes[3].kind, PassKind::kFinish);
  EXPECT_EQ(r.plan.passes[4].kind, PassKind::kSpring);
  EXPECT_NEAR(r.plan.passes[3].shift, 2 * kTan30, 1e-12);
  EXPECT_NEAR(r.plan.passes[4].shift, 2 * kTan30, 1e-12);
  EXPECT_NEAR(r.plan.passes[2].to.z, -20 - 1.8 * kTan30 + 2 * kTan30, 1e-12);
}

TEST(Planner, AlternatingCountsFinishPassesInTheLadder) {
  // OPTION 4, D 2, CUTS 3, FINCUT 2: ladder 2/3, 4/3, 2, 2, 2; passes 2 and 4 shifted.
  Planned r = plan("THREAD/ON,DEPTH,2,CUTS,3,OPTION,4,FINCUT,2");
  ASSERT_TRUE(r.ok) << r.messages;
  const double want[] = {0, 4.0 / 3 * kTan30, 0, 2 * kTan30, 0};
  for (int i = 0; i < 5; ++i) EXPECT_NEAR(r.plan.passes[i].shift, want[i], 1e-12) << i;
}

TEST(Planner, FlankShiftOnAnInternalThread) {
  Geometry s;
  s.p0 = {3, 5};
  s.gotos = {{5, 2}, {5, -20}};
  Planned r = plan("THREAD/ON,DEPTH,1,CUTS,2,OPTION,3", s);
  ASSERT_TRUE(r.ok) << r.messages;
  // 0.5 and 1 outward (+X); shifts 0.5 tan 30 and tan 30 along -Z.
  EXPECT_POINT(r.plan.passes[0].from, 5.5, 2 - 0.5 * kTan30);
  EXPECT_POINT(r.plan.passes[0].to, 5.5, -20 - 0.5 * kTan30 + kTan30);
  EXPECT_POINT(r.plan.passes[1].to, 6, -20);
}

TEST(Planner, FlankShiftAlongZInfeedOnAFace) {
  // CUTANG 270 is a multiple of 90: options 1-4 shift along the face line (t = -X).
  Geometry s;
  s.p0 = {12, 3};
  s.gotos = {{10, 0}, {2, 0}};
  Planned r = plan("THREAD/ON,DEPTH,1,CUTS,1,OPTION,1", s);
  ASSERT_TRUE(r.ok) << r.messages;
  EXPECT_NEAR(r.plan.passes[0].shift, kTan30, 1e-12);
  EXPECT_POINT(r.plan.passes[0].from, 10 - kTan30, -1);
  EXPECT_POINT(r.plan.passes[0].to, 2, -1);
}

// --- Pull-out. ---

TEST(Planner, PulloutFromThirdGoto) {
  Geometry s;
  s.gotos = {kP1, kP2, {11.5, -21.5}};
  Planned r = plan("THREAD/ON,DEPTH,0.92,CUTS,3", s);
  ASSERT_TRUE(r.ok) << r.messages;
  const ThreadPlan& p = r.plan;
  ASSERT_TRUE(p.pullout.has_value());
  EXPECT_POINT(*p.pullout, 1.5, -1.5);  // P3 - P2
  EXPECT_FALSE(p.pullout_linear);       // 45 degrees
  // Pass 1 at 0.46: ends at (9.54, -20), pulls out to (11.04, -21.5), clears to X 11.299038.
  EXPECT_POINT(p.passes[0].pullout_end, 11.04, -21.5);
  EXPECT_POINT(p.passes[0].clear, 10 + kH, -21.5);
  EXPECT_POINT(p.passes[2].pullout_end, 10.58, -21.5);
  EXPECT_NEAR(p.clearance, kH, 1e-12);  // the pull-out top 1.5 - 0.46 = 1.04 is lower
}

TEST(Planner, ShallowThirdGotoIsCutLinear) {
  // P3 - P2 = (0.5, -1.5): atan(0.5 / 1.5) = 18.4 degrees, outside 30..60.
  Geometry s;
  s.gotos = {kP1, kP2, {10.5, -21.5}};
  Planned r = plan("THREAD/ON,DEPTH,0.92,CUTS,3", s);
  ASSERT_TRUE(r.ok) << r.messages;
  EXPECT_TRUE(r.plan.pullout_linear);
}

TEST(Planner, ThirdGotoIntoTheMaterialIsAnError) {
  Geometry s;
  s.gotos = {kP1, kP2, {9, -21}};
  Planned r = plan("THREAD/ON,DEPTH,0.92,CUTS,3", s);
  EXPECT_FALSE(r.ok);
  EXPECT_EQ(r.messages,
            "t.cl:5:1: error: the chamfer end (X 9, Z -21) is 1 on the material side of the thread "
            "line: the pull-out must move out of the thread\n"
            "t.cl:2:1: note: the thread sequence starts here\n");
}

TEST(Planner, ThirdGotoAtTheThreadEndIsNoPullout) {
  Geometry s;
  s.gotos = {kP1, kP2, kP2};
  Planned r = plan("THREAD/ON,DEPTH,1", s);
  ASSERT_TRUE(r.ok) << r.messages;
  EXPECT_FALSE(r.plan.pullout.has_value());
  EXPECT_EQ(r.messages,
            "t.cl:5:1: warning: the third GOTO (X 10, Z -20) repeats the thread end: no "
            "pull-out\n");
}

TEST(Planner, AtanglDefaultHeightPullsStraightOut) {
  // ATANGL,0: h = 1.299038 straight out (+X): 90 degrees to the line -> linear.
  Planned r = plan("THREAD/ON,DEPTH,1,ATANGL,0");
  ASSERT_TRUE(r.ok) << r.messages;
  ASSERT_TRUE(r.plan.pullout.has_value());
  EXPECT_POINT(*r.plan.pullout, kH, 0);
  EXPECT_TRUE(r.plan.pullout_linear);
  // ATANGL,0,0 is the same.
  Planned z = plan("THREAD/ON,DEPTH,1,ATANGL,0,0");
  ASSERT_TRUE(z.ok) << z.messages;
  EXPECT_POINT(*z.plan.pullout, kH, 0);
}

TEST(Planner, AtanglWithHeight) {
  // ATANGL,30,2: 2 out (+X) and 2 tan 30 = 1.154701 along t (-Z): 60 degrees to the line.
  Planned r = plan("THREAD/ON,DEPTH,1,ATANGL,30,2");
  ASSERT_TRUE(r.ok) << r.messages;
  EXPECT_POINT(*r.plan.pullout, 2, -2 * kTan30);
  EXPECT_FALSE(r.plan.pullout_linear);  // 60 is inside 30..60
  // Pass at depth 1 ends at (9, -20) and pulls out to (11, -21.154701); the clear line is raised
  // to the pull-out top 2 - 1 = 1 ... which is below H: stays 1.299038.
  EXPECT_POINT(r.plan.passes[0].pullout_end, 11, -20 - 2 * kTan30);
  EXPECT_NEAR(r.plan.clearance, kH, 1e-12);
  EXPECT_POINT(r.plan.passes[0].clear, 10 + kH, -20 - 2 * kTan30);
}

TEST(Planner, AtanglNegativeLeansBack) {
  // ATANGL,-20,1: 1 out and tan(-20) = -0.363970 along t, i.e. +0.363970 in Z: 110 degrees.
  Planned r = plan("THREAD/ON,DEPTH,1,ATANGL,-20,1");
  ASSERT_TRUE(r.ok) << r.messages;
  EXPECT_POINT(*r.plan.pullout, 1, std::tan(radians(20)));
  EXPECT_TRUE(r.plan.pullout_linear);
}

TEST(Planner, ChamfrPositive) {
  // CHAMFR,2 (45): 2 along t and 2 tan 45 out: (2, -2) from every pass end.
  Planned r = plan("THREAD/ON,DEPTH,0.92,CUTS,3,CHAMFR,2");
  ASSERT_TRUE(r.ok) << r.messages;
  EXPECT_POINT(*r.plan.pullout, 2, -2);
  EXPECT_FALSE(r.plan.pullout_linear);
  EXPECT_POINT(r.plan.passes[0].to, 9.54, -20);
  EXPECT_POINT(r.plan.passes[0].pullout_end, 11.54, -22);
  // The pull-out top 2 - 0.46 = 1.54 is above 1.299038: the clear line is at 1.54.
  EXPECT_NEAR(r.plan.clearance, 1.54, 1e-12);
  EXPECT_POINT(r.plan.passes[0].clear, 11.54, -22);
  EXPECT_POINT(r.plan.passes[2].clear, 11.54, -22);  // from 10 - 0.92 + 2 = 11.08 up to 11.54
  EXPECT_POINT(r.plan.end_position, 11.54, 2);
}

TEST(Planner, ChamfrNegativeShortensEveryPass) {
  // CHAMFR,-2: every pass ends 2 before P2 (Z -18); the 45 degree pull-out ends at Z -20.
  Planned r = plan("THREAD/ON,DEPTH,0.92,CUTS,3,CHAMFR,-2");
  ASSERT_TRUE(r.ok) << r.messages;
  EXPECT_POINT(*r.plan.pullout, 2, -2);
  for (const ThreadPass& p : r.plan.passes) {
    EXPECT_NEAR(p.from.z, 2, 1e-12);
    EXPECT_NEAR(p.to.z, -18, 1e-12);
    EXPECT_NEAR(p.pullout_end.z, -20, 1e-12);
    EXPECT_NEAR(p.pullout_end.x, 10 - p.depth + 2, 1e-12);
  }
}

TEST(Planner, ChamfrNegativeWithFlankShift) {
  // OPTION 3, D 2, CUTS 2: shifts 1 tan 30 and 2 tan 30; the deepest pass ends at
  // -20 + 2 (chamfer) = -18 and its pull-out at -20.
  Planned r = plan("THREAD/ON,DEPTH,2,CUTS,2,OPTION,3,CHAMFR,-2");
  ASSERT_TRUE(r.ok) << r.messages;
  EXPECT_POINT(r.plan.passes[1].to, 8, -18);
  EXPECT_POINT(r.plan.passes[1].pullout_end, 10, -20);
  EXPECT_POINT(r.plan.passes[0].to, 9, -18 - kTan30 + 2 * kTan30);
}

TEST(Planner, ChamfrAngles) {
  struct Case {
    const char* words;
    double dx, dz;
    bool linear;
  };
  const double t20 = std::tan(radians(20)), t29 = std::tan(radians(29)),
               t61 = std::tan(radians(61));
  const Case cases[] = {
      {"CHAMFR,2,20", 2 * t20, -2, true},          // 20 degrees
      {"CHAMFR,1,29", t29, -1, true},              // just below 30
      {"CHAMFR,1,30", kTan30, -1, false},          // 30: thread interpolation
      {"CHAMFR,1,60", std::sqrt(3.0), -1, false},  // 60: thread interpolation
      {"CHAMFR,1,61", t61, -1, true},              // just above 60
  };
  for (const Case& c : cases) {
    Planned r = plan(std::string("THREAD/ON,DEPTH,1,") + c.words);
    ASSERT_TRUE(r.ok) << r.messages;
    EXPECT_POINT(*r.plan.pullout, c.dx, c.dz);
    EXPECT_EQ(r.plan.pullout_linear, c.linear) << c.words;
  }
}

TEST(Planner, ChamfrZeroIsNoPullout) {
  Planned r = plan("THREAD/ON,DEPTH,1,CHAMFR,0");
  ASSERT_TRUE(r.ok) << r.messages;
  EXPECT_FALSE(r.plan.pullout.has_value());
  // ... and does not conflict with a third GOTO.
  Geometry s;
  s.gotos = {kP1, kP2, {11.5, -21.5}};
  Planned g = plan("THREAD/ON,DEPTH,1,CHAMFR,0,0", s);
  ASSERT_TRUE(g.ok) << g.messages;
  EXPECT_POINT(*g.plan.pullout, 1.5, -1.5);
}

TEST(Planner, OnlyOnePullout) {
  Planned r = plan("THREAD/ON,DEPTH,1,ATANGL,10,CHAMFR,2");
  EXPECT_FALSE(r.ok);
  EXPECT_EQ(r.messages,
            "t.cl:2:29: error: CHAMFR defines a second pull-out: ATANGL at line 2, column 19 "
            "already defines it; give only one of a third GOTO, ATANGL and CHAMFR\n");
  Planned rev = plan("THREAD/ON,DEPTH,1,CHAMFR,2,ATANGL,10");
  EXPECT_FALSE(rev.ok);
  EXPECT_EQ(rev.messages,
            "t.cl:2:28: error: ATANGL defines a second pull-out: CHAMFR at line 2, column 19 "
            "already defines it; give only one of a third GOTO, ATANGL and CHAMFR\n");
  Geometry s;
  s.gotos = {kP1, kP2, {11.5, -21.5}};
  Planned g = plan("THREAD/ON,DEPTH,1,CHAMFR,2", s);
  EXPECT_FALSE(g.ok);
  EXPECT_EQ(g.messages,
            "t.cl:5:1: error: the third GOTO defines a second pull-out: CHAMFR at line 2, column "
            "19 already defines it; give only one of a third GOTO, ATANGL and CHAMFR\n"
            "t.cl:2:1: note: the thread sequence starts here\n");
  Planned all = plan("THREAD/ON,DEPTH,1,ATANGL,0,CHAMFR,2", s);
  EXPECT_FALSE(all.ok);
  EXPECT_EQ(all.messages,
            "t.cl:2:28: error: CHAMFR defines a second pull-out: ATANGL at line 2, column 19 "
            "already defines it; give only one of a third GOTO, ATANGL and CHAMFR\n"
            "t.cl:5:1: error: the third GOTO defines a second pull-out: ATANGL at line 2, column "
            "19 already defines it; give only one of a third GOTO, ATANGL and CHAMFR\n"
            "t.cl:2:1: note: the thread sequence starts here\n");
}

// --- Return. ---

TEST(Planner, ReturnWithHeight) {
  Planned r = plan("THREAD/ON,CUTS,2,0.5,RETURN,3");
  ASSERT_TRUE(r.ok) << r.messages;
  EXPECT_NEAR(r.plan.clearance, 3, 1e-12);
  EXPECT_POINT(r.plan.passes[0].approach, 13, 2);
  EXPECT_POINT(r.plan.passes[0].clear, 13, -20);
  EXPECT_POINT(r.plan.passes[1].clear, 13, -20);
  EXPECT_POINT(r.plan.end_position, 13, 2);
}

TEST(Planner, ReturnWithoutHeightGoesToTheInitialX) {
  // P0 at X 12: the clear line is 2 above the crest.
  Planned r = plan("THREAD/ON,DEPTH,1,RETURN");
  ASSERT_TRUE(r.ok) << r.messages;
  EXPECT_NEAR(r.plan.clearance, 2, 1e-12);
  EXPECT_POINT(r.plan.passes[0].approach, 12, 2);
  EXPECT_POINT(r.plan.passes[0].clear, 12, -20);
  EXPECT_POINT(r.plan.end_position, 12, 2);
}

TEST(Planner, ReturnWithoutHeightOnAFaceGoesToTheInitialZ) {
  Geometry s;
  s.p0 = {12, 3};
  s.gotos = {{10, 0}, {2, 0}};
  Planned r = plan("THREAD/ON,DEPTH,1,RETURN", s);
  ASSERT_TRUE(r.ok) << r.messages;
  EXPECT_NEAR(r.plan.clearance, 3, 1e-12);
  EXPECT_POINT(r.plan.passes[0].approach, 10, 3);
  EXPECT_POINT(r.plan.passes[0].clear, 2, 3);
}

TEST(Planner, ReturnWithoutHeightOnATaper) {
  // Taper (10, 2) -> (11, -20), P0 X 14: the clear line passes through X 14 above P2:
  // H = (14 - 11) / (22 / sqrt(485)).
  Geometry s;
  s.p0 = {14, 5};
  s.gotos = {{10, 2}, {11, -20}};
  Planned r = plan("THREAD/ON,DEPTH,1,RETURN", s);
  ASSERT_TRUE(r.ok) << r.messages;
  EXPECT_NEAR(r.plan.clearance, 3 * std::sqrt(485.0) / 22, 1e-12);
}

TEST(Planner, ReturnWithoutHeightFromInsideIsAnError) {
  Geometry s;
  s.p0 = {9, 5};
  Planned r = plan("THREAD/ON,DEPTH,1,CUTANG,180,RETURN", s);
  EXPECT_FALSE(r.ok);
  EXPECT_EQ(r.messages,
            "t.cl:2:30: error: RETURN without a height clears to the initial point's X 9, which is "
            "not outside the thread end (X 10, Z -20); give RETURN,h\n");
}

// A face thread (lead along X, P1 (X 20, Z 0) to P2 (X 5, Z 0)) measures the infeed side and
// the RETURN height along Z.
TEST(Planner, FaceThreadInitialPointErrorsAreAlongZ) {
  auto face = [](Vec2 p0, const std::string& on_line) {
    Geometry s;
    s.p0 = p0;
    s.gotos = {{20, 0}, {5, 0}};
    return plan(on_line, s);
  };
  EXPECT_EQ(face({25, 0}, "THREAD/ON,DEPTH,1").messages,
            "t.cl:2:1: error: cannot choose the infeed direction: the initial point (X 25, Z 0) is "
            "on the thread line; give CUTANG\n");
  // CUTANG 90 feeds toward +Z, so outward is -Z: Z 1 is inside the thread end's Z 0, Z -2 is 2
  // outside it.
  EXPECT_EQ(face({25, 1}, "THREAD/ON,DEPTH,1,CUTANG,90,RETURN").messages,
            "t.cl:2:29: error: RETURN without a height clears to the initial point's Z 1, which is "
            "not outside the thread end (X 5, Z 0); give RETURN,h\n");
  const Planned ok = face({25, -2}, "THREAD/ON,DEPTH,1,CUTANG,90,RETURN");
  ASSERT_TRUE(ok.ok) << ok.messages;
  EXPECT_EQ(ok.plan.kind, ThreadKind::kFace);
  EXPECT_EQ(ok.plan.clearance, 2);
}

TEST(Planner, ReturnBelowThePulloutIsRaised) {
  // CHAMFR,2 reaches 2 - 0.46 = 1.54 above the crest on the first pass; RETURN,0.5 is lower.
  Planned r = plan("THREAD/ON,DEPTH,0.92,CUTS,3,CHAMFR,2,RETURN,0.5");
  ASSERT_TRUE(r.ok) << r.messages;
  EXPECT_NEAR(r.plan.clearance, 1.54, 1e-12);
  EXPECT_EQ(r.messages,
            "t.cl:2:38: warning: the return height 0.5 is below the pull-out end (1.54 above the "
            "thread line): the tool clears to 1.54\n");
}

TEST(Planner, DefaultReturnIsAFullThreadDepth) {
  // No RETURN, no pull-out: pitch / (2 tan 30); with TPI 8 in mm: 3.175 * sqrt(3) / 2.
  Planned r = plan("THREAD/ON,DEPTH,1,TPI,8");
  ASSERT_TRUE(r.ok) << r.messages;
  EXPECT_NEAR(r.plan.clearance, 3.175 * std::sqrt(3.0) / 2, 1e-12);
  EXPECT_POINT(r.plan.passes[0].approach, 10 + 3.175 * std::sqrt(3.0) / 2, 2);
}

// --- Multi-start. ---

TEST(Planner, TwoStartsByOffset) {
  Planned r = plan("THREAD/ON,DEPTH,0.92,CUTS,3,MULTRD,2");
  ASSERT_TRUE(r.ok) << r.messages;
  const ThreadPlan& p = r.plan;
  EXPECT_EQ(p.pitch.starts, 2);
  EXPECT_EQ(p.lead, 3);  // 2 x 1.5
  EXPECT_FALSE(p.starts_by_angle);
  // ICAM order: pass 1 of start 0, pass 1 of start 1, pass 2 of start 0, ...
  ASSERT_EQ(p.passes.size(), 6u);
  const int want_n[] = {1, 1, 2, 2, 3, 3};
  const int want_k[] = {0, 1, 0, 1, 0, 1};
  for (int i = 0; i < 6; ++i) {
    const ThreadPass& s = p.passes[i];
    EXPECT_EQ(s.n, want_n[i]);
    EXPECT_EQ(s.start, want_k[i]);
    EXPECT_EQ(s.start_angle, 0);
    // Start 1 begins one pitch earlier (Z 3.5, against the cut), ends at the same Z -20.
    EXPECT_NEAR(s.from.z, 2 + 1.5 * s.start, 1e-12);
    EXPECT_NEAR(s.to.z, -20, 1e-12);
    EXPECT_POINT(s.approach, 10 + kH, 2 + 1.5 * s.start);
  }
  EXPECT_EQ(p.passes[1].depth, p.passes[0].depth);
}

TEST(Planner, ThreeStartsByOffset) {
  Planned r = plan("THREAD/ON,DEPTH,1,MULTRD,3");
  ASSERT_TRUE(r.ok) << r.messages;
  ASSERT_EQ(r.plan.passes.size(), 3u);
  EXPECT_EQ(r.plan.lead, 4.5);
  // Starts at Z 2, 3.5, 5; all end at Z -20.
  EXPECT_POINT(r.plan.passes[0].from, 9, 2);
  EXPECT_POINT(r.plan.passes[1].from, 9, 3.5);
  EXPECT_POINT(r.plan.passes[2].from, 9, 5);
  for (const ThreadPass& s : r.plan.passes) EXPECT_POINT(s.to, 9, -20);
}

TEST(Planner, StartsByAngle) {
  Geometry s;
  s.settings.start_angle_word = true;
  Planned two = plan("THREAD/ON,CUTS,2,0.5,MULTRD,2", s);
  ASSERT_TRUE(two.ok) << two.messages;
  EXPECT_TRUE(two.plan.starts_by_angle);
  const double want2[] = {0, 180, 0, 180};
  for (int i = 0; i < 4; ++i) {
    EXPECT_EQ(two.plan.passes[i].start_angle, want2[i]);
    EXPECT_NEAR(two.plan.passes[i].from.z, 2, 1e-12);  // same path for every start
  }
  Planned three = plan("THREAD/ON,DEPTH,1,MULTRD,3", s);
  ASSERT_TRUE(three.ok) << three.messages;
  EXPECT_EQ(three.plan.passes[0].start_angle, 0);
  EXPECT_EQ(three.plan.passes[1].start_angle, 120);
  EXPECT_EQ(three.plan.passes[2].start_angle, 240);
  EXPECT_EQ(three.plan.passes[2].start, 2);
  // One start: nothing to index.
  Planned one = plan("THREAD/ON,DEPTH,1", s);
  ASSERT_TRUE(one.ok);
  EXPECT_FALSE(one.plan.starts_by_angle);
}

TEST(Planner, StartsFromTheModalPitch) {
  Geometry s;
  s.modal = pitch_of(1.5, 2);
  Planned r = plan("THREAD/ON,DEPTH,1", s);
  ASSERT_TRUE(r.ok) << r.messages;
  EXPECT_EQ(r.plan.pitch.starts, 2);
  EXPECT_EQ(r.plan.lead, 3);
  // THREAD/ON,MULTRD overrides the modal starts.
  Planned o = plan("THREAD/ON,DEPTH,1,MULTRD,3", s);
  ASSERT_TRUE(o.ok) << o.messages;
  EXPECT_EQ(o.plan.pitch.starts, 3);
  EXPECT_EQ(o.plan.pitch.pitch, 1.5);
}

TEST(Planner, StartOffsetOnATaperIsOnePitchAlongZ) {
  // Taper (10, 2) -> (11, -20): start 1 moves back along the line until Z is 1.5 further:
  // 1.5 sqrt(485) / 22 along -t = (-1.5/22, +1.5).
  Geometry s;
  s.p0 = {14, 5};
  s.gotos = {{10, 2}, {11, -20}};
  Planned r = plan("THREAD/ON,DEPTH,1,MULTRD,2", s);
  ASSERT_TRUE(r.ok) << r.messages;
  const double r485 = std::sqrt(485.0);
  EXPECT_POINT(r.plan.passes[1].from, 10 - r485 / 22 - 1.5 / 22, 3.5);
  EXPECT_POINT(r.plan.passes[1].to, r.plan.passes[0].to.x, -20);
}

// --- Pitch. ---

TEST(Planner, NoPitchIsAnError) {
  Geometry s;
  s.modal = PitchSpec{};
  Planned r = plan("THREAD/ON,DEPTH,1", s);
  EXPECT_FALSE(r.ok);
  EXPECT_EQ(r.messages,
            "t.cl:2:1: error: no pitch in force at THREAD/ON: give PITCH/ before it, or TPI, IPR, "
            "MMPR or PERREV on it\n");
  // The pitch on THREAD/ON is enough.
  Planned ok = plan("THREAD/ON,DEPTH,1,MMPR,2", s);
  ASSERT_TRUE(ok.ok) << ok.messages;
  EXPECT_EQ(ok.plan.pitch.pitch, 2);
}

TEST(Planner, ThreadOnPitchOverridesTheModalOne) {
  Planned r = plan("THREAD/ON,DEPTH,1,TPI,10");
  ASSERT_TRUE(r.ok) << r.messages;
  EXPECT_NEAR(r.plan.pitch.pitch, 2.54, 1e-12);  // 25.4 / 10
  EXPECT_TRUE(r.plan.pitch.from_tpi);
  EXPECT_EQ(r.plan.pitch.tpi, 10);
}

TEST(Planner, VariableLeadNeedsTheMachine) {
  Geometry s;
  s.settings.machine_name = "fanuc-0t";
  Planned r = plan("THREAD/ON,DEPTH,1,INCR,0.01", s);
  EXPECT_FALSE(r.ok);
  EXPECT_EQ(r.messages,
            "t.cl:2:19: error: variable lead (INCR 0.01 per revolution, CL line 2) cannot be cut "
            "on machine 'fanuc-0t': it does not declare variable-lead threading (G34/G35)\n");
  // From a PITCH/ on line 1: reported at THREAD/ON, naming line 1.
  s.modal.lead_change = -0.02;
  s.modal.lead_change_loc = {1, 10};
  Planned m = plan("THREAD/ON,DEPTH,1", s);
  EXPECT_FALSE(m.ok);
  EXPECT_EQ(m.messages,
            "t.cl:2:1: error: variable lead (DECR 0.02 per revolution, CL line 1) cannot be cut on "
            "machine 'fanuc-0t': it does not declare variable-lead threading (G34/G35)\n");
  // A machine without a name.
  s.settings.machine_name.clear();
  Planned u = plan("THREAD/ON,DEPTH,1", s);
  EXPECT_EQ(u.messages,
            "t.cl:2:1: error: variable lead (DECR 0.02 per revolution, CL line 1) cannot be cut on "
            "this machine: it does not declare variable-lead threading (G34/G35)\n");
  // A machine that can.
  s.settings.variable_lead = true;
  Planned v = plan("THREAD/ON,DEPTH,1", s);
  ASSERT_TRUE(v.ok) << v.messages;
  EXPECT_EQ(v.plan.pitch.lead_change, -0.02);
  // INCR,0 is a constant lead.
  Geometry c;
  Planned zero = plan("THREAD/ON,DEPTH,1,INCR,0", c);
  EXPECT_TRUE(zero.ok) << zero.messages;
}

// --- The GOTOs. ---

TEST(Planner, GotoCount) {
  Geometry s;
  s.gotos = {};
  EXPECT_EQ(plan("THREAD/ON,DEPTH,1", s).messages,
            "t.cl:2:1: error: THREAD/ON needs 2 or 3 GOTOs before THREAD/OFF (thread start, "
            "thread end, optional chamfer end); found 0\n");
  s.gotos = {kP1};
  EXPECT_EQ(plan("THREAD/ON,DEPTH,1", s).messages,
            "t.cl:2:1: error: THREAD/ON needs 2 or 3 GOTOs before THREAD/OFF (thread start, "
            "thread end, optional chamfer end); found 1\n");
  s.gotos = {kP1, kP2, {12, -22}, {12, 0}, {12, 2}};
  EXPECT_EQ(plan("THREAD/ON,DEPTH,1", s).messages,
            "t.cl:6:1: error: THREAD/ON takes at most 3 GOTOs before THREAD/OFF (thread start, "
            "thread end, chamfer end); this is GOTO 4 of 5\n"
            "t.cl:2:1: note: the thread sequence starts here\n");
}

TEST(Planner, GotoCountInTheProEForm) {
  Geometry s;
  s.gotos = {kP1};
  s.on_word = "OP/THREAD";
  s.off_word = "OP/THREAD,NOMORE";
  s.first_arg = 2;
  EXPECT_EQ(plan("OP/THREAD,TURN,DEPTH,1", s).messages,
            "t.cl:2:1: error: OP/THREAD needs 2 or 3 GOTOs before OP/THREAD,NOMORE (thread start, "
            "thread end, optional chamfer end); found 1\n");
}

TEST(Planner, ZeroLengthThread) {
  Geometry s;
  s.gotos = {kP1, kP1};
  EXPECT_EQ(plan("THREAD/ON,DEPTH,1", s).messages,
            "t.cl:4:1: error: the thread end (X 10, Z 2) is the thread start: the thread has no "
            "length\n"
            "t.cl:2:1: note: the thread sequence starts here\n");
}

TEST(Planner, PassesWithoutLength) {
  EXPECT_EQ(plan("THREAD/ON,DEPTH,1,CHAMFR,-25").messages,
            "t.cl:2:1: error: the passes have no length: thread length 22 - largest flank shift 0 "
            "- negative CHAMFR 25 = -3\n");
  // A 1 long thread with a 2 deep single-edge thread: shift 2 tan 30 = 1.154701 > 1.
  Geometry s;
  s.gotos = {{10, 2}, {10, 1}};
  EXPECT_EQ(plan("THREAD/ON,DEPTH,2,OPTION,1", s).messages,
            "t.cl:2:1: error: the passes have no length: thread length 1 - largest flank shift "
            "1.154701 - negative CHAMFR 0 = -0.154701\n");
}

TEST(Planner, LadderErrorsComeThrough) {
  EXPECT_EQ(plan("THREAD/ON,CUTS,4").messages,
            "t.cl:2:11: error: CUTS 4 needs a depth or a step: give DEPTH,d, STEP,s or "
            "CUTS,4,s\n");
}

// --- Inch threads. ---

TEST(Planner, InchThreadFromTpi) {
  // 1/2-13 UNC external: TPI 13 -> pitch 1/13 = 0.076923 in; depth 0.61343 / 13 = 0.047187.
  Geometry s;
  s.units = LengthUnit::kInch;
  s.modal = PitchSpec{};
  s.p0 = {0.3, 0.2};
  s.gotos = {{0.25, 0.1}, {0.25, -0.75}};
  Planned r = plan("THREAD/ON,TPI,13,DEPTH,0.047187,CUTS,4,OPTION,1", s);
  ASSERT_TRUE(r.ok) << r.messages;
  EXPECT_EQ(r.plan.units, LengthUnit::kInch);
  EXPECT_NEAR(r.plan.pitch.pitch, 1.0 / 13, 1e-15);
  EXPECT_NEAR(r.plan.clearance, std::sqrt(3.0) / 26, 1e-12);  // (1/13) sqrt(3) / 2
  // Last pass: X 0.25 - 0.047187, shift 0.047187 tan 30.
  EXPECT_POINT(r.plan.passes[3].from, 0.25 - 0.047187, 0.1 - 0.047187 * kTan30);
  EXPECT_POINT(r.plan.passes[3].to, 0.25 - 0.047187, -0.75);
}

}  // namespace
}  // namespace clpost

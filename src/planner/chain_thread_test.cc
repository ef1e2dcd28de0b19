// Chained multi-pass threads (threading.md section 11), computed by hand. Unless a test says
// otherwise: mm, pitch 2, P0 = (X 30, Z 5) and the contour P1 (X 15, Z 0) - P2 (X 15, Z -30) -
// P3 (X 18, Z -60) - P4 (X 22, Z -68): a cylinder, a taper rising 3 over 30 and one rising 4
// over 8, cut toward -Z from outside (default CUTANG 180, u = (X -1, Z 0)). THREAD/ON is on line
// 2, the GOTOs on lines 3, 4, ... With TLANGL 90 a flank shift is tan 45 = 1 times the depth;
// the last segment's direction is (4, -8)/|.|, so an end that slides back by s along Z moves
// s/2 along X.
#include <gtest/gtest.h>

#include <cmath>
#include <string>
#include <vector>

#include "planner/plan_format.h"
#include "planner/planner.h"
#include "planner/planner_test_util.h"

namespace clpost {
namespace {

using testing::make_multi;
using testing::pitch_of;
using testing::TestStatement;

const std::vector<Vec2> kContour = {{15, 0}, {15, -30}, {18, -60}, {22, -68}};

struct Chain {
  bool ok = false;
  ThreadPlan plan;
  std::string messages;
};

Chain chain(const std::string& on_line, const std::vector<Vec2>& gotos = kContour,
            Vec2 p0 = {30, 5}, PitchSpec modal = pitch_of(2), PlannerSettings settings = {}) {
  TestStatement on(on_line, 2);
  Diagnostics d("t.cl");
  testing::MultiCase c = make_multi(on, LengthUnit::kMm, p0, gotos, d);
  Chain r;
  if (!c.parsed) {
    ADD_FAILURE() << "words do not parse: " << on_line << "\n" << d.render_all();
    return r;
  }
  EXPECT_TRUE(c.in.words.chain.set);
  c.in.modal_pitch = modal;
  r.ok = plan_chain_thread(c.in, settings, r.plan, d);
  EXPECT_EQ(r.ok, !d.has_errors());
  r.messages = testing::first_lines(d);
  return r;
}

// The path of a pass, compared point by point.
void expect_path(const ThreadPass& p, const std::vector<Vec2>& want) {
  ASSERT_EQ(p.path.size(), want.size()) << "pass " << p.n;
  for (size_t i = 0; i < want.size(); ++i) {
    EXPECT_NEAR(p.path[i].x, want[i].x, 1e-9) << "pass " << p.n << " point " << i;
    EXPECT_NEAR(p.path[i].z, want[i].z, 1e-9) << "pass " << p.n << " point " << i;
  }
  EXPECT_NEAR(p.from.x, want.front().x, 1e-12);
  EXPECT_NEAR(p.from.z, want.front().z, 1e-12);
  EXPECT_NEAR(p.to.x, want.back().x, 1e-12);
  EXPECT_NEAR(p.to.z, want.back().z, 1e-12);
}

// The contour translated by (dx, dz), the last point slid back by (ex, ez).
std::vector<Vec2> moved(double dx, double dz, double ex = 0, double ez = 0) {
  std::vector<Vec2> v;
  for (const Vec2& p : kContour) v.push_back({p.x + dx, p.z + dz});
  v.back().x += ex;
  v.back().z += ez;
  return v;
}

TEST(ChainThread, Option0IsTheContourTranslatedAlongTheInfeed) {
  // OPTION 0, c = 2 over D = 1.2: d_i = 1.2 i (5 - i) / 6 = 0.8, 1.2. No flank shift.
  const Chain r = chain("THREAD/ON,DEPTH,1.2,CUTS,2,OPTION,0,CHAIN");
  ASSERT_TRUE(r.ok) << r.messages;
  const ThreadPlan& p = r.plan;
  EXPECT_EQ(p.form, ThreadForm::kChain);
  EXPECT_EQ(p.kind, ThreadKind::kTurn);
  EXPECT_EQ(p.side, ThreadSide::kExternal);
  EXPECT_DOUBLE_EQ(p.cutang, 180);
  EXPECT_DOUBLE_EQ(p.lead, 2);
  ASSERT_EQ(p.points.size(), 4u);
  EXPECT_DOUBLE_EQ(p.p1.x, 15);
  EXPECT_DOUBLE_EQ(p.p2.z, -68);
  ASSERT_EQ(p.passes.size(), 2u);
  expect_path(p.passes[0], moved(-0.8, 0));
  expect_path(p.passes[1], moved(-1.2, 0));
  EXPECT_DOUBLE_EQ(p.passes[0].shift, 0);
  // The clear line is P0's X 30: the tool comes down along CUTANG from it and clears to it.
  EXPECT_NEAR(p.passes[0].approach.x, 30, 1e-12);
  EXPECT_NEAR(p.passes[0].approach.z, 0, 1e-12);
  EXPECT_NEAR(p.passes[1].clear.x, 30, 1e-12);
  EXPECT_NEAR(p.passes[1].clear.z, -68, 1e-12);
  EXPECT_NEAR(p.end_position.x, 30, 1e-12);
  EXPECT_NEAR(p.end_position.z, 0, 1e-12);
  EXPECT_FALSE(p.pullout.has_value());
}

TEST(ChainThread, Option3ShiftsAlongZAndEndsOnTheLastSegment) {
  // OPTION 3, c = 2: d = 0.6, 1.2; shifts 0.6, 1.2 toward -Z. Every pass ends 1.2 earlier in
  // Z along its last segment: (X -0.6, Z +1.2). The deepest ends at P4's Z.
  const Chain r = chain("THREAD/ON,DEPTH,1.2,CUTS,2,OPTION,3,TLANGL,90,CHAIN");
  ASSERT_TRUE(r.ok) << r.messages;
  const ThreadPlan& p = r.plan;
  ASSERT_EQ(p.passes.size(), 2u);
  EXPECT_DOUBLE_EQ(p.passes[0].shift, 0.6);
  EXPECT_DOUBLE_EQ(p.passes[1].shift, 1.2);
  expect_path(p.passes[0], moved(-0.6, -0.6, -0.6, 1.2));
  expect_path(p.passes[1], moved(-1.2, -1.2, -0.6, 1.2));
  EXPECT_NEAR(p.passes[1].to.z, -68, 1e-12);
  EXPECT_NEAR(p.passes[1].to.x, 20.2, 1e-12);
}

TEST(ChainThread, Option3WithAnAngledInfeedHasNoShift) {
  // CUTANG 210: u = (cos 210, sin 210) = (-sqrt(3)/2, -1/2); d = 0.6, 1.2 along it.
  const Chain r = chain("THREAD/ON,DEPTH,1.2,CUTS,2,OPTION,3,CUTANG,210,CHAIN");
  ASSERT_TRUE(r.ok) << r.messages;
  const double c = std::sqrt(3.0) / 2;
  ASSERT_EQ(r.plan.passes.size(), 2u);
  expect_path(r.plan.passes[0], moved(-0.6 * c, -0.3));
  expect_path(r.plan.passes[1], moved(-1.2 * c, -0.6));
  EXPECT_DOUBLE_EQ(r.plan.passes[1].shift, 0);
}

TEST(ChainThread, Option1ConstantCrossSectionWithShift) {
  // OPTION 1, c = 4 over 1.2: d_i = 1.2 sqrt(i/4): 0.6, 0.848528, 1.039230, 1.2, each shifted
  // as deep along -Z (TLANGL 90).
  const Chain r = chain("THREAD/ON,DEPTH,1.2,CUTS,4,OPTION,1,TLANGL,90,CHAIN");
  ASSERT_TRUE(r.ok) << r.messages;
  ASSERT_EQ(r.plan.passes.size(), 4u);
  for (int i = 1; i <= 4; ++i) {
    const double d = 1.2 * std::sqrt(i / 4.0);
    const ThreadPass& pass = r.plan.passes[static_cast<size_t>(i - 1)];
    EXPECT_NEAR(pass.depth, d, 1e-12);
    expect_path(pass, moved(-d, -d, -0.6, 1.2));
  }
  EXPECT_NEAR(r.plan.passes[0].path[1].x, 14.4, 1e-12);
  EXPECT_NEAR(r.plan.passes[0].path[1].z, -30.6, 1e-12);
}

TEST(ChainThread, Option1WithoutShiftWhenTheInfeedIsAngled) {
  const Chain r = chain("THREAD/ON,DEPTH,1.2,CUTS,4,OPTION,1,CUTANG,210,CHAIN");
  ASSERT_TRUE(r.ok) << r.messages;
  const double c = std::sqrt(3.0) / 2;
  for (int i = 1; i <= 4; ++i) {
    const double d = 1.2 * std::sqrt(i / 4.0);
    expect_path(r.plan.passes[static_cast<size_t>(i - 1)], moved(-d * c, -d / 2));
  }
}

TEST(ChainThread, PulloutOnTheLastSegmentAndTwoStarts) {
  // A taper then a cylinder; ATANGL,0,1 pulls straight out along the last segment's outward
  // normal (X +1). Two starts by offset: start 2 begins one pitch (2) earlier along the first
  // segment, whose direction (3, -6)/|.| moves 1 in X per 2 in Z.
  const Chain r =
      chain("THREAD/ON,DEPTH,1,ATANGL,0,1,MULTRD,2,CHAIN", {{15, 0}, {18, -6}, {18, -20}});
  ASSERT_TRUE(r.ok) << r.messages;
  const ThreadPlan& p = r.plan;
  ASSERT_TRUE(p.pullout.has_value());
  EXPECT_NEAR(p.pullout->x, 1, 1e-12);
  EXPECT_NEAR(p.pullout->z, 0, 1e-12);
  ASSERT_EQ(p.passes.size(), 2u);
  EXPECT_EQ(p.passes[0].start, 0);
  EXPECT_EQ(p.passes[1].start, 1);
  expect_path(p.passes[0], {{14, 0}, {17, -6}, {17, -20}});
  expect_path(p.passes[1], {{13, 2}, {17, -6}, {17, -20}});
  EXPECT_NEAR(p.passes[0].pullout_end.x, 18, 1e-12);
  EXPECT_NEAR(p.passes[0].clear.x, 30, 1e-12);
  EXPECT_NEAR(p.passes[0].clear.z, -20, 1e-12);
  EXPECT_NEAR(p.passes[1].approach.z, 2, 1e-12);
}

TEST(ChainThread, InternalChainAndReturnHeight) {
  // A bore from X 10 opening to X 12 over Z -10 .. -20, cut from inside (P0 X 5): CUTANG 0,
  // internal. RETURN,1 clears 1 inside the innermost point X 10.
  const Chain r =
      chain("THREAD/ON,DEPTH,0.5,RETURN,1,CHAIN", {{10, 0}, {10, -10}, {12, -20}}, {5, 3});
  ASSERT_TRUE(r.ok) << r.messages;
  const ThreadPlan& p = r.plan;
  EXPECT_EQ(p.side, ThreadSide::kInternal);
  EXPECT_DOUBLE_EQ(p.cutang, 0);
  expect_path(p.passes[0], {{10.5, 0}, {10.5, -10}, {12.5, -20}});
  EXPECT_NEAR(p.end_position.x, 9, 1e-12);
  EXPECT_NEAR(p.passes[0].approach.x, 9, 1e-12);
}

TEST(ChainThread, FaceChainLeadsAlongX) {
  // Along -X: a face, then a 45 degree cone; infeed toward -Z from P0 Z 5.
  const Chain r = chain("THREAD/ON,DEPTH,0.5,CHAIN", {{30, 0}, {20, 0}, {10, -10}}, {35, 5});
  ASSERT_TRUE(r.ok) << r.messages;
  EXPECT_EQ(r.plan.kind, ThreadKind::kFace);
  EXPECT_FALSE(r.plan.lead_along_z);
  EXPECT_DOUBLE_EQ(r.plan.cutang, 270);
  expect_path(r.plan.passes[0], {{30, -0.5}, {20, -0.5}, {10, -10.5}});
  EXPECT_NEAR(r.plan.end_position.x, 30, 1e-12);
  EXPECT_NEAR(r.plan.end_position.z, 5, 1e-12);
}

TEST(ChainThread, PlanJsonHasPointsAndPaths) {
  const Chain r = chain("THREAD/ON,DEPTH,0.5,CHAIN", {{15, 0}, {15, -10}, {16, -20}});
  ASSERT_TRUE(r.ok) << r.messages;
  const std::string json = plan_to_json("t.cl", LengthUnit::kMm, {r.plan});
  EXPECT_NE(json.find("\"form\": \"chain\""), std::string::npos) << json;
  EXPECT_NE(json.find("\"points\": [{\"x\": 15, \"z\": 0}, {\"x\": 15, \"z\": -10}, "
                      "{\"x\": 16, \"z\": -20}],"),
            std::string::npos)
      << json;
  EXPECT_NE(json.find("\"from\": {\"x\": 14.5, \"z\": 0}, \"to\": {\"x\": 15.5, \"z\": -20}, "
                      "\"path\": [{\"x\": 14.5, \"z\": 0}, {\"x\": 14.5, \"z\": -10}, "
                      "{\"x\": 15.5, \"z\": -20}]}"),
            std::string::npos)
      << json;
  const std::string text = plan_to_text("t.cl", LengthUnit::kMm, {r.plan});
  EXPECT_NE(text.find("  contour (X 15, Z 0) -> (X 15, Z -10) -> (X 16, Z -20)\n"),
            std::string::npos)
      << text;
  EXPECT_NE(text.find("(X 14.5, Z 0) -> (X 14.5, Z -10) -> (X 15.5, Z -20)\n"), std::string::npos)
      << text;
  EXPECT_NE(text.find("  returns to X 30; ends at (X 30, Z 0)\n"), std::string::npos) << text;
}

TEST(ChainThread, NegativeChamfrShortensTheLastSegment) {
  // CHAMFR,-2 (45 degrees) on a last segment along -Z: every pass ends 2 earlier and runs out
  // 2 along it and 2 outward (X +2, Z -2), ending where the pass would have ended.
  const Chain r = chain("THREAD/ON,DEPTH,1,CHAMFR,-2,CHAIN", {{15, 0}, {15, -10}, {15, -20}});
  ASSERT_TRUE(r.ok) << r.messages;
  ASSERT_TRUE(r.plan.pullout.has_value());
  EXPECT_NEAR(r.plan.pullout->x, 2, 1e-12);
  EXPECT_NEAR(r.plan.pullout->z, -2, 1e-12);
  expect_path(r.plan.passes[0], {{14, 0}, {14, -10}, {14, -18}});
  EXPECT_NEAR(r.plan.passes[0].pullout_end.x, 16, 1e-12);
  EXPECT_NEAR(r.plan.passes[0].pullout_end.z, -20, 1e-12);
}

TEST(ChainThread, ClearLineBelowThePulloutIsRaised) {
  // P0 X 16, one pass 1 deep, ATANGL,0,3 pulls 3 straight out to X 17: the tool clears to 17.
  const Chain r = chain("THREAD/ON,DEPTH,1,ATANGL,0,3,CHAIN", {{15, 0}, {15, -10}}, {16, 5});
  ASSERT_TRUE(r.ok) << r.messages;
  EXPECT_EQ(r.messages,
            "t.cl:2:1: warning: the clear line X 16 is inside the pull-out end: the tool clears "
            "to 17\n");
  EXPECT_NEAR(r.plan.end_position.x, 17, 1e-12);
  EXPECT_NEAR(r.plan.passes[0].clear.x, 17, 1e-12);
}

TEST(ChainThread, FaceChainErrorsNameTheXAxis) {
  const Chain r = chain("THREAD/ON,DEPTH,1,CHAIN", {{30, 0}, {20, 0}, {25, -5}}, {35, 5});
  EXPECT_FALSE(r.ok);
  EXPECT_EQ(r.messages,
            "t.cl:5:1: error: the chain segment from (X 20, Z 0) to (X 25, Z -5) moves 5 along X; "
            "every segment must advance along X like the first one (-X)\n"
            "t.cl:2:1: note: the thread sequence starts here\n");
}

struct ChainError {
  const char* on;
  std::vector<Vec2> gotos;
  Vec2 p0;
  const char* expected;
};

void expect_chain_errors(const std::vector<ChainError>& cases) {
  for (const ChainError& c : cases) {
    PlannerSettings settings;
    settings.variable_lead = true;  // the chain's own refusal of INCR / DECR
    const Chain r = chain(c.on, c.gotos, c.p0, pitch_of(2), settings);
    EXPECT_FALSE(r.ok) << c.on;
    EXPECT_EQ(r.messages, c.expected) << c.on;
  }
}

TEST(ChainThread, GotoAndSegmentErrors) {
  std::vector<Vec2> many;
  for (int i = 0; i < 22; ++i) many.push_back({15, -2.0 * i});
  expect_chain_errors({
      {"THREAD/ON,DEPTH,1,CHAIN",
       {{15, 0}},
       {30, 5},
       "t.cl:2:1: error: THREAD/ON,CHAIN needs 2 to 21 GOTOs before THREAD/OFF (the thread "
       "contour); found 1\n"},
      {"THREAD/ON,DEPTH,1,CHAIN",
       many,
       {30, 5},
       "t.cl:24:1: error: THREAD/ON,CHAIN takes at most 21 GOTOs before THREAD/OFF (20 "
       "segments); this is GOTO 22\n"
       "t.cl:2:1: note: the thread sequence starts here\n"},
      {"THREAD/ON,DEPTH,1,CHAIN",
       {{15, 0}, {15, 0}, {15, -10}},
       {30, 5},
       "t.cl:4:1: error: GOTO 2 (X 15, Z 0) repeats the point before it: a chain segment needs "
       "a length\n"
       "t.cl:2:1: note: the thread sequence starts here\n"},
      {"THREAD/ON,DEPTH,1,CHAIN",
       {{15, 0}, {15, -10}, {15, -10}},
       {30, 5},
       "t.cl:5:1: error: GOTO 3 (X 15, Z -10) repeats the point before it: a chain segment needs "
       "a length\n"
       "t.cl:2:1: note: the thread sequence starts here\n"},
      {"THREAD/ON,DEPTH,1,CHAIN",
       {{15, 0}, {15, -10}, {16, -5}},
       {30, 5},
       "t.cl:5:1: error: the chain segment from (X 15, Z -10) to (X 16, Z -5) moves 5 along Z; "
       "every segment must advance along Z like the first one (-Z)\n"
       "t.cl:2:1: note: the thread sequence starts here\n"},
      {"THREAD/ON,DEPTH,1,CHAIN",
       {{15, 0}, {15, -10}, {20, -10}},
       {30, 5},
       "t.cl:5:1: error: the chain segment from (X 15, Z -10) to (X 20, Z -10) moves 0 along Z; "
       "every segment must advance along Z like the first one (-Z)\n"
       "t.cl:2:1: note: the thread sequence starts here\n"},
      {"THREAD/ON,DEPTH,1,CHAIN",
       {{15, 0}, {15, -10}, {18, -12}},
       {30, 5},
       "t.cl:5:1: error: the chain segment from (X 15, Z -10) to (X 18, Z -12) is 56.309932° off "
       "the Z axis; a chain segment may be at most 45° off it\n"
       "t.cl:2:1: note: the thread sequence starts here\n"},
  });
}

TEST(ChainThread, ReturnLeadShiftAndInfeedErrors) {
  expect_chain_errors({
      {"THREAD/ON,DEPTH,1,CHAIN",
       {{15, 0}, {15, -10}, {25, -20}},
       {20, 5},
       "t.cl:2:1: error: the tool returns to the initial point's X 20, which is not outside the "
       "chain contour: GOTO 3 (X 25, Z -20) reaches X 25; start from outside the contour or give "
       "RETURN,h\n"},
      {"THREAD/ON,DEPTH,1,CUTANG,180,RETURN,CHAIN",
       {{15, 0}, {15, -10}},
       {15, 5},
       "t.cl:2:30: error: the tool returns to the initial point's X 15, which is not outside the "
       "chain contour: GOTO 1 (X 15, Z 0) reaches X 15; start from outside the contour or give "
       "RETURN,h\n"},
      {"THREAD/ON,DEPTH,1,DECR,0.01,CHAIN",
       {{15, 0}, {15, -10}},
       {30, 5},
       "t.cl:2:19: error: a chained thread cuts one constant lead: DECR 0.01 (CL line 2) cannot "
       "be used with CHAIN\n"},
      {"THREAD/ON,DEPTH,1,OPTION,3,TLANGL,90,CHAIN",
       {{15, 0}, {15, -10}, {16, -11}},
       {30, 5},
       "t.cl:2:1: error: the passes end 1.414214 back along the last chain segment (largest "
       "flank shift 1, negative CHAMFR 0), which is only 1.414214 long\n"},
      {"THREAD/ON,DEPTH,1,CUTANG,95,CHAIN",
       {{15, 0}, {18, -10}, {21, -20}},
       {30, 5},
       "t.cl:2:19: error: CUTANG 95 is within 10° of the chain's lead axis Z: the infeed must "
       "cross it\n"},
  });
}

}  // namespace
}  // namespace clpost

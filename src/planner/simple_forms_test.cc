// Single-pass threads (THREAD/TURN|FACE|TAPER + 2 GOTOs) and coupled motion (COUPLE/ON ...).
#include <gtest/gtest.h>

#include <string>
#include <vector>

#include "planner/planner.h"
#include "planner/planner_test_util.h"

namespace clpost {
namespace {

using testing::make_goto;
using testing::pitch_of;
using testing::TestStatement;

std::string messages(const Diagnostics& d) {
  std::string out;
  for (const Diagnostic& x : d.kept()) {
    const std::string s = d.render(x);
    out += s.substr(0, s.find('\n') + 1);
  }
  return out;
}

// THREAD/<kind> on line 7, its GOTOs on lines 8, 9, ...
SingleThreadInput single(const std::string& line, const std::vector<Vec2>& gotos,
                         PitchSpec pitch = pitch_of(1.5)) {
  TestStatement st(line, 7);
  SingleThreadInput in;
  in.loc = st.st.loc;
  in.lines = st.saved();
  in.word = "THREAD/" + std::string(st.st.args.empty() ? "" : st.st.args[0].text);
  in.pitch = pitch;
  in.p0 = {12, 5};
  uint32_t n = 8;
  for (const Vec2& p : gotos) in.gotos.push_back(make_goto(p, n++));
  return in;
}

// COUPLE/ON on line 7 (its couplets applied to `modal`), the tool at `start`, GOTOs on 8, 9...
CoupleInput couple(const std::string& line, Vec2 start, const std::vector<Vec2>& gotos,
                   PitchSpec modal, Diagnostics& d) {
  TestStatement st(line, 7);
  CoupleInput in;
  in.loc = st.st.loc;
  in.lines = st.saved();
  in.pitch = modal;
  EXPECT_TRUE(parse_pitch_words(st.st, 1, LengthUnit::kMm, in.pitch, d)) << d.render_all();
  in.start = start;
  uint32_t n = 8;
  for (const Vec2& p : gotos) in.gotos.push_back(make_goto(p, n++));
  return in;
}

TEST(SingleThread, TurnIsOneSynchronizedMove) {
  Diagnostics d("t.cl");
  ThreadPlan p;
  ASSERT_TRUE(plan_single_thread(single("THREAD/TURN", {{10, 2}, {10, -20}}), {}, p, d))
      << d.render_all();
  EXPECT_EQ(p.form, ThreadForm::kSingle);
  EXPECT_EQ(p.kind, ThreadKind::kTurn);
  EXPECT_EQ(p.loc.line, 7u);
  EXPECT_EQ(p.lead, 1.5);
  ASSERT_EQ(p.path.size(), 2u);  // GOTO/start, COUPLE/ON, GOTO/end, COUPLE/OFF
  EXPECT_EQ(p.path[0].z, 2);
  EXPECT_EQ(p.path[1].z, -20);
  ASSERT_EQ(p.passes.size(), 1u);
  EXPECT_EQ(p.passes[0].n, 1);
  EXPECT_EQ(p.passes[0].depth, 0);
  EXPECT_EQ(p.passes[0].from.x, 10);
  EXPECT_EQ(p.passes[0].from.z, 2);
  EXPECT_EQ(p.passes[0].to.z, -20);
  EXPECT_EQ(p.p0.x, 12);  // where the tool was before THREAD/TURN
  EXPECT_EQ(p.p1.z, 2);
  EXPECT_EQ(p.p2.z, -20);
  EXPECT_EQ(p.end_position.z, -20);
  EXPECT_FALSE(p.pullout.has_value());
  EXPECT_EQ(d.warning_count(), 0u);
}

TEST(SingleThread, FaceAndTaper) {
  Diagnostics d("t.cl");
  ThreadPlan face;
  ASSERT_TRUE(plan_single_thread(single("THREAD/FACE", {{10, 0}, {2, 0}}), {}, face, d));
  EXPECT_EQ(face.kind, ThreadKind::kFace);
  EXPECT_FALSE(face.lead_along_z);
  ThreadPlan taper;
  ASSERT_TRUE(plan_single_thread(single("THREAD/TAPER", {{10, 2}, {11, -20}}), {}, taper, d));
  EXPECT_EQ(taper.kind, ThreadKind::kTaper);
  EXPECT_TRUE(taper.lead_along_z);
  // The minor word does not change the output: THREAD/TURN on a taper is still a taper.
  ThreadPlan turn_word;
  ASSERT_TRUE(plan_single_thread(single("THREAD/TURN", {{10, 2}, {11, -20}}), {}, turn_word, d));
  EXPECT_EQ(turn_word.kind, ThreadKind::kTaper);
}

TEST(SingleThread, Errors) {
  {
    Diagnostics d("t.cl");
    ThreadPlan p;
    EXPECT_FALSE(plan_single_thread(single("THREAD/TURN", {{10, 2}}), {}, p, d));
    EXPECT_EQ(messages(d),
              "t.cl:7:1: error: THREAD/TURN needs exactly 2 GOTOs (thread start, thread end); "
              "found 1\n");
  }
  {
    Diagnostics d("t.cl");
    ThreadPlan p;
    EXPECT_FALSE(
        plan_single_thread(single("THREAD/TURN", {{10, 2}, {10, -20}, {12, -22}}), {}, p, d));
    EXPECT_EQ(messages(d),
              "t.cl:10:1: error: THREAD/TURN takes exactly 2 GOTOs (thread start, thread end); "
              "this is GOTO 3 of 3 (use THREAD/ON for a chamfer pull-out)\n"
              "t.cl:7:1: note: the thread starts here\n");
  }
  {
    Diagnostics d("t.cl");
    ThreadPlan p;
    EXPECT_FALSE(plan_single_thread(single("THREAD/TURN", {{10, 2}, {10, 2}}), {}, p, d));
    EXPECT_EQ(messages(d),
              "t.cl:9:1: error: the thread end (X 10, Z 2) is the thread start: the thread has no "
              "length\n"
              "t.cl:7:1: note: the thread starts here\n");
  }
  {
    Diagnostics d("t.cl");
    ThreadPlan p;
    EXPECT_FALSE(
        plan_single_thread(single("THREAD/FACE", {{10, 0}, {2, 0}}, PitchSpec{}), {}, p, d));
    EXPECT_EQ(messages(d),
              "t.cl:7:1: error: no pitch in force at THREAD/FACE: give PITCH/ before it, or TPI, "
              "IPR, MMPR or PERREV on it\n");
  }
}

TEST(Couple, OnePassPerSynchronizedMove) {
  Diagnostics d("t.cl");
  CoupleInput in = couple("COUPLE/ON", {10, 2}, {{10, -20}, {12, -22}}, pitch_of(1.5), d);
  ThreadPlan p;
  ASSERT_TRUE(plan_couple(in, {}, p, d)) << d.render_all();
  EXPECT_EQ(p.form, ThreadForm::kCouple);
  EXPECT_EQ(p.kind, ThreadKind::kTurn);  // from the first move, the thread proper
  ASSERT_EQ(p.path.size(), 3u);
  EXPECT_EQ(p.path[0].z, 2);
  EXPECT_EQ(p.path[2].x, 12);
  ASSERT_EQ(p.passes.size(), 2u);
  EXPECT_EQ(p.passes[0].n, 1);
  EXPECT_EQ(p.passes[1].n, 2);
  EXPECT_EQ(p.passes[1].from.z, -20);
  EXPECT_EQ(p.passes[1].to.x, 12);
  EXPECT_EQ(p.passes[1].to.z, -22);
  EXPECT_EQ(p.end_position.z, -22);
  EXPECT_EQ(p.p1.z, 2);
  EXPECT_EQ(p.p2.z, -22);
}

TEST(Couple, PitchFromTheCoupleStatement) {
  Diagnostics d("t.cl");
  CoupleInput in = couple("COUPLE/ON,MMPR,2", {10, 2}, {{10, -20}}, pitch_of(1.5), d);
  ThreadPlan p;
  ASSERT_TRUE(plan_couple(in, {}, p, d));
  EXPECT_EQ(p.pitch.pitch, 2);
  EXPECT_EQ(p.lead, 2);
}

TEST(Couple, GotoThatDoesNotMoveIsSkipped) {
  Diagnostics d("t.cl");
  CoupleInput in =
      couple("COUPLE/ON", {10, 2}, {{10, -20}, {10, -20}, {12, -22}}, pitch_of(1.5), d);
  ThreadPlan p;
  ASSERT_TRUE(plan_couple(in, {}, p, d));
  EXPECT_EQ(p.passes.size(), 2u);
  EXPECT_EQ(p.path.size(), 3u);
  EXPECT_EQ(messages(d),
            "t.cl:9:1: warning: this GOTO (X 10, Z -20) does not move the tool: no synchronized "
            "move\n");
}

TEST(Couple, NoMoveIsAnError) {
  Diagnostics d("t.cl");
  CoupleInput in = couple("COUPLE/ON", {10, 2}, {}, pitch_of(1.5), d);
  ThreadPlan p;
  EXPECT_FALSE(plan_couple(in, {}, p, d));
  EXPECT_EQ(messages(d),
            "t.cl:7:1: error: COUPLE/ON has no synchronized move: expected a GOTO that moves the "
            "tool\n");
}

TEST(Couple, NoPitchIsAnError) {
  Diagnostics d("t.cl");
  CoupleInput in = couple("COUPLE/ON", {10, 2}, {{10, -20}}, PitchSpec{}, d);
  ThreadPlan p;
  EXPECT_FALSE(plan_couple(in, {}, p, d));
  EXPECT_EQ(messages(d),
            "t.cl:7:1: error: no pitch in force at COUPLE/ON: give PITCH/ before it, or TPI, IPR, "
            "MMPR or PERREV on it\n");
}

TEST(Couple, MultiStartIsCutOnce) {
  Diagnostics d("t.cl");
  CoupleInput in = couple("COUPLE/ON,MULTRD,2", {10, 2}, {{10, -20}}, pitch_of(1.5), d);
  ThreadPlan p;
  ASSERT_TRUE(plan_couple(in, {}, p, d));
  EXPECT_EQ(p.lead, 3);
  EXPECT_EQ(p.passes.size(), 1u);
  EXPECT_EQ(messages(d),
            "t.cl:7:1: warning: MULTRD 2 on COUPLE/ON: the path is cut once, at lead 3 (start 0); "
            "program the other starts as their own moves\n");
}

TEST(Couple, VariableLead) {
  PlannerSettings s;
  s.machine_name = "haas-st10";
  {
    Diagnostics d("t.cl");
    CoupleInput in = couple("COUPLE/ON,INCR,0.05", {10, 2}, {{10, -20}}, pitch_of(1.5), d);
    ThreadPlan p;
    EXPECT_FALSE(plan_couple(in, s, p, d));
    EXPECT_EQ(messages(d),
              "t.cl:7:11: error: variable lead (INCR 0.05 per revolution, CL line 7) cannot be cut "
              "on machine 'haas-st10': it does not declare variable-lead threading (G34/G35)\n");
  }
  {
    s.variable_lead = true;
    Diagnostics d("t.cl");
    CoupleInput in = couple("COUPLE/ON,INCR,0.05", {10, 2}, {{10, -20}}, pitch_of(1.5), d);
    ThreadPlan p;
    ASSERT_TRUE(plan_couple(in, s, p, d));
    EXPECT_EQ(p.pitch.lead_change, 0.05);
  }
}

}  // namespace
}  // namespace clpost

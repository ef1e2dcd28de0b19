// The plan as JSON and as a table, and how numbers are written.
#include "planner/plan_format.h"

#include <gtest/gtest.h>

#include <cmath>
#include <limits>
#include <string>

#include "planner/planner_test_util.h"
#include "planner/run_in.h"
#include "support/number_text.h"

namespace clpost {
namespace {

using testing::make_multi;
using testing::pitch_of;
using testing::TestStatement;

TEST(NumberText, TrimsAndRounds) {
  EXPECT_EQ(num_text(2.5), "2.5");
  EXPECT_EQ(num_text(60), "60");
  EXPECT_EQ(num_text(0.1 + 0.2), "0.3");  // 0.30000000000000004
  EXPECT_EQ(num_text(1.0 / 3), "0.333333");
  EXPECT_EQ(num_text(2.0 / 3), "0.666667");
  EXPECT_EQ(num_text(-19.711324865), "-19.711325");
  EXPECT_EQ(num_text(-1e-9), "0");  // never "-0"
  EXPECT_EQ(num_text(-0.0), "0");
  EXPECT_EQ(num_text(1234567.125), "1234567.125");
  EXPECT_EQ(num_text(1e12), "1e+12");
  EXPECT_EQ(num_text(std::numeric_limits<double>::infinity()), "inf");
}

// THREAD/ON,DEPTH,1,CUTS,2,OPTION,3,CHAMFR,1 at line 2; P0 (12, 5), P1 (10, 2), P2 (10, -20),
// pitch 1.5 (mm).
ThreadPlan small_thread() {
  TestStatement on("THREAD/ON,DEPTH,1,CUTS,2,OPTION,3,CHAMFR,1", 2);
  Diagnostics d("small.cl");
  testing::MultiCase c = make_multi(on, LengthUnit::kMm, {12, 5}, {{10, 2}, {10, -20}}, d);
  c.in.modal_pitch = pitch_of(1.5);
  ThreadPlan p;
  EXPECT_TRUE(c.parsed && plan_multi_thread(c.in, {}, p, d)) << d.render_all();
  return p;
}

TEST(PlanJson, SmallThread) {
  // OPTION 3: depths 0.5, 1; single-edge shifts 0.5 tan 30 = 0.288675 and tan 30 = 0.577350.
  // Pass 1: from Z 2 - 0.288675 = 1.711325 to -20 - 0.288675 + 0.577350 = -19.711325.
  // Pass 2: from Z 2 - 0.577350 = 1.42265 to -20. CHAMFR 1 at 45: pull-out (+1, -1).
  EXPECT_EQ(plan_to_json("small.cl", LengthUnit::kMm, {small_thread()}),
            R"({
  "file": "small.cl",
  "units": "mm",
  "threads": [
    {
      "line": 2,
      "form": "multi",
      "kind": "turn",
      "side": "external",
      "pitch": 1.5,
      "lead": 1.5,
      "starts": 1,
      "depth": 1,
      "option": 3,
      "tool_angle": 60,
      "cutang": 180,
      "p1": {"x": 10, "z": 2},
      "p2": {"x": 10, "z": -20},
      "pullout": {"x": 1, "z": -1},
      "rpm": null,
      "run_in": null,
      "run_out": null,
      "run_in_added": false,
      "lead_right": null,
      "passes": [
        {"n": 1, "start": 0, "depth": 0.5, "kind": "rough", "shift": 0.288675, "from": {"x": 9.5, "z": 1.711325}, "to": {"x": 9.5, "z": -19.711325}},
        {"n": 2, "start": 0, "depth": 1, "kind": "rough", "shift": 0.57735, "from": {"x": 9, "z": 1.42265}, "to": {"x": 9, "z": -20}}
      ]
    }
  ]
}
)");
}

TEST(PlanJson, NoThreads) {
  EXPECT_EQ(plan_to_json("empty.cl", LengthUnit::kInch, {}),
            "{\n  \"file\": \"empty.cl\",\n  \"units\": \"in\",\n  \"threads\": []\n}\n");
}

TEST(PlanJson, CoupledThreadHasNoInfeed) {
  ThreadPlan p;
  p.loc = {4, 1};
  p.form = ThreadForm::kCouple;
  p.pitch = pitch_of(2);
  p.lead = 2;
  p.p1 = {10, 0};
  p.p2 = {10, -5};
  ThreadPass s;
  s.n = 1;
  s.from = p.p1;
  s.to = p.p2;
  p.passes.push_back(s);
  ThreadPlan q = p;
  q.loc = {9, 1};
  q.form = ThreadForm::kSingle;
  q.kind = ThreadKind::kFace;
  EXPECT_EQ(plan_to_json("c.cl", LengthUnit::kMm, {p, q}),
            R"({
  "file": "c.cl",
  "units": "mm",
  "threads": [
    {
      "line": 4,
      "form": "couple",
      "kind": "turn",
      "side": "external",
      "pitch": 2,
      "lead": 2,
      "starts": 1,
      "depth": 0,
      "option": null,
      "tool_angle": null,
      "cutang": null,
      "p1": {"x": 10, "z": 0},
      "p2": {"x": 10, "z": -5},
      "pullout": null,
      "rpm": null,
      "run_in": null,
      "run_out": null,
      "run_in_added": false,
      "lead_right": null,
      "passes": [
        {"n": 1, "start": 0, "depth": 0, "kind": "rough", "shift": 0, "from": {"x": 10, "z": 0}, "to": {"x": 10, "z": -5}}
      ]
    },
    {
      "line": 9,
      "form": "single",
      "kind": "face",
      "side": "external",
      "pitch": 2,
      "lead": 2,
      "starts": 1,
      "depth": 0,
      "option": null,
      "tool_angle": null,
      "cutang": null,
      "p1": {"x": 10, "z": 0},
      "p2": {"x": 10, "z": -5},
      "pullout": null,
      "rpm": null,
      "run_in": null,
      "run_out": null,
      "run_in_added": false,
      "lead_right": null,
      "passes": [
        {"n": 1, "start": 0, "depth": 0, "kind": "rough", "shift": 0, "from": {"x": 10, "z": 0}, "to": {"x": 10, "z": -5}}
      ]
    }
  ]
}
)");
}

TEST(PlanJson, KindsAndSidesAndStarts) {
  ThreadPlan p;
  p.side = ThreadSide::kInternal;
  p.kind = ThreadKind::kTaper;
  p.pitch = pitch_of(1.5, 2);
  ThreadPass a;
  a.kind = PassKind::kFinish;
  a.start = 1;
  ThreadPass b;
  b.kind = PassKind::kSpring;
  p.passes = {a, b};
  const std::string j = plan_to_json("k.cl", LengthUnit::kMm, {p});
  EXPECT_NE(j.find("\"side\": \"internal\""), std::string::npos);
  EXPECT_NE(j.find("\"kind\": \"taper\""), std::string::npos);
  EXPECT_NE(j.find("\"starts\": 2"), std::string::npos);
  EXPECT_NE(j.find("{\"n\": 0, \"start\": 1, \"depth\": 0, \"kind\": \"finish\""),
            std::string::npos);
  EXPECT_NE(j.find("\"kind\": \"spring\""), std::string::npos);
}

TEST(PlanJson, FileNameIsEscaped) {
  // Quote, backslash, tab, a control byte, valid UTF-8 (é) kept, an invalid byte replaced.
  const std::string name = std::string("a\"b\\c\td\x01") + "\xC3\xA9" + "\xFF.cl";
  const std::string j = plan_to_json(name, LengthUnit::kMm, {});
  EXPECT_EQ(j.substr(0, j.find('\n', 2) + 1),
            "{\n  \"file\": \"a\\\"b\\\\c\\td\\u0001\xC3\xA9\\ufffd.cl\",\n");
}

TEST(PlanText, SmallThread) {
  EXPECT_EQ(plan_to_text("small.cl", LengthUnit::kMm, {small_thread()}),
            "small.cl: 1 thread (mm)\n"
            "\n"
            "line 2: multi turn thread, external, pitch 1.5, lead 1.5, 1 start, depth 1, option 3, "
            "tool angle 60, cutang 180, pull-out (X 1, Z -1) (threaded)\n"
            "  pass start      depth       step      shift  kind    from -> to\n"
            "     1     0        0.5        0.5   0.288675  rough   (X 9.5, Z 1.711325) -> (X 9.5, "
            "Z -19.711325)\n"
            "     2     0          1        0.5    0.57735  rough   (X 9, Z 1.42265) -> (X 9, Z "
            "-20)\n"
            "  returns 1.299038 above the thread line; ends at (X 11.299038, Z 2)\n");
}

// At 1000 rpm: V = 1000 x 1.5 / 60 = 25, δ2 = 0.033 x 25 = 0.825, δ1 = 0.825 x (0.01 - 1 - ln 0.01)
// = 0.825 x 3.615170 = 2.982515. Both passes cover Z 1.42265 (pass 2's start, 2 - tan 30 =
// 1.4226497) to -19.711325 (pass 1's end): the lead is right from 1.4226497 - 2.9825154 =
// -1.559866 to -19.711325 + 0.825 = -18.886325.
TEST(PlanText, RunInRunOutAndWhereTheLeadIsRight) {
  ThreadPlan p = small_thread();
  set_run_in_out(p, 1000, {0.033, 0.01});
  const std::string text = plan_to_text("small.cl", LengthUnit::kMm, {p});
  EXPECT_EQ(text.substr(text.rfind("  returns")),
            "  returns 1.299038 above the thread line; ends at (X 11.299038, Z 2)\n"
            "  run-in 2.982515, run-out 0.825 at 1000 rpm; lead right from Z -1.559866 to Z "
            "-18.886325\n");
  const std::string json = plan_to_json("small.cl", LengthUnit::kMm, {p});
  EXPECT_NE(json.find("      \"pullout\": {\"x\": 1, \"z\": -1},\n"
                      "      \"rpm\": 1000,\n"
                      "      \"run_in\": 2.982515,\n"
                      "      \"run_out\": 0.825,\n"
                      "      \"run_in_added\": false,\n"
                      "      \"lead_right\": {\"axis\": \"z\", \"from\": -1.559866, \"to\": "
                      "-18.886325},\n"
                      "      \"passes\": [\n"),
            std::string::npos)
      << json;
  // At 20000 rpm δ1 + δ2 = 0.033 x 500 x 4.615170 = 76.15 covers the whole cut.
  set_run_in_out(p, 20000, {0.033, 0.01});
  EXPECT_NE(plan_to_text("small.cl", LengthUnit::kMm, {p})
                .find("  run-in 59.650308, run-out 16.5 at 20000 rpm; no length has the right "
                      "lead\n"),
            std::string::npos);
  EXPECT_NE(plan_to_json("small.cl", LengthUnit::kMm, {p}).find("\"lead_right\": null"),
            std::string::npos);
}

TEST(PlanText, MultiStartByAngleShowsTheAngleAndPerStartSteps) {
  TestStatement on("THREAD/ON,CUTS,2,0.5,MULTRD,2,TPI,16", 2);
  Diagnostics d("m.cl");
  testing::MultiCase c = make_multi(on, LengthUnit::kMm, {12, 5}, {{10, 2}, {10, -20}}, d);
  PlannerSettings s;
  s.start_angle_word = true;
  ThreadPlan p;
  ASSERT_TRUE(c.parsed && plan_multi_thread(c.in, s, p, d)) << d.render_all();
  // TPI 16: pitch 25.4 / 16 = 1.5875, lead 3.175; return 1.5875 sqrt(3) / 2 = 1.374815.
  EXPECT_EQ(
      plan_to_text("m.cl", LengthUnit::kMm, {p}),
      "m.cl: 1 thread (mm)\n"
      "\n"
      "line 2: multi turn thread, external, pitch 1.5875 (16 TPI), lead 3.175, 2 starts (by "
      "spindle start angle), depth 1, option 0, tool angle 60, cutang 180, pull-out none\n"
      "  pass start   angle      depth       step      shift  kind    from -> to\n"
      "     1     0       0        0.5        0.5          0  rough   (X 9.5, Z 2) -> (X 9.5, "
      "Z -20)\n"
      "     1     1     180        0.5        0.5          0  rough   (X 9.5, Z 2) -> (X 9.5, "
      "Z -20)\n"
      "     2     0       0          1        0.5          0  rough   (X 9, Z 2) -> (X 9, Z "
      "-20)\n"
      "     2     1     180          1        0.5          0  rough   (X 9, Z 2) -> (X 9, Z "
      "-20)\n"
      "  returns 1.374815 above the thread line; ends at (X 11.374815, Z 2)\n");
}

TEST(PlanText, CoupledThread) {
  ThreadPlan p;
  p.loc = {4, 1};
  p.form = ThreadForm::kCouple;
  p.pitch = pitch_of(2);
  p.pitch.lead_change = 0.01;
  p.lead = 2;
  ThreadPass s;
  s.n = 1;
  s.from = {10, 0};
  s.to = {10, -5};
  p.passes.push_back(s);
  p.end_position = s.to;
  EXPECT_EQ(plan_to_text("c.cl", LengthUnit::kMm, {p, p}),
            "c.cl: 2 threads (mm)\n"
            "\n"
            "line 4: couple turn thread, external, pitch 2, lead 2, 1 start, lead change +0.01 per "
            "rev\n"
            "  pass start      depth       step      shift  kind    from -> to\n"
            "     1     0          0          0          0  rough   (X 10, Z 0) -> (X 10, Z -5)\n"
            "  ends at (X 10, Z -5)\n"
            "\n"
            "line 4: couple turn thread, external, pitch 2, lead 2, 1 start, lead change +0.01 per "
            "rev\n"
            "  pass start      depth       step      shift  kind    from -> to\n"
            "     1     0          0          0          0  rough   (X 10, Z 0) -> (X 10, Z -5)\n"
            "  ends at (X 10, Z -5)\n");
}

}  // namespace
}  // namespace clpost

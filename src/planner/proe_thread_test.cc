// The thread of a real CAM file: Pro/ENGINEER's NIST sample V20_cl_data_unified-iso.ncl
// (inches, X a radius, Z the spindle axis), read with the real reader and planned the way the
// interpreter does it: `OP/THREAD,TURN,<words>` ... `OP/THREAD,NOMORE`.
#include <gtest/gtest.h>

#include <cmath>
#include <string>
#include <string_view>

#include "planner/plan_format.h"
#include "planner/planner.h"
#include "reader/cl_reader.h"

namespace clpost {
namespace {

// The file as published (lines 1-32).
constexpr std::string_view kProE =
    "$$*          Pro/CLfile  Version 19.0 - 9738\n"
    "$$-> MFGNO / THREAD-TURN\n"
    "PARTNO / THREAD-TURN\n"
    "$$-> FEATNO / 5\n"
    "MACHIN / TURN, 01\n"
    "UNITS / INCHES\n"
    "TURRET / 1\n"
    "$$-> CSYS / 1.0000000000, 0.0000000000, 0.0000000000, 0.0000000000,  $\n"
    "            0.0000000000, 1.0000000000, 0.0000000000, 0.0000000000,  $\n"
    "            0.0000000000, 0.0000000000, 1.0000000000, 0.0000000000\n"
    "SPINDL / RPM, 400.000000,  CLW\n"
    "RAPID \n"
    "GOTO / 4.0000000000, 0.0000000000, 5.0000000000\n"
    "RAPID \n"
    "GOTO / 1.4500000000, 0.0000000000, 5.0000000000\n"
    "RAPID \n"
    "GOTO / 1.4500000000, 0.0000000000, 4.0000000000\n"
    "FEDRAT / 30.000000,  IPM\n"
    "OP  / THREAD , TURN, DEPTH, 0.061343, TPI, 10.000000, CUTS, 3, FINCUT, 3,$\n"
    " CUTANG, 180.000000\n"
    "GOTO / 1.2500000000, 0.0000000000, 4.0000000000\n"
    "GOTO / 1.2500000000, 0.0000000000, 2.0000000000\n"
    "OP  / THREAD, NOMORE\n"
    "RAPID \n"
    "GOTO / 1.4500000000, 0.0000000000, 4.0000000000\n"
    "RAPID \n"
    "GOTO / 4.0000000000, 0.0000000000, 4.0000000000\n"
    "RAPID \n"
    "GOTO / 4.0000000000, 0.0000000000, 5.0000000000\n"
    "SPINDL / OFF\n"
    "$$-> END / \n"
    "FINI \n";

bool is_op_thread(const Statement& st, std::string_view minor) {
  return st.major == "OP" && st.args.size() >= 2 && st.args[0].is("THREAD") && st.args[1].is(minor);
}

// Reads the file and plans its one thread.
bool plan_proe(ThreadPlan& plan, Diagnostics& diags) {
  ClReader reader(kProE, diags);
  Statement st;
  Vec2 last{};
  MultiThreadInput in;
  in.units = LengthUnit::kInch;
  in.on_word = "OP/THREAD";
  in.off_word = "OP/THREAD,NOMORE";
  bool inside = false;
  bool done = false;
  while (reader.next(st)) {
    if (st.major == "GOTO" && st.args.size() == 3) {
      const Vec2 p{st.args[0].number, st.args[2].number};  // X radius, Z axis; Y is 0
      if (inside) in.gotos.push_back(ThreadGoto{p, st.loc, SavedLines::of(st)});
      last = p;
    } else if (is_op_thread(st, "TURN")) {
      if (!parse_thread_words(st, 2, LengthUnit::kInch, in.words, diags)) return false;
      in.on_loc = st.loc;
      in.on_lines = SavedLines::of(st);
      in.p0 = last;
      in.feed_approach = true;  // FEDRAT/30,IPM is in force
      inside = true;
    } else if (is_op_thread(st, "NOMORE")) {
      in.off_loc = st.loc;
      inside = false;
      done = plan_multi_thread(in, PlannerSettings{}, plan, diags);
    }
  }
  return done && !diags.has_errors();
}

TEST(ProEThread, Plan) {
  Diagnostics diags("V20_cl_data_unified-iso.ncl");
  ThreadPlan p;
  ASSERT_TRUE(plan_proe(p, diags)) << diags.render_all();
  EXPECT_EQ(p.loc.line, 19u);
  EXPECT_EQ(p.kind, ThreadKind::kTurn);
  EXPECT_EQ(p.side, ThreadSide::kExternal);
  EXPECT_EQ(p.cutang, 180);
  EXPECT_EQ(p.option, 0);  // default
  // TPI 10 in an inch file: pitch 0.1.
  EXPECT_NEAR(p.pitch.pitch, 0.1, 1e-15);
  EXPECT_TRUE(p.pitch.from_tpi);
  EXPECT_EQ(p.lead, p.pitch.pitch);
  EXPECT_EQ(p.depth, 0.061343);
  EXPECT_TRUE(p.feed_approach);
  EXPECT_EQ(p.p0.x, 1.45);
  EXPECT_EQ(p.p0.z, 4);
  // OPTION 0, c = 3, R = D (FINCUT 3 has no allowance): d_i = D i (7 - i) / 12
  //   = 0.0306715, 0.0511192, 0.061343; then 3 spring passes at D.
  const double D = 0.061343;
  const double want[] = {D / 2, D * 10 / 12, D, D, D, D};
  const PassKind kinds[] = {PassKind::kRough,  PassKind::kRough,  PassKind::kRough,
                            PassKind::kSpring, PassKind::kSpring, PassKind::kSpring};
  // Default return: 0.1 / (2 tan 30) = 0.0866025 above the crest X 1.25.
  const double h = 0.1 * std::sqrt(3.0) / 2;
  ASSERT_EQ(p.passes.size(), 6u);
  for (int i = 0; i < 6; ++i) {
    const ThreadPass& s = p.passes[i];
    EXPECT_NEAR(s.depth, want[i], 1e-15);
    EXPECT_EQ(s.kind, kinds[i]);
    EXPECT_NEAR(s.from.x, 1.25 - want[i], 1e-12);
    EXPECT_EQ(s.from.z, 4);
    EXPECT_NEAR(s.to.x, 1.25 - want[i], 1e-12);
    EXPECT_EQ(s.to.z, 2);
    EXPECT_NEAR(s.approach.x, 1.25 + h, 1e-12);
    EXPECT_NEAR(s.clear.x, 1.25 + h, 1e-12);
    EXPECT_EQ(s.clear.z, 2);
  }
  EXPECT_NEAR(p.end_position.x, 1.25 + h, 1e-12);
  EXPECT_EQ(p.end_position.z, 4);
}

TEST(ProEThread, Json) {
  Diagnostics diags("V20_cl_data_unified-iso.ncl");
  ThreadPlan p;
  ASSERT_TRUE(plan_proe(p, diags)) << diags.render_all();
  // 1.25 - 0.0306715 = 1.2193285 prints as 1.219329 (6 decimals); 1.25 - 0.0511192 = 1.198881.
  EXPECT_EQ(plan_to_json("V20_cl_data_unified-iso.ncl", LengthUnit::kInch, {p}),
            R"({
  "file": "V20_cl_data_unified-iso.ncl",
  "units": "in",
  "threads": [
    {
      "line": 19,
      "form": "multi",
      "kind": "turn",
      "side": "external",
      "pitch": 0.1,
      "lead": 0.1,
      "starts": 1,
      "depth": 0.061343,
      "option": 0,
      "tool_angle": 60,
      "cutang": 180,
      "p1": {"x": 1.25, "z": 4},
      "p2": {"x": 1.25, "z": 2},
      "pullout": null,
      "rpm": null,
      "run_in": null,
      "run_out": null,
      "run_in_added": false,
      "lead_right": null,
      "passes": [
        {"n": 1, "start": 0, "depth": 0.030672, "kind": "rough", "shift": 0, "from": {"x": 1.219329, "z": 4}, "to": {"x": 1.219329, "z": 2}},
        {"n": 2, "start": 0, "depth": 0.051119, "kind": "rough", "shift": 0, "from": {"x": 1.198881, "z": 4}, "to": {"x": 1.198881, "z": 2}},
        {"n": 3, "start": 0, "depth": 0.061343, "kind": "rough", "shift": 0, "from": {"x": 1.188657, "z": 4}, "to": {"x": 1.188657, "z": 2}},
        {"n": 4, "start": 0, "depth": 0.061343, "kind": "spring", "shift": 0, "from": {"x": 1.188657, "z": 4}, "to": {"x": 1.188657, "z": 2}},
        {"n": 5, "start": 0, "depth": 0.061343, "kind": "spring", "shift": 0, "from": {"x": 1.188657, "z": 4}, "to": {"x": 1.188657, "z": 2}},
        {"n": 6, "start": 0, "depth": 0.061343, "kind": "spring", "shift": 0, "from": {"x": 1.188657, "z": 4}, "to": {"x": 1.188657, "z": 2}}
      ]
    }
  ]
}
)");
}

}  // namespace
}  // namespace clpost

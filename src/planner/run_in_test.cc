// The run-in law (Fanuc's "Incorrect threaded length") and where the lead is right, with the
// numbers worked out by hand.
#include "planner/run_in.h"

#include <gtest/gtest.h>

#include <cmath>

namespace clpost {
namespace {

constexpr LeadLaw kFanuc{0.033, 0.01};

// V = 1500 x 2 / 60 = 50 mm/s, T1·V = 0.033 x 50 = 1.65 = δ2;
// a − 1 − ln a = 0.01 − 1 + 4.605170 = 3.615170, δ1 = 1.65 x 3.615170 = 5.965031.
TEST(RunIn, FanucFormAt1500RpmAndA2mmLead) {
  const RunInOut r = run_in_out(1500, 2, kFanuc);
  EXPECT_NEAR(r.run_in, 5.965031, 1e-6);
  EXPECT_NEAR(r.run_out, 1.65, 1e-12);
}

TEST(RunIn, DoublingTheTimeConstantDoublesBoth) {
  const RunInOut r = run_in_out(1500, 2, {0.066, 0.01});
  EXPECT_NEAR(r.run_in, 11.930062, 1e-6);
  EXPECT_NEAR(r.run_out, 3.3, 1e-12);
}

// A smaller allowed error takes longer to reach: a = 0.001, a − 1 − ln a = 0.001 − 1 + 6.907755
// = 5.908755, δ1 = 1.65 x 5.908755 = 9.749446; δ2 does not depend on a.
TEST(RunIn, TheLeadErrorSetsOnlyTheRunIn) {
  const RunInOut r = run_in_out(1500, 2, {0.033, 0.001});
  EXPECT_NEAR(r.run_in, 9.749446, 1e-6);
  EXPECT_NEAR(r.run_out, 1.65, 1e-12);
}

// The shops' short form: R·L/1800 = 3000/1800 = 1.666667 = δ2, δ1 = 1.666667 x (−1 − ln 0.01)
// = 1.666667 x 3.605170 = 6.008617: 0.043586 and 0.016667 more than the manual's form.
TEST(RunIn, ShortFormIsALittleLonger) {
  const RunInOut s = short_form_run_in_out(1500, 2, 0.01);
  EXPECT_NEAR(s.run_in, 6.008617, 1e-6);
  EXPECT_NEAR(s.run_out, 1.666667, 1e-6);
  const RunInOut r = run_in_out(1500, 2, kFanuc);
  EXPECT_NEAR(s.run_in - r.run_in, 0.043586, 1e-6);
}

TEST(RunIn, NoSpeedNoRunIn) {
  EXPECT_EQ(run_in_out(0, 2, kFanuc).run_in, 0);
  EXPECT_EQ(run_in_out(1500, 0, kFanuc).run_out, 0);
}

// A 5 mm cut at a 3 mm lead: δ1 + δ2 = 0.033 x R x 3 / 60 x 4.615170 = 0.007615 R, shorter than
// 5 below R = 656.596: 656 rpm. The run-out alone (0.00165 R) below R = 3030.3: 3030 rpm.
TEST(RunIn, LargestRpmThatLeavesARightLead) {
  EXPECT_EQ(largest_rpm_with_right_lead(5, 3, kFanuc, true), 656);
  EXPECT_EQ(largest_rpm_with_right_lead(5, 3, kFanuc, false), 3030);
  // 0.001 long: 0.13 rpm would fill it.
  EXPECT_EQ(largest_rpm_with_right_lead(0.001, 3, kFanuc, true), 0);
}

ThreadPlan single_thread(Vec2 from, Vec2 to, double lead) {
  ThreadPlan p;
  p.form = ThreadForm::kSingle;
  p.p1 = from;
  p.p2 = to;
  p.lead = lead;
  p.pitch.pitch = lead;
  p.lead_along_z = std::abs(to.z - from.z) >= std::abs(to.x - from.x);
  p.path = {from, to};
  ThreadPass pass;
  pass.n = 1;
  pass.from = from;
  pass.to = to;
  p.passes = {pass};
  return p;
}

TEST(RunIn, TheWholeCutAndNoLengthRight) {
  // Z 2 to Z -3 at 2000 rpm, lead 3: V = 100 mm/s, δ2 = 3.3, δ1 = 3.3 x 3.615170 = 11.930062.
  ThreadPlan p = single_thread({10, 2}, {10, -3}, 3);
  set_run_in_out(p, 2000, kFanuc);
  EXPECT_EQ(p.rpm, 2000);
  EXPECT_NEAR(p.run_in, 11.930062, 1e-6);
  EXPECT_NEAR(p.run_out, 3.3, 1e-12);
  const LeadSpan s = lead_span(p);
  ASSERT_TRUE(s.known);
  EXPECT_FALSE(s.any);
  EXPECT_EQ(s.cut_from, 2);
  EXPECT_EQ(s.cut_to, -3);
  EXPECT_EQ(no_right_lead_warning(p, kFanuc),
            "run-in 11.930062 and run-out 3.3 at 2000 rpm, lead 3, cover the whole synchronized "
            "cut (5 long): no length of this thread has the right lead; 656 rpm or less leaves "
            "one");
  // At 600 rpm: V = 30, δ2 = 0.99, δ1 = 3.579018: right from Z 2 - 3.579018 = -1.579018 to
  // Z -3 + 0.99 = -2.01.
  set_run_in_out(p, 600, kFanuc);
  const LeadSpan slow = lead_span(p);
  EXPECT_TRUE(slow.any);
  EXPECT_NEAR(slow.from, -1.579018, 1e-6);
  EXPECT_NEAR(slow.to, -2.01, 1e-12);
  EXPECT_EQ(no_right_lead_warning(p, kFanuc), "");
}

TEST(RunIn, TheSpanEveryPassShares) {
  // Two passes toward -Z: from Z 1.8 to -19.7 and from Z 1.5 to -20. Shared: Z 1.5 to -19.7;
  // at 1500 rpm and lead 2 right from 1.5 - 5.965031 = -4.465031 to -19.7 + 1.65 = -18.05.
  ThreadPlan p = single_thread({10, 2}, {10, -20}, 2);
  p.form = ThreadForm::kMulti;
  p.passes.resize(2);
  p.passes[0].from = {9.7, 1.8};
  p.passes[0].to = {9.7, -19.7};
  p.passes[1].from = {9.4, 1.5};
  p.passes[1].to = {9.4, -20};
  set_run_in_out(p, 1500, kFanuc);
  const LeadSpan s = lead_span(p);
  EXPECT_TRUE(s.along_z);
  EXPECT_EQ(s.cut_from, 1.5);
  EXPECT_EQ(s.cut_to, -19.7);
  EXPECT_NEAR(s.from, -4.465031, 1e-6);
  EXPECT_NEAR(s.to, -18.05, 1e-12);
}

TEST(RunIn, AFaceThreadAlongX) {
  // From radius 20 to 10 at Z 0, lead 1 at 600 rpm: V = 10, δ2 = 0.33, δ1 = 1.193006; right from
  // X 20 - 1.193006 = 18.806994 to X 10 + 0.33 = 10.33.
  ThreadPlan p = single_thread({20, 0}, {10, 0}, 1);
  set_run_in_out(p, 600, kFanuc);
  const LeadSpan s = lead_span(p);
  EXPECT_FALSE(s.along_z);
  EXPECT_NEAR(s.from, 18.806994, 1e-6);
  EXPECT_NEAR(s.to, 10.33, 1e-12);
}

TEST(RunIn, AVariableLeadRunsOutAtTheLeadItEndsWith) {
  // INCR 0.1 over 20: K² = 4 + 2 x 0.1 x 20 = 8, K = 2.828427 at the end; δ2 = 0.033 x 1500 x
  // 2.828427 / 60 = 2.333452; δ1 at the starting lead 2: 5.965031.
  ThreadPlan p = single_thread({10, 0}, {10, -20}, 2);
  p.pitch.lead_change = 0.1;
  set_run_in_out(p, 1500, kFanuc);
  EXPECT_NEAR(p.run_in, 5.965031, 1e-6);
  EXPECT_NEAR(p.run_out, 2.333452, 1e-6);
}

TEST(RunIn, UnknownSpeed) {
  ThreadPlan p = single_thread({10, 2}, {10, -3}, 3);
  set_run_in_out(p, 0, kFanuc);
  EXPECT_EQ(p.run_in, 0);
  EXPECT_FALSE(lead_span(p).known);
  EXPECT_EQ(no_right_lead_warning(p, kFanuc), "");
}

TEST(RunIn, AddedBeforeTheStart) {
  // A taper from (10, 0) to (11, -20): t along Z has length 20 / sqrt(401) = 0.998752, so a run-in
  // of 5.965031 along Z is 5.972482 along the thread line.
  ThreadPlan p = single_thread({10, 0}, {11, -20}, 2);
  p.form = ThreadForm::kMulti;
  plan_run_in_out(p, 1500, kFanuc, true);
  EXPECT_TRUE(p.run_in_added);
  EXPECT_NEAR(added_run_in_along(p), 5.972482, 1e-6);
  plan_run_in_out(p, 1500, kFanuc, false);
  EXPECT_EQ(added_run_in_along(p), 0);
}

}  // namespace
}  // namespace clpost

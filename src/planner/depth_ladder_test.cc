// The depth ladder: every row of the DEPTH/CUTS/STEP table, the OPTION laws, FINCUT and the
// pass limit. Expected depths are worked out by hand in the comments.
#include "planner/depth_ladder.h"

#include <gtest/gtest.h>

#include <cmath>
#include <string>
#include <vector>

#include "planner/planner_test_util.h"

namespace clpost {
namespace {

using testing::TestStatement;

struct Result {
  bool ok = false;
  DepthLadder ladder;
  std::string messages;  // "file:line:col: error: message" lines
};

// Parses THREAD/ON words of `line` (line 3) and builds the ladder; OPTION from the words, else
// `default_option`.
Result ladder_of(const std::string& line, int default_option = 0) {
  TestStatement st(line, 3);
  Diagnostics d("t.cl");
  ThreadWords w;
  Result r;
  if (!parse_thread_words(st.st, 1, LengthUnit::kMm, w, d)) {
    ADD_FAILURE() << "words do not parse: " << line << "\n" << d.render_all();
    return r;
  }
  const int option = w.option.set ? w.option.value : default_option;
  r.ok = make_depth_ladder(w, option, st.saved(), st.st.loc, "THREAD/ON", r.ladder, d);
  EXPECT_EQ(r.ok, !d.has_errors());
  for (const Diagnostic& x : d.kept()) {
    const std::string s = d.render(x);
    r.messages += s.substr(0, s.find('\n') + 1);
  }
  return r;
}

void expect_depths(const DepthLadder& l, const std::vector<double>& want) {
  ASSERT_EQ(l.depths.size(), want.size());
  ASSERT_EQ(l.kinds.size(), want.size());
  for (size_t i = 0; i < want.size(); ++i)
    EXPECT_NEAR(l.depths[i], want[i], 1e-9) << "pass " << i + 1;
}

std::vector<PassKind> kinds(int rough, std::vector<PassKind> rest = {}) {
  std::vector<PassKind> k(static_cast<size_t>(rough), PassKind::kRough);
  k.insert(k.end(), rest.begin(), rest.end());
  return k;
}

// --- Constant steps: CUTS,c,STEP,s and CUTS,c,s. ---

TEST(DepthLadder, CutsWithStepWord) {
  // 4 passes at 0.5: 0.5, 1.0, 1.5, 2.0; D = 4 x 0.5 = 2.
  Result r = ladder_of("THREAD/ON,CUTS,4,STEP,0.5");
  ASSERT_TRUE(r.ok) << r.messages;
  expect_depths(r.ladder, {0.5, 1.0, 1.5, 2.0});
  EXPECT_EQ(r.ladder.depth, 2);
  EXPECT_EQ(r.ladder.kinds, kinds(4));
}

TEST(DepthLadder, CutsWithStepValue) {
  Result r = ladder_of("THREAD/ON,CUTS,4,0.5");
  ASSERT_TRUE(r.ok) << r.messages;
  expect_depths(r.ladder, {0.5, 1.0, 1.5, 2.0});
}

TEST(DepthLadder, ConstantStepsIgnoreTheOptionLaw) {
  // Steps given: OPTION 1 (degressive) changes nothing.
  Result r = ladder_of("THREAD/ON,CUTS,4,0.5,OPTION,1");
  ASSERT_TRUE(r.ok) << r.messages;
  expect_depths(r.ladder, {0.5, 1.0, 1.5, 2.0});
}

TEST(DepthLadder, ConstantStepsVerifiedByDepthWithFinish) {
  // DEPTH 2.2 = 4 x 0.5 + FINCUT 0.2: roughing to 2.0, then the finish pass at 2.2.
  Result r = ladder_of("THREAD/ON,DEPTH,2.2,CUTS,4,STEP,0.5,FINCUT,1,0.2");
  ASSERT_TRUE(r.ok) << r.messages;
  expect_depths(r.ladder, {0.5, 1.0, 1.5, 2.0, 2.2});
  EXPECT_EQ(r.ladder.kinds, kinds(4, {PassKind::kFinish}));
  EXPECT_NEAR(r.ladder.roughing_depth, 2.0, 1e-12);
}

TEST(DepthLadder, ConstantStepsWithoutDepthAddTheAllowance) {
  // No DEPTH: D = 3 x 0.4 + 0.1 = 1.3.
  Result r = ladder_of("THREAD/ON,CUTS,3,0.4,FINCUT,2,0.1");
  ASSERT_TRUE(r.ok) << r.messages;
  expect_depths(r.ladder, {0.4, 0.8, 1.2, 1.3, 1.3});
  EXPECT_NEAR(r.ladder.depth, 1.3, 1e-12);
  EXPECT_EQ(r.ladder.kinds, kinds(3, {PassKind::kFinish, PassKind::kSpring}));
}

TEST(DepthLadder, DepthMismatchStepWord) {
  Result r = ladder_of("THREAD/ON,DEPTH,2.5,CUTS,4,STEP,0.5,FINCUT,1,0.2");
  EXPECT_FALSE(r.ok);
  EXPECT_EQ(r.messages,
            "t.cl:3:11: error: DEPTH 2.5 does not match CUTS 4 x STEP 0.5 + FINCUT 0.2 = 2.2\n");
}

TEST(DepthLadder, DepthMismatchStepValueNoFinish) {
  Result r = ladder_of("THREAD/ON,CUTS,4,0.5,DEPTH,2.1");
  EXPECT_FALSE(r.ok);
  EXPECT_EQ(r.messages, "t.cl:3:22: error: DEPTH 2.1 does not match CUTS 4 x 0.5 = 2\n");
}

// --- Couplets. ---

TEST(DepthLadder, Couplets) {
  // 2 x 0.5 then 3 x 0.2: 0.5, 1.0, 1.2, 1.4, 1.6.
  Result r = ladder_of("THREAD/ON,CUTS,2,0.5,3,0.2");
  ASSERT_TRUE(r.ok) << r.messages;
  expect_depths(r.ladder, {0.5, 1.0, 1.2, 1.4, 1.6});
  EXPECT_NEAR(r.ladder.depth, 1.6, 1e-12);
}

TEST(DepthLadder, CoupletsVerifiedByDepth) {
  // 2 x 0.5 + 3 x 0.2 + FINCUT 0.1 = 1.7.
  Result r = ladder_of("THREAD/ON,DEPTH,1.7,CUTS,2,0.5,3,0.2,FINCUT,1,0.1");
  ASSERT_TRUE(r.ok) << r.messages;
  expect_depths(r.ladder, {0.5, 1.0, 1.2, 1.4, 1.6, 1.7});
}

TEST(DepthLadder, CoupletsDepthMismatch) {
  Result r = ladder_of("THREAD/ON,DEPTH,1.7,CUTS,2,0.5,3,0.2");
  EXPECT_FALSE(r.ok);
  EXPECT_EQ(r.messages,
            "t.cl:3:11: error: DEPTH 1.7 does not match CUTS 2 x 0.5 + 3 x 0.2 = 1.6\n");
}

TEST(DepthLadder, DepthSumToleranceIsOneMicroUnit) {
  // |1.6 + 0 - 1.6000005| = 5e-7 <= 1e-6: accepted, the last pass reaches DEPTH exactly.
  Result ok = ladder_of("THREAD/ON,DEPTH,1.6000005,CUTS,2,0.5,3,0.2");
  ASSERT_TRUE(ok.ok) << ok.messages;
  EXPECT_EQ(ok.ladder.depths.back(), 1.6000005);
  // |1.6 - 1.600002| = 2e-6 > 1e-6: rejected.
  Result bad = ladder_of("THREAD/ON,DEPTH,1.600002,CUTS,2,0.5,3,0.2");
  EXPECT_FALSE(bad.ok);
}

TEST(DepthLadder, StepConflictsWithCutsSteps) {
  Result r = ladder_of("THREAD/ON,CUTS,4,0.5,STEP,0.5");
  EXPECT_FALSE(r.ok);
  EXPECT_EQ(r.messages,
            "t.cl:3:22: error: STEP 0.5 conflicts with the steps given by CUTS 4 x 0.5: give the "
            "step either with CUTS,c,s or with CUTS,c,STEP,s\n");
}

// --- DEPTH,D,CUTS,c: the OPTION laws over R = D - f. ---

TEST(DepthLadder, Option0ByCount) {
  // c = 4, R = 2: d_i = R i (2c - i + 1) / (c (c + 1)) = 2 i (9 - i) / 20
  //   i = 1: 2*1*8/20 = 0.8; i = 2: 2*2*7/20 = 1.4; i = 3: 2*3*6/20 = 1.8; i = 4: 2*4*5/20 = 2.0
  Result r = ladder_of("THREAD/ON,DEPTH,2,CUTS,4");
  ASSERT_TRUE(r.ok) << r.messages;
  expect_depths(r.ladder, {0.8, 1.4, 1.8, 2.0});
  EXPECT_EQ(r.ladder.kinds, kinds(4));
}

TEST(DepthLadder, Option0ByCountStepsDecreaseByAConstant) {
  // c = 3, R = 0.92: steps proportional to 3, 2, 1 -> 0.46, 0.306667, 0.153333.
  Result r = ladder_of("THREAD/ON,DEPTH,0.92,CUTS,3,OPTION,0");
  ASSERT_TRUE(r.ok) << r.messages;
  expect_depths(r.ladder, {0.46, 0.46 + 0.92 / 3, 0.92});
}

TEST(DepthLadder, Option1And2ByCount) {
  // c = 4, R = 2: d_i = 2 sqrt(i / 4) = sqrt(i): 1, 1.414214, 1.732051, 2.
  for (int option : {1, 2}) {
    Result r = ladder_of("THREAD/ON,DEPTH,2,CUTS,4", option);
    ASSERT_TRUE(r.ok) << r.messages;
    expect_depths(r.ladder, {1, std::sqrt(2.0), std::sqrt(3.0), 2});
  }
}

TEST(DepthLadder, Option3And4ByCount) {
  // c = 4, R = 2: d_i = 2 i / 4: 0.5, 1, 1.5, 2.
  for (int option : {3, 4}) {
    Result r = ladder_of("THREAD/ON,DEPTH,2,CUTS,4", option);
    ASSERT_TRUE(r.ok) << r.messages;
    expect_depths(r.ladder, {0.5, 1, 1.5, 2});
  }
}

TEST(DepthLadder, OptionLawRunsOverDepthLessAllowance) {
  // D = 2.2, f = 0.2 -> R = 2; OPTION 3, c = 4: 0.5, 1, 1.5, 2, then finish at 2.2, spring at 2.2.
  Result r = ladder_of("THREAD/ON,DEPTH,2.2,CUTS,4,OPTION,3,FINCUT,2,0.2");
  ASSERT_TRUE(r.ok) << r.messages;
  expect_depths(r.ladder, {0.5, 1, 1.5, 2, 2.2, 2.2});
  EXPECT_EQ(r.ladder.kinds, kinds(4, {PassKind::kFinish, PassKind::kSpring}));
}

// --- DEPTH,D,STEP,s: first step s, count from the OPTION law. ---

TEST(DepthLadder, Option0ByFirstStep) {
  // R = 2, s = 1: c = max(1, ceil(2*2/1 - 1)) = 3; delta = 2 (1*3 - 2) / (3*2) = 1/3;
  // steps 1, 2/3, 1/3 -> 1, 1.666667, 2.
  Result r = ladder_of("THREAD/ON,DEPTH,2,STEP,1");
  ASSERT_TRUE(r.ok) << r.messages;
  expect_depths(r.ladder, {1, 5.0 / 3, 2});
}

TEST(DepthLadder, Option0ByFirstStepExactCount) {
  // R = 2, s = 0.8: c = ceil(4/0.8 - 1) = 4; delta = 2 (3.2 - 2) / 12 = 0.2;
  // steps 0.8, 0.6, 0.4, 0.2 -> 0.8, 1.4, 1.8, 2.0 (the same ladder as CUTS,4).
  Result r = ladder_of("THREAD/ON,DEPTH,2,STEP,0.8,OPTION,0");
  ASSERT_TRUE(r.ok) << r.messages;
  expect_depths(r.ladder, {0.8, 1.4, 1.8, 2.0});
}

TEST(DepthLadder, Option0FirstStepDeeperThanTheThread) {
  // R = 2, s = 3: c = max(1, ceil(4/3 - 1)) = 1: one pass at 2.
  Result r = ladder_of("THREAD/ON,DEPTH,2,STEP,3");
  ASSERT_TRUE(r.ok) << r.messages;
  expect_depths(r.ladder, {2});
}

TEST(DepthLadder, Option1ByFirstStep) {
  // R = 2, s = 0.8: c = ceil((2/0.8)^2) = ceil(6.25) = 7; d_i = min(2, 0.8 sqrt(i)):
  // 0.8, 1.131371, 1.385641, 1.6, 1.788854, 1.959592, 2 (0.8 sqrt 7 = 2.1166 -> 2).
  for (int option : {1, 2}) {
    Result r = ladder_of("THREAD/ON,DEPTH,2,STEP,0.8", option);
    ASSERT_TRUE(r.ok) << r.messages;
    expect_depths(r.ladder, {0.8, 0.8 * std::sqrt(2.0), 0.8 * std::sqrt(3.0), 1.6,
                             0.8 * std::sqrt(5.0), 0.8 * std::sqrt(6.0), 2});
  }
}

TEST(DepthLadder, Option1ByFirstStepExact) {
  // R = 2, s = 1: c = (2/1)^2 = 4: 1, 1.414214, 1.732051, 2.
  Result r = ladder_of("THREAD/ON,DEPTH,2,STEP,1,OPTION,1");
  ASSERT_TRUE(r.ok) << r.messages;
  expect_depths(r.ladder, {1, std::sqrt(2.0), std::sqrt(3.0), 2});
}

TEST(DepthLadder, Option3ByFirstStepLastTakesTheRest) {
  // R = 2, s = 0.6: c = ceil(3.333) = 4: 0.6, 1.2, 1.8, then the remaining 0.2 -> 2.
  for (int option : {3, 4}) {
    Result r = ladder_of("THREAD/ON,DEPTH,2,STEP,0.6", option);
    ASSERT_TRUE(r.ok) << r.messages;
    expect_depths(r.ladder, {0.6, 1.2, 1.8, 2});
  }
}

TEST(DepthLadder, RemainderBelowOneNanoUnitAddsNoPass) {
  // R = 2.0000000005, s = 0.5: ceil(4.000000001) = 5, but the 5th pass would remove 5e-10 <
  // 1e-9: 4 passes, the last at R.
  Result r = ladder_of("THREAD/ON,DEPTH,2.0000000005,STEP,0.5,OPTION,3");
  ASSERT_TRUE(r.ok) << r.messages;
  ASSERT_EQ(r.ladder.depths.size(), 4u);
  EXPECT_EQ(r.ladder.depths.back(), 2.0000000005);
  // R = 2.000000002: the remainder 2e-9 is a pass of its own.
  Result r5 = ladder_of("THREAD/ON,DEPTH,2.000000002,STEP,0.5,OPTION,3");
  ASSERT_TRUE(r5.ok) << r5.messages;
  ASSERT_EQ(r5.ladder.depths.size(), 5u);
  EXPECT_EQ(r5.ladder.depths[3], 2.0);
  EXPECT_EQ(r5.ladder.depths[4], 2.000000002);
}

TEST(DepthLadder, CountFunctionsApplyTheRemainderRule) {
  // OPTION 0, R = 2, s = 1 + 1e-12: 2R/s - 1 = 2.999999999996 -> c = 3 (last step 1/3).
  EXPECT_EQ(option_count_for_first_step(0, 2, 1 + 1e-12), 3);
  // OPTION 0, R = 2, s = 1 - 1e-12: 2R/s - 1 = 3.000000000004 -> ceil 4, but the 4th step would
  // be (4 - 4s)/4 = 1e-12 < 1e-9: c = 3.
  EXPECT_EQ(option_count_for_first_step(0, 2, 1 - 1e-12), 3);
  // OPTION 1, R = 2, s = 1 - 1e-12: (R/s)^2 = 4.000000000008 -> 5, but 2 - s*sqrt(4) = 2e-12:
  // c = 4.
  EXPECT_EQ(option_count_for_first_step(1, 2, 1 - 1e-12), 4);
  // OPTION 3, R = 2, s = 0.01: 200 passes, not 201 (2/0.01 is 200.00000000000003 in binary).
  EXPECT_EQ(option_count_for_first_step(3, 2, 0.01), 200);
}

// --- DEPTH alone, CUTS,1 alone. ---

TEST(DepthLadder, DepthAloneIsOnePass) {
  Result r = ladder_of("THREAD/ON,DEPTH,1.2");
  ASSERT_TRUE(r.ok) << r.messages;
  expect_depths(r.ladder, {1.2});
}

TEST(DepthLadder, DepthAloneWithFinish) {
  // One roughing pass to 2 - 0.3 = 1.7, then the finish pass at 2.
  Result r = ladder_of("THREAD/ON,DEPTH,2,FINCUT,1,0.3");
  ASSERT_TRUE(r.ok) << r.messages;
  expect_depths(r.ladder, {1.7, 2});
  EXPECT_EQ(r.ladder.kinds, kinds(1, {PassKind::kFinish}));
}

TEST(DepthLadder, CutsOneAloneCutsOnTheContour) {
  Result r = ladder_of("THREAD/ON,CUTS,1");
  ASSERT_TRUE(r.ok) << r.messages;
  expect_depths(r.ladder, {0});
  EXPECT_EQ(r.ladder.depth, 0);
}

TEST(DepthLadder, CutsOneWithSpringPasses) {
  Result r = ladder_of("THREAD/ON,CUTS,1,FINCUT,2");
  ASSERT_TRUE(r.ok) << r.messages;
  expect_depths(r.ladder, {0, 0, 0});
  EXPECT_EQ(r.ladder.kinds, kinds(1, {PassKind::kSpring, PassKind::kSpring}));
}

// --- FINCUT. ---

TEST(DepthLadder, FincutWithoutAllowanceMakesSpringPasses) {
  // f = 0: roughing reaches D; the 2 FINCUT passes repeat D.
  Result r = ladder_of("THREAD/ON,DEPTH,2,CUTS,4,OPTION,3,FINCUT,2");
  ASSERT_TRUE(r.ok) << r.messages;
  expect_depths(r.ladder, {0.5, 1, 1.5, 2, 2, 2});
  EXPECT_EQ(r.ladder.kinds, kinds(4, {PassKind::kSpring, PassKind::kSpring}));
}

TEST(DepthLadder, FincutFinishThenSpring) {
  // R = 2 - 0.2 = 1.8 over 3 passes (OPTION 3): 0.6, 1.2, 1.8; finish at 2, then 2 spring.
  Result r = ladder_of("THREAD/ON,DEPTH,2,CUTS,3,OPTION,3,FINCUT,3,0.2");
  ASSERT_TRUE(r.ok) << r.messages;
  expect_depths(r.ladder, {0.6, 1.2, 1.8, 2, 2, 2});
  EXPECT_EQ(r.ladder.kinds, kinds(3, {PassKind::kFinish, PassKind::kSpring, PassKind::kSpring}));
  EXPECT_EQ(r.ladder.finishing, 3);
  EXPECT_EQ(r.ladder.roughing, 3);
}

TEST(DepthLadder, FincutZeroCountStopsShortOfDepth) {
  // FINCUT,0,0.2: cut to 2 - 0.2 = 1.8 and stop.
  Result r = ladder_of("THREAD/ON,DEPTH,2,CUTS,3,OPTION,3,FINCUT,0,0.2");
  ASSERT_TRUE(r.ok) << r.messages;
  expect_depths(r.ladder, {0.6, 1.2, 1.8});
  EXPECT_EQ(r.ladder.depth, 2);
}

TEST(DepthLadder, AllowanceNotBelowDepthIsAnError) {
  Result r = ladder_of("THREAD/ON,DEPTH,2,CUTS,3,FINCUT,1,2");
  EXPECT_FALSE(r.ok);
  EXPECT_EQ(r.messages, "t.cl:3:26: error: FINCUT allowance 2 must be less than DEPTH 2\n");
}

TEST(DepthLadder, AllowanceWithoutDepthOnTheContourIsAnError) {
  Result r = ladder_of("THREAD/ON,CUTS,1,FINCUT,1,0.1");
  EXPECT_FALSE(r.ok);
  EXPECT_EQ(r.messages,
            "t.cl:3:18: error: FINCUT allowance 0.1 needs DEPTH: CUTS 1 without DEPTH cuts on the "
            "contour (depth 0)\n");
}

// --- Missing information. ---

TEST(DepthLadder, CutsMoreThanOneWithoutDepthOrStep) {
  Result r = ladder_of("THREAD/ON,CUTS,4");
  EXPECT_FALSE(r.ok);
  EXPECT_EQ(r.messages,
            "t.cl:3:11: error: CUTS 4 needs a depth or a step: give DEPTH,d, STEP,s or "
            "CUTS,4,s\n");
}

TEST(DepthLadder, StepWithoutDepthOrCuts) {
  Result r = ladder_of("THREAD/ON,STEP,0.5");
  EXPECT_FALSE(r.ok);
  EXPECT_EQ(r.messages,
            "t.cl:3:11: error: STEP 0.5 needs DEPTH or CUTS: give DEPTH,d or CUTS,c with it\n");
}

TEST(DepthLadder, NoDepthWordAtAll) {
  Result r = ladder_of("THREAD/ON,OPTION,1");
  EXPECT_FALSE(r.ok);
  EXPECT_EQ(r.messages,
            "t.cl:3:1: error: THREAD/ON gives no thread depth: expected DEPTH, CUTS or STEP\n");
}

// --- The 200-pass limit. ---

TEST(DepthLadder, TwoHundredPassesAreAllowed) {
  Result r = ladder_of("THREAD/ON,DEPTH,2,CUTS,198,FINCUT,2");
  ASSERT_TRUE(r.ok) << r.messages;
  EXPECT_EQ(r.ladder.depths.size(), 200u);
  Result s = ladder_of("THREAD/ON,DEPTH,2,STEP,0.01,OPTION,3");
  ASSERT_TRUE(s.ok) << s.messages;
  EXPECT_EQ(s.ladder.depths.size(), 200u);
}

TEST(DepthLadder, TwoHundredAndOnePassesAreNot) {
  Result r = ladder_of("THREAD/ON,DEPTH,2,CUTS,199,FINCUT,2");
  EXPECT_FALSE(r.ok);
  EXPECT_EQ(r.messages,
            "t.cl:3:19: error: the thread needs 201 passes (199 roughing + 2 finish); at most "
            "200 are allowed\n");
}

TEST(DepthLadder, CoupletsOverTheLimit) {
  // 150 + 51 = 201.
  Result r = ladder_of("THREAD/ON,CUTS,150,0.01,51,0.01");
  EXPECT_FALSE(r.ok);
  EXPECT_EQ(r.messages,
            "t.cl:3:11: error: the thread needs 201 passes (201 roughing + 0 finish); at most "
            "200 are allowed\n");
}

TEST(DepthLadder, TinyFirstStepOverTheLimit) {
  // OPTION 3, R = 2, s = 0.001: ceil(2000) = 2000 passes.
  Result r = ladder_of("THREAD/ON,DEPTH,2,STEP,0.001,OPTION,3");
  EXPECT_FALSE(r.ok);
  EXPECT_EQ(r.messages,
            "t.cl:3:19: error: the thread needs 2000 passes (2000 roughing + 0 finish); at most "
            "200 are allowed\n");
  // OPTION 1, s = 1e-9: (2e9)^2 = 4e18 passes: reported, never allocated.
  Result huge = ladder_of("THREAD/ON,DEPTH,2,STEP,0.000000001,OPTION,1");
  EXPECT_FALSE(huge.ok);
  EXPECT_EQ(huge.messages,
            "t.cl:3:19: error: the thread needs 4e+18 passes (4e+18 roughing + 0 finish); at "
            "most 200 are allowed\n");
}

}  // namespace
}  // namespace clpost

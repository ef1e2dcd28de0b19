// A plan made into a section, and the section's geometry (tips and the cut profile).
#include "plot/thread_section.h"

#include <gtest/gtest.h>

#include <cmath>
#include <numbers>
#include <vector>

#include "planner/run_in.h"
#include "plot/thread_profile.h"
#include "support/angles.h"

namespace clpost {
namespace {

// A 2-start plan as the planner makes it: ladder passes 1..2 for both starts (ICAM order), then a
// finish pass; the start's pass number repeats.
ThreadPlan two_start_plan() {
  ThreadPlan p;
  p.loc = {12, 1};
  p.form = ThreadForm::kMulti;
  p.side = ThreadSide::kInternal;
  p.units = LengthUnit::kInch;
  p.pitch.pitch = 0.0625;
  p.pitch.starts = 2;
  p.lead = 0.125;
  p.depth = 0.04;
  p.option = 1;
  p.tool_angle = 55;
  const double depth[] = {0.02, 0.02, 0.035, 0.035, 0.04, 0.04};
  for (int i = 0; i < 6; ++i) {
    ThreadPass t;
    t.n = i / 2 + 1;
    t.start = i % 2;
    t.depth = depth[i];
    t.shift = depth[i] * std::tan(radians(27.5));
    t.kind = i >= 4 ? PassKind::kFinish : PassKind::kRough;
    t.from = {1, 2};
    p.passes.push_back(t);
  }
  return p;
}

TEST(SectionFromPlan, CopiesThreadAndPassesInCuttingOrder) {
  const ThreadSection s = section_from_plan(two_start_plan(), "my thread");
  EXPECT_EQ(s.title, "my thread");
  EXPECT_EQ(s.units, LengthUnit::kInch);
  EXPECT_EQ(s.side, ThreadSide::kInternal);
  EXPECT_DOUBLE_EQ(s.pitch, 0.0625);
  EXPECT_DOUBLE_EQ(s.lead, 0.125);
  EXPECT_EQ(s.starts, 2);
  EXPECT_DOUBLE_EQ(s.depth, 0.04);
  EXPECT_DOUBLE_EQ(s.tool_angle, 55);
  ASSERT_EQ(s.passes.size(), 6u);
  const int n[] = {1, 1, 2, 2, 3, 3};
  for (size_t i = 0; i < 6; ++i) {
    EXPECT_EQ(s.passes[i].n, n[i]) << i;
    EXPECT_EQ(s.passes[i].start, static_cast<int>(i % 2)) << i;
  }
  EXPECT_DOUBLE_EQ(s.passes[2].depth, 0.035);
  EXPECT_NEAR(s.passes[2].shift, 0.035 * 0.520567, 1e-6);  // tan 27.5 deg = 0.520567
  EXPECT_EQ(s.passes[3].kind, PassKind::kRough);
  EXPECT_EQ(s.passes[4].kind, PassKind::kFinish);
}

TEST(SectionFromPlan, DefaultTitle) {
  EXPECT_EQ(section_from_plan(two_start_plan(), "").title,
            "thread at line 12 - pitch 0.0625, depth 0.04, OPTION 1");
  ThreadPlan coupled;
  coupled.form = ThreadForm::kCouple;
  coupled.loc = {7, 1};
  coupled.pitch.pitch = 2;
  const ThreadSection s = section_from_plan(coupled, "");
  EXPECT_EQ(s.title, "thread at line 7 - pitch 2, depth 0");
  EXPECT_TRUE(s.passes.empty());
}

// The depth of the profile at u, interpolated between its points.
double profile_at(const std::vector<SectionPoint>& prof, double u) {
  for (size_t i = 1; i < prof.size(); ++i)
    if (prof[i].u >= u) {
      const double t = (u - prof[i - 1].u) / (prof[i].u - prof[i - 1].u);
      return prof[i - 1].d + t * (prof[i].d - prof[i - 1].d);
    }
  return std::nan("");
}

TEST(CutProfile, OneSixtyDegreeV) {
  ThreadSection s;
  s.pitch = 1.5;
  s.lead = 1.5;
  s.depth = 0.9;
  s.passes.push_back({1, 0, 0.9, 0, PassKind::kFinish});
  const std::vector<SectionPoint> prof = cut_profile(s, -1.5, 1.5);
  ASSERT_GE(prof.size(), 3u);
  EXPECT_DOUBLE_EQ(prof.front().u, -1.5);
  EXPECT_DOUBLE_EQ(prof.back().u, 1.5);
  EXPECT_NEAR(profile_at(prof, 0), 0.9, 1e-9);
  EXPECT_NEAR(profile_at(prof, 0.3), 0.9 - 0.3 / std::tan(std::numbers::pi / 6), 1e-9);  // 0.380385
  EXPECT_NEAR(profile_at(prof, 0.6), 0, 1e-9);    // past the V's edge at 0.9 tan 30 = 0.5196
  EXPECT_NEAR(profile_at(prof, 1.5), 0.9, 1e-9);  // the next turn, one lead on
  EXPECT_NEAR(profile_at(prof, -1.2), 0.9 - 0.3 / std::tan(std::numbers::pi / 6), 1e-9);
  // Straight stretches are not sampled: crest, flank, flank, crest ... about a dozen points.
  EXPECT_LE(prof.size(), 16u);
}

TEST(CutProfile, FlankInfeedEnvelope) {
  // Two passes walking down the left flank (shift = depth tan 30): the left flanks coincide, the
  // groove is the deeper V.
  ThreadSection s;
  s.pitch = 2;
  const double k = std::tan(std::numbers::pi / 6);
  s.passes.push_back({1, 0, 0.5, 0.5 * k, PassKind::kRough});
  s.passes.push_back({2, 0, 1.0, 1.0 * k, PassKind::kFinish});
  const std::vector<SectionPoint> prof = cut_profile(s, -1, 3);
  EXPECT_NEAR(profile_at(prof, 0), 0, 1e-9);          // left flank leaves the surface at u = 0
  EXPECT_NEAR(profile_at(prof, k), 1.0, 1e-9);        // deepest tip
  EXPECT_NEAR(profile_at(prof, 0.5 * k), 0.5, 1e-9);  // on the common flank, at pass 1's tip
  EXPECT_NEAR(profile_at(prof, 1.5 * k), 0.5, 1e-9);  // right flank of the deep V
  EXPECT_NEAR(profile_at(prof, 1.5), 0, 1e-9);        // crest between the turns
}

TEST(SectionGeometry, GroovesOnePitchApartAndFallbacks) {
  ThreadSection s;
  s.pitch = 1.5;
  s.starts = 2;
  s.depth = 0.92;
  const SectionPoint t = pass_tip(s, {1, 1, 0.4, 0.1, PassKind::kRough});
  EXPECT_DOUBLE_EQ(t.u, 1.6);
  EXPECT_DOUBLE_EQ(t.d, 0.4);
  EXPECT_EQ(groove_count(s), 2);
  // No passes: the nominal V at depth D in each groove.
  const std::vector<SectionPoint> tips = cutting_tips(s);
  ASSERT_EQ(tips.size(), 2u);
  EXPECT_DOUBLE_EQ(tips[1].u, 1.5);
  EXPECT_DOUBLE_EQ(tips[1].d, 0.92);
  s.pitch = 0;
  s.lead = 3;
  EXPECT_DOUBLE_EQ(groove_pitch(s), 1.5);  // lead / starts
  s.tool_angle = std::nan("");
  EXPECT_NEAR(half_angle_tan(s), std::tan(std::numbers::pi / 6), 1e-12);
}

}  // namespace
}  // namespace clpost

namespace clpost {
namespace {

// A chain (threading.md section 11): one section per segment. Contour (X 15, Z 0) - (X 15,
// A single-pass thread from Z 2 to Z -30 at radius 10, lead 2, 1500 rpm: run-in 5.965031,
// run-out 1.65 (planner/run_in.h), the lead right from Z -3.965031 to -28.35.
TEST(SectionFromPlan, CarriesTheRunInAndRunOut) {
  ThreadPlan p;
  p.form = ThreadForm::kSingle;
  p.lead = 2;
  p.p1 = {10, 2};
  p.p2 = {10, -30};
  p.path = {p.p1, p.p2};
  ThreadPass pass;
  pass.from = p.p1;
  pass.to = p.p2;
  p.passes = {pass};
  EXPECT_FALSE(section_from_plan(p, "").zones.known);  // no speed: nothing known
  set_run_in_out(p, 1500, {0.033, 0.01});
  const SectionLead z = section_from_plan(p, "").zones;
  ASSERT_TRUE(z.known);
  EXPECT_TRUE(z.along_z);
  EXPECT_TRUE(z.any);
  EXPECT_EQ(z.cut_from, 2);
  EXPECT_EQ(z.cut_to, -30);
  EXPECT_NEAR(z.right_from, -3.965031, 1e-6);
  EXPECT_NEAR(z.right_to, -28.35, 1e-12);
  EXPECT_NEAR(z.run_in, 5.965031, 1e-6);
  EXPECT_EQ(z.rpm, 1500);
  EXPECT_EQ(z.across_lo, 10);
  EXPECT_EQ(z.across_hi, 10);
}

// Z -10) - (X 18, Z -16), every pass the contour moved 1 toward the axis: on the cylinder the
// depth is 1 with no shift; on the taper (direction (3, -6)/sqrt(45)) the depth at right angles
// is cos(26.565 deg) = 2/sqrt(5) = 0.894427 and the pass sits 1/sqrt(5) = 0.447214 back along it.
TEST(ThreadSection, ChainHasASectionPerSegment) {
  ThreadPlan plan;
  plan.form = ThreadForm::kChain;
  plan.loc.line = 7;
  plan.pitch.pitch = 2;
  plan.option = 0;
  plan.points = {{15, 0}, {15, -10}, {18, -16}};
  ThreadPass p;
  p.n = 1;
  p.depth = 1;
  p.path = {{14, 0}, {14, -10}, {17, -16}};
  plan.passes.push_back(p);
  const std::vector<ThreadSection> s = sections_from_plan(plan);
  ASSERT_EQ(s.size(), 2u);
  EXPECT_EQ(s[0].title,
            "thread at line 7 - segment 1 of 2, (X 15, Z 0) to (X 15, Z -10) - pitch 2, "
            "OPTION 0");
  EXPECT_NEAR(s[0].passes[0].depth, 1, 1e-12);
  EXPECT_NEAR(s[0].passes[0].shift, 0, 1e-12);
  EXPECT_NEAR(s[1].passes[0].depth, 2 / std::sqrt(5.0), 1e-12);
  EXPECT_NEAR(s[1].passes[0].shift, -1 / std::sqrt(5.0), 1e-12);
  EXPECT_NEAR(s[1].depth, 2 / std::sqrt(5.0), 1e-12);
  // Any other form: the one section of section_from_plan.
  plan.form = ThreadForm::kMulti;
  EXPECT_EQ(sections_from_plan(plan).size(), 1u);
}

}  // namespace
}  // namespace clpost

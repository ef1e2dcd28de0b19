// The seeded sets CI runs: 300 generated programs (seeds 1…300) posted on linuxcnc-lathe and run
// through rs274, 2000 (seeds 1…2000) posted on fanuc-0i-t, haas-st and nct-2000t (its programs
// with PITCH/…,TPI too) and read by the oracle's reader of their documented meanings
// (fanuc_reader.h), 5000 posted on heidenhain-pilot and read by heidenhain_reader.h, and 2000 on
// sinumerik-840d read by sinumerik_reader.h, each with block delete off and on, every event
// compared with the model's.
// It fails with the count of programs that differ, one line per class of difference, and the
// first program of each class in full (reproduce one with `build/tests/oracle_run --seed N`;
// longer runs on fresh seeds: `scripts/fuzz.sh --oracle SECONDS`).
#include <gtest/gtest.h>

#include "differential.h"

namespace oracle {
namespace {

TEST(OracleDifferential, SeededProgramsMatchRs274) {
  if (!rs274_installed())
    GTEST_SKIP() << "rs274 not installed (apt-get install linuxcnc-uspace): skipped";
  Differential d;
  std::string error;
  ASSERT_TRUE(d.init(CLPOST_SOURCE_DIR, error)) << error;
  const Summary s = d.run(1, 300, 0);
  std::printf("%s", summary_text(s).c_str());  // the count, the time and the classes
  std::string firsts;
  for (size_t i = 0; i < s.firsts.size() && i < 3; ++i) firsts += "\n" + report(s.firsts[i]);
  EXPECT_EQ(s.programs, 300);
  EXPECT_EQ(s.refused, 0);
  EXPECT_EQ(s.differing, 0) << s.differing << " of " << s.programs
                            << " programs differ (classes above; build/tests/oracle_run --seed N "
                               "shows any); the first ones:"
                            << firsts;
}

// The refusals a control may make of a generated program (a located clpost error): an arc
// right after GOHOME, where a machine whose home is its reference return does not know the
// arc's start.
// HEIDENHAIN: a program in another unit than the machine's (the control reads one unit, set
// outside the program), and LOADTL/n,ADJUST,m (its T word selects no offset).
bool expected_refusal(const std::string& klass) {
  return klass.find("an arc cannot start at the machine's home") != std::string::npos ||
         klass.find("(heidenhain) reads the whole program in mm") != std::string::npos ||
         klass.find("heidenhainpilot' cannot select offset") != std::string::npos;
}

// `count` programs from seed 1, at least `compared` of them not refused.
void expect_matches(Control control, int count = 2000, int compared = 0) {
  Differential d;
  std::string error;
  ASSERT_TRUE(d.init(CLPOST_SOURCE_DIR, error, control)) << error;
  const Summary s = d.run(1, count, 0);
  std::printf("%s", summary_text(s).c_str());
  std::string firsts;
  for (size_t i = 0; i < s.firsts.size() && i < 3; ++i) firsts += "\n" + report(s.firsts[i]);
  EXPECT_EQ(s.programs, count);
  EXPECT_GE(s.programs - s.refused, compared);
  for (const auto& [klass, c] : s.refusals)
    EXPECT_TRUE(expected_refusal(klass))
        << c.programs << " refused: " << klass << " (seed " << c.first_seed << ")";
  EXPECT_EQ(s.differing, 0) << s.differing << " of " << s.programs
                            << " programs differ (build/tests/oracle_run --control "
                            << control_name(control)
                            << " --seed N shows any); the first ones:" << firsts;
}

TEST(OracleDifferential, SeededProgramsMatchTheFanucReader) {
  expect_matches(Control::kFanuc);
}

TEST(OracleDifferential, SeededProgramsMatchTheHaasReader) {
  expect_matches(Control::kHaas);
}

// heidenhain-pilot refuses nine programs in ten of the generator's (inch, LOADTL ADJUST): 5000
// programs, at least 400 of them compared.
TEST(OracleDifferential, SeededProgramsMatchTheHeidenhainReader) {
  expect_matches(Control::kHeidenhain, 5000, 400);
}

TEST(OracleDifferential, SeededProgramsMatchTheNctReader) {
  expect_matches(Control::kNct);
}

TEST(OracleDifferential, SeededProgramsMatchTheSinumerikReader) {
  expect_matches(Control::kSinumerik);
}

// The oracle sees a wrong program: the model's events against rs274's for a program that cuts
// the arc the other way (G2 for the CL's G3) and at another feed.
TEST(OracleDifferential, AWrongProgramDiffers) {
  std::vector<Event> model(1), rs274(1);
  model[0].motion = rs274[0].motion = MotionKind::kArc;
  model[0].rotation = 1, rs274[0].rotation = -1;
  Difference d = compare_events(model, rs274).first;
  ASSERT_TRUE(d.found);
  EXPECT_EQ(d.field, "arc sense");
  rs274[0].rotation = 1;
  model[0].state.feed_given = rs274[0].state.feed_given = true;
  model[0].state.feed = 0.2, rs274[0].state.feed = 5.08;
  rs274[0].inch = true;
  d = compare_events(model, rs274).first;
  ASSERT_TRUE(d.found);
  EXPECT_EQ(d.field, "feed");
  EXPECT_EQ(d.detail, "model 0.2 mm/min, rs274 5.08 mm/min (G20)");
  rs274[0].state.feed = 0.2 + 1e-3;  // within half the last digit of F in inches (0.00127 mm)
  EXPECT_FALSE(compare_events(model, rs274).first.found);
}

}  // namespace
}  // namespace oracle

// The generator: reproducible, every program valid as the header of generator.h says, and the
// grammar's statements all drawn within the CI set's seeds.
#include <gtest/gtest.h>

#include <cmath>
#include <map>

#include "generator.h"
#include "model.h"

namespace oracle {
namespace {

TEST(OracleGenerator, TheSameSeedGivesTheSameProgram) {
  EXPECT_EQ(generate_program(17), generate_program(17));
  EXPECT_NE(generate_program(17), generate_program(18));
}

// Every arc starts and ends on its circle (within the rounding of its end point to 4 decimals),
// every program reads to its end in the model.
TEST(OracleGenerator, ProgramsAreValid) {
  for (uint32_t seed = 1; seed <= 2000; ++seed) {
    const std::string cl = generate_program(seed);
    ModelResult m = model_events(cl);
    ASSERT_EQ(m.error, "") << "seed " << seed << "\n" << cl;
    const Event* before = nullptr;
    for (const Event& e : m.events) {
      if (e.kind != Event::Kind::kMotion) continue;
      if (e.motion == MotionKind::kArc) {
        ASSERT_NE(before, nullptr) << "seed " << seed;
        const double r0 = std::hypot(before->x - e.cx, before->z - e.cz);
        const double r1 = std::hypot(e.x - e.cx, e.z - e.cz);
        EXPECT_NEAR(r0, r1, 2e-4 * (e.inch ? 25.4 : 1)) << "seed " << seed << ": " << e.source;
        EXPECT_GT(e.cx - r0, 0) << "seed " << seed << ": the arc crosses the axis";
      }
      before = &e;
    }
  }
}

TEST(OracleGenerator, EveryStatementOfTheGrammarIsDrawn) {
  std::map<std::string, int> seen;
  const char* kForms[] = {"UNITS/INCHES", "UNITS/MM",    "FEDRAT/",       ",MMPR",        ",IPM",
                          "MMPR,",        "SPINDL/ON",   "SPINDL/OFF",    ",SMM",         ",SFM",
                          "MAXRPM",       "RPM,",        ",ADJUST,",      "RAPID",        "GODLTA/",
                          "GOHOME/",      "CIRCLE/",     "OPSKIP/ON",     "DELAY/REV,",   ",REV\n",
                          ",SEC",         "COOLNT/MIST", "THREAD/TURN\n", "THREAD/TURN,", "PITCH/",
                          "FROM/"};
  int fedrat_without_mode = 0;
  for (uint32_t seed = 1; seed <= 300; ++seed) {
    const std::string cl = generate_program(seed);
    for (const char* f : kForms)
      if (cl.find(f) != std::string::npos) ++seen[f];
    for (size_t at = cl.find("FEDRAT/"); at != std::string::npos; at = cl.find("FEDRAT/", at + 1))
      if (cl.substr(at, cl.find('\n', at) - at).find_first_of("MI", 7) == std::string::npos)
        ++fedrat_without_mode;
  }
  for (const char* f : kForms) EXPECT_GE(seen[f], 5) << f;
  EXPECT_GE(fedrat_without_mode, 50);
}

// For NCT PITCH/ is also given in threads per inch and threads are also coupled (COUPLE/ON), and
// the model reads them; the other controls' programs have neither.
TEST(OracleGenerator, NctThreadFormsOnlyWhenAsked) {
  int tpi = 0, couple = 0;
  for (uint32_t seed = 1; seed <= 300; ++seed) {
    const std::string cl = generate_program(seed, true);
    EXPECT_EQ(model_events(cl).error, "") << "seed " << seed;
    tpi += cl.find(",TPI") != std::string::npos ? 1 : 0;
    couple += cl.find("COUPLE/ON") != std::string::npos ? 1 : 0;
    const std::string plain = generate_program(seed);
    EXPECT_EQ(plain.find(",TPI"), std::string::npos) << "seed " << seed;
    EXPECT_EQ(plain.find("COUPLE/"), std::string::npos) << "seed " << seed;
  }
  EXPECT_GE(tpi, 5);
  EXPECT_GE(couple, 5);
}

}  // namespace
}  // namespace oracle

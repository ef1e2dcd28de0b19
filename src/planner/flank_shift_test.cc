// Flank infeed (threading.md section 6): which passes are shifted and by how much. With a 60
// degree tool, sigma = d tan 30 = d / sqrt(3).
#include "planner/flank_shift.h"

#include <gtest/gtest.h>

#include <cmath>
#include <vector>

namespace clpost {
namespace {

const std::vector<double> kDepths = {0.3, 0.6, 0.9, 1.2};
const double kTan30 = 1 / std::sqrt(3.0);

TEST(FlankShifts, SingleEdgeShiftsEveryPass) {
  for (int option : {1, 3}) {
    const FlankShifts s = flank_shifts(kDepths, option, 180, 60);
    ASSERT_EQ(s.sigma.size(), 4u) << option;
    for (size_t i = 0; i < 4; ++i) EXPECT_NEAR(s.sigma[i], kDepths[i] * kTan30, 1e-15) << i;
    EXPECT_EQ(s.max, s.sigma[3]);
    EXPECT_NEAR(s.max, 1.2 * kTan30, 1e-15);  // 0.69282
  }
}

TEST(FlankShifts, AlternatingEdgesShiftTheEvenPassesOnly) {
  for (int option : {2, 4}) {
    const FlankShifts s = flank_shifts(kDepths, option, 270, 60);
    ASSERT_EQ(s.sigma.size(), 4u) << option;
    EXPECT_EQ(s.sigma[0], 0);
    EXPECT_NEAR(s.sigma[1], 0.6 * kTan30, 1e-15);
    EXPECT_EQ(s.sigma[2], 0);
    EXPECT_NEAR(s.sigma[3], 1.2 * kTan30, 1e-15);
    EXPECT_EQ(s.max, s.sigma[3]);
  }
}

TEST(FlankShifts, ToolAngleSetsTheShift) {
  // 90 degree tool: sigma = d tan 45 = d.
  const FlankShifts s = flank_shifts({0.5, 1.0}, 1, 0, 90);
  EXPECT_NEAR(s.sigma[0], 0.5, 1e-15);
  EXPECT_NEAR(s.sigma[1], 1.0, 1e-15);
}

TEST(FlankShifts, NoneForOptionZeroOrAnAngledInfeed) {
  for (const FlankShifts& s : {flank_shifts(kDepths, 0, 180, 60), flank_shifts(kDepths, 1, 150, 60),
                               flank_shifts(kDepths, 3, 180.5, 60)}) {
    EXPECT_EQ(s.sigma, std::vector<double>(4, 0.0));
    EXPECT_EQ(s.max, 0);
  }
  // Every multiple of 90 degrees counts as an axis, negative ones too.
  EXPECT_GT(flank_shifts(kDepths, 1, -90, 60).max, 0);
  EXPECT_GT(flank_shifts(kDepths, 1, 360, 60).max, 0);
}

TEST(FlankShifts, NoPassesNoShift) {
  const FlankShifts s = flank_shifts({}, 1, 180, 60);
  EXPECT_TRUE(s.sigma.empty());
  EXPECT_EQ(s.max, 0);
}

}  // namespace
}  // namespace clpost

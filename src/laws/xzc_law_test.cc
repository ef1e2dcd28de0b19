#include "laws/xzc_law.h"

#include <gtest/gtest.h>

#include <algorithm>
#include <cmath>

namespace clpost {
namespace {

// The whole motion of `pieces` from `a` (machine C `c0`), sampled densely, is within `tol` of
// the part line a-b; returns the part length they add up to.
double check_pieces(const std::vector<XzcPiece>& pieces, Point3 a, Point3 b, double index,
                    double c0, double tol) {
  XzcPoint at = xzc_point(a, index, c0);
  double length = 0;
  const double dx = b.x - a.x, dy = b.y - a.y, dz = b.z - a.z;
  const double len = std::sqrt(dx * dx + dy * dy + dz * dz);
  for (const XzcPiece& p : pieces) {
    for (int k = 0; k <= 64; ++k) {
      const double t = k / 64.0;
      const Point3 q = part_point(
          {at.r + (p.to.r - at.r) * t, at.c + (p.to.c - at.c) * t, at.z + (p.to.z - at.z) * t},
          index);
      // Distance from q to the segment a-b.
      const double u = std::clamp(
          ((q.x - a.x) * dx + (q.y - a.y) * dy + (q.z - a.z) * dz) / (len * len), 0.0, 1.0);
      const double ex = a.x + dx * u - q.x, ey = a.y + dy * u - q.y, ez = a.z + dz * u - q.z;
      EXPECT_LE(std::sqrt(ex * ex + ey * ey + ez * ez), tol + 1e-9) << "at t " << t;
    }
    EXPECT_LE(std::abs(p.to.c - at.c), 90 + 1e-9);
    length += p.length;
    at = p.to;
  }
  const Point3 end = part_point(at, index);
  EXPECT_NEAR(end.x, b.x, 1e-9);
  EXPECT_NEAR(end.y, b.y, 1e-9);
  EXPECT_NEAR(end.z, b.z, 1e-9);
  return length;
}

TEST(XzcLaw, PointIsRadiusAndIndexPlusAngle) {
  // GOTO/30,0,z at index 90: radius 30 at C90, as the face holes (docs/millturn.md).
  XzcPoint q = xzc_point({30, 0, -2}, 90, 0);
  EXPECT_DOUBLE_EQ(q.r, 30);
  EXPECT_DOUBLE_EQ(q.c, 90);
  EXPECT_DOUBLE_EQ(q.z, -2);
  // (0, 30) at index 0: C90; (3, 4) at index 10: radius 5, C 10 + 53.1301.
  EXPECT_NEAR(xzc_point({0, 30, 0}, 0, 0).c, 90, 1e-12);
  q = xzc_point({3, 4, 0}, 10, 0);
  EXPECT_DOUBLE_EQ(q.r, 5);
  EXPECT_NEAR(q.c, 63.130102354, 1e-9);
  // The nearest turn to the C before: 350 + 20 is 370 near 360, 10 near 0.
  EXPECT_NEAR(xzc_point({1, 0, 0}, 10, 360).c, 370, 1e-12);
  EXPECT_NEAR(xzc_point({1, 0, 0}, 10, 0).c, 10, 1e-12);
  // On the centre line, C stays where it is.
  EXPECT_DOUBLE_EQ(xzc_point({0, 0, 5}, 10, 123).c, 123);
  // And back.
  const Point3 p = part_point({5, 63.130102354, 1}, 10);
  EXPECT_NEAR(p.x, 3, 1e-9);
  EXPECT_NEAR(p.y, 4, 1e-9);
}

TEST(XzcLaw, ChordAcrossTheFaceIsSplitWithinTheTolerance) {
  // X10 from Y-10 to Y10 at index 0: C from -45 to 45, the radius 14.1421 -> 10 -> 14.1421.
  const Point3 a{10, -10, 0}, b{10, 10, 0};
  const auto pieces = xzc_line(a, b, 0, -45, 0.005);
  ASSERT_GT(pieces.size(), 4u);
  EXPECT_NEAR(check_pieces(pieces, a, b, 0, -45, 0.005), 20, 1e-9);
  EXPECT_NEAR(pieces.back().to.c, 45, 1e-9);
  EXPECT_NEAR(pieces.back().to.r, std::sqrt(200.0), 1e-9);
  // One piece (X and C linear) would miss the line by 4.14 mm at its middle: 14.14 - 10.
  EXPECT_NEAR(xzc_deviation({std::sqrt(200.0), -45, 0}, {std::sqrt(200.0), 45, 0}, 0, 2),
              std::sqrt(200.0) - 10, 1e-9);
  // A coarser tolerance gives fewer pieces.
  EXPECT_LT(xzc_line(a, b, 0, -45, 0.05).size(), pieces.size());
}

TEST(XzcLaw, LineThroughTheCentreFlipsCThere) {
  // X10 to X-10 on Y0 at index 30: in to the centre at C30, C turns 180 degrees there (two steps
  // of 90), out at C210 (or -150): never a spin at a tiny radius.
  const auto pieces = xzc_line({10, 0, -1}, {-10, 0, -1}, 30, 30, 0.005);
  ASSERT_EQ(pieces.size(), 4u);
  EXPECT_DOUBLE_EQ(pieces[0].to.r, 0);
  EXPECT_DOUBLE_EQ(pieces[0].to.c, 30);
  EXPECT_DOUBLE_EQ(pieces[0].length, 10);
  EXPECT_TRUE(pieces[1].flip);
  EXPECT_TRUE(pieces[2].flip);
  EXPECT_DOUBLE_EQ(pieces[1].length, 0);
  EXPECT_NEAR(std::abs(pieces[2].to.c - 30), 180, 1e-9);
  EXPECT_NEAR(std::abs(pieces[1].to.c - 30), 90, 1e-9);
  EXPECT_DOUBLE_EQ(pieces[3].to.r, 10);
  EXPECT_DOUBLE_EQ(pieces[3].to.c, pieces[2].to.c);
  EXPECT_DOUBLE_EQ(pieces[3].length, 10);
  // Passing 0.003 from the centre (tolerance 0.005): the same three moves, within 0.003.
  const Point3 a{10, 0.003, 0}, b{-10, 0.003, 0};
  const auto near = xzc_line(a, b, 0, 0, 0.005);
  ASSERT_EQ(near.size(), 4u);
  EXPECT_NEAR(check_pieces(near, a, b, 0, 0, 0.005), 20, 1e-9);
}

TEST(XzcLaw, LineJustOffTheCentreIsSplitNotFlipped) {
  // 0.5 from the centre: C turns from 2.8624 to 177.1376 over many short pieces, each within
  // the tolerance and none turning more than 90 degrees.
  const Point3 a{10, 0.5, 0}, b{-10, 0.5, 0};
  const double c0 = std::atan2(0.5, 10) * 180 / std::acos(-1.0);
  const auto pieces = xzc_line(a, b, 0, c0, 0.005);
  EXPECT_GT(pieces.size(), 20u);
  for (const XzcPiece& p : pieces) EXPECT_FALSE(p.flip);
  EXPECT_NEAR(check_pieces(pieces, a, b, 0, c0, 0.005), 20, 1e-9);
  EXPECT_NEAR(pieces.back().to.c, 177.1375947, 1e-6);
}

TEST(XzcLaw, RadialLineAndZMoveAreOnePiece) {
  // Along a radius (C constant) and along Z: the machine moves straight, exactly.
  EXPECT_EQ(xzc_line({10, 10, 0}, {20, 20, -5}, 0, 45, 0.005).size(), 1u);
  EXPECT_EQ(xzc_line({10, 10, 0}, {10, 10, -5}, 0, 45, 0.005).size(), 1u);
  // From the centre outward: C turns first (a flip on the centre), then the radial line.
  const auto out = xzc_line({0, 0, 0}, {0, 10, 0}, 0, 0, 0.005);
  ASSERT_EQ(out.size(), 2u);
  EXPECT_TRUE(out[0].flip);
  EXPECT_DOUBLE_EQ(out[0].to.c, 90);
  EXPECT_DOUBLE_EQ(out[1].to.r, 10);
  EXPECT_DOUBLE_EQ(out[1].length, 10);
}

}  // namespace
}  // namespace clpost

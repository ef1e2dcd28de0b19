// The face and peripheral views' geometry (plot/mill_views.h): machine X, Y, Z, C mapped back to
// the part as verify maps them, C indexing drawn as the arc it sweeps, G2/G3 along their arcs.
#include "plot/mill_views.h"
#include "support/angles.h"

#include <gtest/gtest.h>

#include <cmath>
#include <numbers>

namespace clpost {
namespace {

SimMillMove at(double x, double y, double z, double c, bool rapid = false, int plane = 17) {
  SimMillMove m;
  m.x = x;
  m.y = y;
  m.z = z;
  m.c = c;
  m.rapid = rapid;
  m.c_known = true;
  m.at_known = true;
  m.plane = plane;
  return m;
}

SimMillMove with_tool(SimMillMove m, int n) {
  m.tool = n;
  return m;
}

CutState tool(int n) {
  CutState s;
  s.tool = n;
  return s;
}

// haas-st-20y's face line at C30: X10 Y-10 to X10 Y10 (X a radius) is the part's line from
// (10 cos 30 + 10 sin 30, 10 sin 30 - 10 cos 30) = (13.6603, -3.6603) to (10 cos 30 - 10 sin 30,
// 10 sin 30 + 10 cos 30) = (3.6603, 13.6603): across part X, up part Y.
TEST(MillViews, AFaceLineAtACIndexIsThePartsLine) {
  MillViews v(true);
  v.mill_move(with_tool(at(10, -10, -1, 30, true), 3));
  v.mill_move(with_tool(at(10, 10, -1, 30), 3));
  const MillViewsDrawn d = v.finish({}, LengthUnit::kMm);
  ASSERT_EQ(d.face.path.moves.size(), 1u);
  const Move& m = d.face.path.moves[0];
  EXPECT_EQ(m.kind, MoveKind::kFeed);
  EXPECT_NEAR(m.from.z, 13.6603, 1e-4);
  EXPECT_NEAR(m.from.x, -3.6603, 1e-4);
  EXPECT_NEAR(m.to.z, 3.6603, 1e-4);
  EXPECT_NEAR(m.to.x, 13.6603, 1e-4);
  EXPECT_TRUE(d.has_face());
  EXPECT_FALSE(d.has_peripheral());
  EXPECT_NEAR(d.stock_radius, std::hypot(10, 10), 1e-9);  // the work's: nothing was turned
  EXPECT_FALSE(d.stock_turned);
}

// A rapid C index at radius 30 from C0 to C90 sweeps the quarter circle on the part: 18 steps
// of 5 degrees, each a chord of 2 * 30 * sin(2.5 deg); back to C0 the same; then C0 to C350 on a
// rollover control is 10 degrees the short way (2 chords), never below part Y 30 sin(-10 deg).
TEST(MillViews, ACIndexIsTheArcItSweepsOnThePart) {
  MillViews v(true);
  v.mill_move(with_tool(at(30, 0, 5, 0, true, 18), 3));
  v.mill_move(with_tool(at(30, 0, 5, 90, true, 18), 3));
  v.mill_move(with_tool(at(30, 0, 5, 0, true, 18), 3));
  v.mill_move(with_tool(at(30, 0, 5, 350, true, 18), 3));
  v.mill_move(with_tool(at(20, 0, 5, 350, false, 18), 3));  // a feed, so that the view is drawn
  const MillViewsDrawn d = v.finish({}, LengthUnit::kMm);
  EXPECT_EQ(d.face.measure.moves[0], 38u);
  EXPECT_NEAR(d.face.measure.length[0], 38 * 2 * 30 * std::sin(radians(2.5)), 1e-9);
  EXPECT_NEAR(d.face.measure.all.x_hi, 30, 1e-9);
  EXPECT_NEAR(d.face.measure.all.x_lo, 30 * std::sin(-radians(10)), 1e-9);
  EXPECT_EQ(d.face.measure.moves[1], 1u);
}

// haas-st-20y's G3 X-20. Y-10. Z-1. I-10. J10. in G17 from X20 (radius 10) Y-10 at C0: three
// quarters of the circle of radius 14.1421 about (0, 0), turning positively from -45 degrees
// through +90 to 225, drawn in steps of at most 5 degrees (270 / 5 = 54 chords).
TEST(MillViews, AG3InG17IsDrawnAlongItsArc) {
  MillViews v(true);
  v.mill_move(with_tool(at(10, -10, -1, 0, true), 3));
  SimMillMove g3 = at(-10, -10, -1, 0);
  g3.arc = g3.ccw = true;
  g3.i = -10;
  g3.j = 10;
  v.mill_move(with_tool(g3, 3));
  const MillViewsDrawn d = v.finish({}, LengthUnit::kMm);
  EXPECT_EQ(d.face.measure.moves[1], 54u);
  EXPECT_NEAR(d.face.measure.length[1], 54 * 2 * std::hypot(10, 10) * std::sin(radians(2.5)), 1e-9);
  EXPECT_NEAR(d.face.measure.all.x_hi, std::hypot(10, 10), 1e-9);  // through +Y (C90)
}

// A G19 line at C90, X40 (radius) Y0 from Z-10 to Z-20, is peripheral: unrolled at radius 40
// (its own), the arc length 40 * pi / 2 = 62.8319 up, Z across.
TEST(MillViews, AG19MoveIsUnrolledOnThePeriphery) {
  MillViews v(true);
  v.mill_move(with_tool(at(40, 0, -10, 90, true, 19), 4));
  v.mill_move(with_tool(at(40, 0, -20, 90, false, 19), 4));
  const MillViewsDrawn d = v.finish({}, LengthUnit::kMm);
  ASSERT_EQ(d.peripheral.path.moves.size(), 1u);
  const Move& m = d.peripheral.path.moves[0];
  EXPECT_NEAR(m.from.z, -10, 1e-9);
  EXPECT_NEAR(m.to.z, -20, 1e-9);
  EXPECT_NEAR(m.from.x, 20 * std::numbers::pi, 1e-9);
  EXPECT_NEAR(d.unroll_radius, 40, 1e-9);
  EXPECT_FALSE(d.has_face());
}

// Holes: a face hole at X (radius) 30, C90 is a mark at part (0, 30); a radial hole at Z-20,
// C270 with its R plane at radius 42, on a part turned to radius 40, is unrolled at the stock:
// 40 * 3 pi / 2 = 188.4956 up at Z -20. The turning tool's feeds (tool 1) turn the stock; the
// tool that wrote C (tool 3) does not.
TEST(MillViews, HolesAreMarksAtTheirC) {
  MillViews v(true);
  Move turn;
  turn.kind = MoveKind::kFeed;
  turn.from = {40, 0};
  turn.to = {40, -30};
  v.side_move(turn, tool(1));
  v.mill_move(with_tool(at(30, 0, 5, 90, true, 18), 3));
  turn.from = {30, 5};
  turn.to = {30, -8};
  v.side_move(turn, tool(3));  // the face hole's feed: C work
  std::vector<SimHole> holes(3);
  holes[0].x = 30;
  holes[0].c = 90;
  holes[1].radial = true;
  holes[1].z = -20;
  holes[1].r = 42;
  holes[1].c = 270;
  holes[2].x = 0;  // C never written: not drawn
  const MillViewsDrawn d = v.finish(holes, LengthUnit::kMm);
  ASSERT_EQ(d.face_holes.size(), 1u);
  EXPECT_NEAR(d.face_holes[0].z, 0, 1e-9);
  EXPECT_NEAR(d.face_holes[0].x, 30, 1e-9);
  ASSERT_EQ(d.radial_holes.size(), 1u);
  EXPECT_NEAR(d.radial_holes[0].z, -20, 1e-9);
  EXPECT_NEAR(d.radial_holes[0].x, 40 * 1.5 * std::numbers::pi, 1e-9);
  EXPECT_NEAR(d.stock_radius, 40, 1e-9);
  EXPECT_TRUE(d.stock_turned);
  EXPECT_TRUE(d.has_face());
  EXPECT_TRUE(d.has_peripheral());
}

// Before C is written nothing is C work, and the first move of the tool that writes C starts
// nowhere known in C (not drawn); another tool's moves after the C work (a turning tool, C still
// at its last index) are not C work either: only tool 3's feed from X10 to X20 at C45 is drawn.
TEST(MillViews, OnlyTheToolThatWroteCDrawsInTheViews) {
  MillViews v(true);
  SimMillMove before = at(20, 0, 2, 0, false, 18);
  before.c_known = false;
  v.mill_move(with_tool(before, 1));
  v.mill_move(with_tool(at(10, 0, 2, 45, true, 18), 3));
  v.mill_move(with_tool(at(20, 0, 2, 45, false, 18), 3));
  v.mill_move(with_tool(at(30, 0, 2, 45, false, 18), 5));
  const MillViewsDrawn d = v.finish({}, LengthUnit::kMm);
  EXPECT_EQ(d.face.measure.total(), 1u);
  EXPECT_EQ(d.face.measure.moves[1], 1u);
  EXPECT_NEAR(d.face.measure.length[1], 10, 1e-9);
  EXPECT_NEAR(d.face.measure.all.x_hi, 20 * std::sin(std::numbers::pi / 4), 1e-9);
}

// A face tool after a radial one on a machine with Y (MillTurn3x_PATH1's tool 5 after tool 4):
// tool 4 puts C back to 0 before the tool change, tool 5 writes no C and moves in G17 (a rapid,
// then a feed): its feed
// from X0.1 Y0.05 to X1.5 Y0.75 (radius X, at C0: the part's line, hypot(1.4, 0.7) = 1.565248)
// is C work, drawn in the face view.
TEST(MillViews, AFaceToolAtTheCTheLastToolLeftDrawsInTheFaceView) {
  MillViews v(true, true);
  v.mill_move(with_tool(at(7, 0.1, 2, 90, false, 19), 4));
  v.mill_move(with_tool(at(7, 0.1, 2, 0, true, 19), 4));
  v.mill_move(with_tool(at(0.1, 0.05, 0, 0, true, 17), 5));
  v.mill_move(with_tool(at(1.5, 0.75, 0, 0, false, 17), 5));
  const MillViewsDrawn d = v.finish({}, LengthUnit::kMm);
  EXPECT_TRUE(d.has_face());
  EXPECT_NEAR(d.face.measure.length[1], std::hypot(1.4, 0.7), 1e-9);
}

}  // namespace
}  // namespace clpost

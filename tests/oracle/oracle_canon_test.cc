// rs274's canonical calls as the oracle reads them; the lines are rs274's own output (LinuxCNC
// 2.9, `rs274 -t tests/oracle/data/offsets.tbl -g`) for small programs.
#include <gtest/gtest.h>

#include "canon.h"

namespace oracle {
namespace {

// G7 G18 G21 / T3 M6 G43 H12 / G96 D2500 S200 M3 / G0 X40 Z5 / G1 Z-10 G95 F0.2 /
// G2 X44 Z-12 I2 K0 / G4 P1.5 / G20 / X2.4 Z-0.6 / G33 Z-1 K0.05
constexpr const char* kCanon =
    "    1 N..... USE_LENGTH_UNITS(CANON_UNITS_MM)\n"
    "    7 N..... SELECT_PLANE(CANON_PLANE_XZ)\n"
    "    9 N..... COMMENT(\"interpreter: Lathe diameter mode changed to diameter\")\n"
    "   12 N..... SELECT_TOOL(3)\n"
    "   13 N..... START_CHANGE()\n"
    "   14 N..... STOP_SPINDLE_TURNING(0)\n"
    "   15 N..... CHANGE_TOOL(3)\n"
    "   16 N..... USE_TOOL_LENGTH_OFFSET(0.0000 0.0000 0.3048, 0.0000 0.0000 0.0000, 0.0000 "
    "0.0000 0.0000)\n"
    "   17 N..... SET_SPINDLE_MODE(0 2500.0000)\n"
    "   18 N..... SET_SPINDLE_SPEED(0, 200.0000)\n"
    "   19 N..... START_SPINDLE_CLOCKWISE(0)\n"
    "   20 N..... STRAIGHT_TRAVERSE(20.0000, 0.0000, 5.0000, 0.0000, 0.0000, 0.0000)\n"
    "   22 N..... SET_FEED_MODE(0, 1)\n"
    "   23 N..... SET_FEED_RATE(0.0000)\n"
    "   24 N..... SET_FEED_RATE(0.2000)\n"
    "   25 N..... STRAIGHT_FEED(20.0000, 0.0000, -10.0000, 0.0000, 0.0000, 0.0000)\n"
    "   26 N..... ARC_FEED(-12.0000, 22.0000, -10.0000, 22.0000, -1, 0.0000, 0.0000, 0.0000, "
    "0.0000)\n"
    "   27 N..... DWELL(1.5000)\n"
    "   31 N..... USE_LENGTH_UNITS(CANON_UNITS_INCHES)\n"
    "   36 N..... STRAIGHT_FEED(1.2000, 0.0000, -0.6000, 0.0000, 0.0000, 0.0000)\n"
    "   37 N..... START_SPEED_FEED_SYNC(0.050000,0)\n"
    "   38 N..... STRAIGHT_FEED(1.2000, 0.0000, -1.0000, 0.0000, 0.0000, 0.0000)\n"
    "   39 N..... STOP_SPEED_FEED_SYNCH()\n"
    "   40 N..... FLOOD_ON()\n"
    "   41 N..... STRAIGHT_TRAVERSE(2.0000, 0.0000, -1.0000, 0.0000, 0.0000, 0.0000)\n";

TEST(OracleCanon, EventsInMmWithTheInterpretersState) {
  std::vector<Event> e = canon_events(kCanon);
  ASSERT_EQ(e.size(), 7u);
  EXPECT_EQ(e[0].motion, MotionKind::kRapid);
  EXPECT_DOUBLE_EQ(e[0].x, 20);  // a radius, as rs274 prints it
  EXPECT_DOUBLE_EQ(e[0].z, 5);
  EXPECT_EQ(e[0].state.tool, 3);
  EXPECT_EQ(e[0].state.offset, 12);  // 0.3048 mm = 0.012 in: tool 12's offset
  EXPECT_TRUE(e[0].state.spindle.on && e[0].state.spindle.css);
  EXPECT_DOUBLE_EQ(e[0].state.spindle.speed, 200);
  EXPECT_DOUBLE_EQ(e[0].state.spindle.limit, 2500);
  EXPECT_EQ(e[1].motion, MotionKind::kFeed);
  EXPECT_DOUBLE_EQ(e[1].state.feed, 0.2);
  EXPECT_EQ(e[1].state.feed_mode, FeedMode::kPerRev);
  EXPECT_EQ(e[2].motion, MotionKind::kArc);
  EXPECT_DOUBLE_EQ(e[2].x, 22);
  EXPECT_DOUBLE_EQ(e[2].z, -12);
  EXPECT_DOUBLE_EQ(e[2].cx, 22);
  EXPECT_DOUBLE_EQ(e[2].cz, -10);
  EXPECT_EQ(e[2].rotation, -1);
  EXPECT_EQ(e[3].kind, Event::Kind::kDwell);
  EXPECT_DOUBLE_EQ(e[3].seconds, 1.5);
  // After G20 the numbers are inches: the same F0.2 is 0.2 in/rev = 5.08 mm/rev, S200 200 ft/min.
  EXPECT_NEAR(e[4].x, 30.48, 1e-9);
  EXPECT_NEAR(e[4].z, -15.24, 1e-9);
  EXPECT_NEAR(e[4].state.feed, 5.08, 1e-9);
  EXPECT_NEAR(e[4].state.spindle.speed, 60.96, 1e-9);
  EXPECT_TRUE(e[4].inch);
  EXPECT_EQ(e[5].motion, MotionKind::kThread);
  EXPECT_NEAR(e[5].lead, 1.27, 1e-9);
  EXPECT_EQ(e[6].motion, MotionKind::kRapid);
  EXPECT_TRUE(e[6].state.coolant.flood);
  EXPECT_FALSE(e[6].state.coolant.mist);
}

TEST(OracleCanon, SpindleStopsAndModes) {
  std::vector<Event> e = canon_events(
      "    1 N..... SET_SPINDLE_MODE(0 0.0000)\n"
      "    2 N..... SET_SPINDLE_SPEED(0, 500.0000)\n"
      "    3 N..... START_SPINDLE_COUNTERCLOCKWISE(0)\n"
      "    4 N..... STRAIGHT_TRAVERSE(1.0000, 0.0000, 0.0000, 0.0000, 0.0000, 0.0000)\n"
      "    5 N..... STOP_SPINDLE_TURNING(0)\n"
      "    6 N..... STRAIGHT_TRAVERSE(2.0000, 0.0000, 0.0000, 0.0000, 0.0000, 0.0000)\n");
  ASSERT_EQ(e.size(), 2u);
  EXPECT_TRUE(e[0].state.spindle.on);
  EXPECT_FALSE(e[0].state.spindle.css);
  EXPECT_EQ(e[0].state.spindle.dir, SpindleDir::kCcw);
  EXPECT_DOUBLE_EQ(e[0].state.spindle.speed, 500);
  EXPECT_FALSE(e[1].state.spindle.on);
  EXPECT_FALSE(e[1].state.feed_given);
}

}  // namespace
}  // namespace oracle

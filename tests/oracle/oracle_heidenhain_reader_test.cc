// The oracle's reader of HEIDENHAIN DIN programs on small hand-written programs, each event's
// numbers computed by hand (mm, X a radius), and the refusals where the control's meaning is a
// parameter or not documented.
#include <gtest/gtest.h>

#include "heidenhain_reader.h"

namespace oracle {
namespace {

constexpr const char* kProgram =
    "%1.nc\n[METRIC]\nMACHINING\n[a comment]\nN 10 T3\nN 20 G26 S2500\nN 30 G96 S200 M3\n"
    "N 40 G0 X40. Z5.\nN 50 G1 Z-10. G95 F0.2 [turning]\nN 60 G2 X44. Z-12. I2. K0.\n"
    "N 70 G4 F1.5\nN 80 G97 S500 M4\nN 90 G26 S500\nN 100 G33 Z-30 F1.5\nN 110 M8\n"
    "N 120 G0 X50\nN 130 G94 G1 X52 F100\nN 140 M30\nEND\n";

TEST(OracleHeidenhainReader, AProgramBecomesEvents) {
  const ControlRun r = heidenhain_events(kProgram, false, false);
  ASSERT_EQ(r.error, "");
  ASSERT_EQ(r.events.size(), 7u);
  const Event& rapid = r.events[0];
  EXPECT_EQ(rapid.motion, MotionKind::kRapid);
  EXPECT_DOUBLE_EQ(rapid.x, 20);  // X40. is a diameter
  EXPECT_DOUBLE_EQ(rapid.z, 5);
  EXPECT_EQ(rapid.state.tool, 3);
  EXPECT_EQ(rapid.state.offset, 3);  // the turret position's own tool data
  EXPECT_TRUE(rapid.state.spindle.on && rapid.state.spindle.css);
  EXPECT_DOUBLE_EQ(rapid.state.spindle.speed, 200);
  EXPECT_DOUBLE_EQ(rapid.state.spindle.limit, 2500);
  EXPECT_EQ(r.events[1].state.feed_mode, FeedMode::kPerRev);
  EXPECT_DOUBLE_EQ(r.events[1].state.feed, 0.2);
  const Event& arc = r.events[2];  // from X20 Z-10: I2. K0. the centre 2 further out (a radius)
  EXPECT_EQ(arc.motion, MotionKind::kArc);
  EXPECT_EQ(arc.rotation, -1);
  EXPECT_DOUBLE_EQ(arc.x, 22);
  EXPECT_DOUBLE_EQ(arc.cx, 22);
  EXPECT_DOUBLE_EQ(arc.cz, -10);
  EXPECT_EQ(r.events[3].kind, Event::Kind::kDwell);
  EXPECT_DOUBLE_EQ(r.events[3].seconds, 1.5);
  const Event& thread = r.events[4];  // "Z-30" without a point is 30 mm
  EXPECT_EQ(thread.motion, MotionKind::kThread);
  EXPECT_DOUBLE_EQ(thread.z, -30);
  EXPECT_DOUBLE_EQ(thread.lead, 1.5);
  EXPECT_EQ(thread.state.spindle.dir, SpindleDir::kCcw);
  EXPECT_FALSE(thread.state.spindle.css);
  EXPECT_DOUBLE_EQ(thread.state.spindle.speed, 500);
  EXPECT_DOUBLE_EQ(thread.state.spindle.limit, 0);
  // G33's F is the pitch: the feed is not known again until an F is written.
  EXPECT_FALSE(r.events[5].state.feed_given);
  EXPECT_TRUE(r.events[5].state.coolant.flood);
  EXPECT_DOUBLE_EQ(r.events[5].x, 25);
  EXPECT_EQ(r.events[6].state.feed_mode, FeedMode::kPerMinute);
  EXPECT_DOUBLE_EQ(r.events[6].state.feed, 100);
  EXPECT_DOUBLE_EQ(r.events[6].x, 26);
}

std::string program(const std::string& body) {
  return "%1.nc\nMACHINING\nN 10 T1\nN 20 G97 S800 M3\nN 30 G0 X20. Z2.\n" + body +
         "N 900 M30\nEND\n";
}

TEST(OracleHeidenhainReader, BlockDeleteSkipsTheOptionalBlocks) {
  const std::string p = program("/N 40 G1 X10. G94 F100.\nN 50 G1 X12. G95 F0.1\n");
  EXPECT_EQ(heidenhain_events(p, false, false).events.size(), 3u);
  const ControlRun on = heidenhain_events(p, true, false);
  ASSERT_EQ(on.error, "");
  ASSERT_EQ(on.events.size(), 2u);
  EXPECT_DOUBLE_EQ(on.events[1].x, 6);
}

// G26 caps a constant speed as well as a constant cutting speed: G97 S3000 under G26 S1500
// turns at 1500 rev/min (MANUALplus 4110, 1.5).
TEST(OracleHeidenhainReader, TheSpeedLimitCapsAConstantSpeed) {
  const ControlRun r = heidenhain_events(
      program("N 40 G26 S1500\nN 50 G97 S3000 M3\nN 60 G0 X30.\nN 70 G26 S3000\nN 80 X40.\n"),
      false, false);
  ASSERT_EQ(r.error, "");
  ASSERT_EQ(r.events.size(), 3u);
  EXPECT_DOUBLE_EQ(r.events[0].state.spindle.speed, 800);
  EXPECT_DOUBLE_EQ(r.events[1].state.spindle.speed, 1500);
  EXPECT_DOUBLE_EQ(r.events[2].state.spindle.speed, 3000);
}

// "[INCH]" is a comment: a program is read in its one unit, control parameter 1's.
TEST(OracleHeidenhainReader, TheUnitIsTheControlsParameter) {
  const std::string p = program("[INCH]\nN 40 G0 X1. Z-1.\n");
  const ControlRun mm = heidenhain_events(p, false, false);
  ASSERT_EQ(mm.error, "");
  EXPECT_DOUBLE_EQ(mm.events[1].x, 0.5);
  const ControlRun in = heidenhain_events(p, false, true);
  EXPECT_DOUBLE_EQ(in.events[1].x, 12.7);
  EXPECT_DOUBLE_EQ(in.events[1].z, -25.4);
  const ControlRun unknown = heidenhain_events(p, false, std::nullopt);
  EXPECT_EQ(unknown.error, "no UNIT in a PROGRAM HEAD: the unit is control parameter 1");
  EXPECT_EQ(unknown.error_line, 3);
}

// What the manuals leave to a parameter, or do not say, stops the run at its line.
TEST(OracleHeidenhainReader, RefusesWhatIsNotDocumented) {
  auto error = [](const std::string& p) { return heidenhain_events(p, false, false).error; };
  EXPECT_EQ(error(program("N 40 G96 S200 M3\n")),
            "G96 before G26 (its limit is a machine parameter)");
  EXPECT_EQ(error(program("N 40 G1 X10.\n")),
            "a feed move before F, G94 or G95 (or after G33's F)");
  EXPECT_EQ(error(program("N 40 G1 X10. G95 F0.1\nN 50 G33 Z-10. F1.\nN 60 G1 X12.\n")),
            "a feed move before F, G94 or G95 (or after G33's F)");
  EXPECT_EQ(error(program("N 40 G31 F1.5 U0.92 IC6 V0 H0\n")),
            "address U is not read by the oracle");
  EXPECT_EQ(error(program("N 40 G2 X30. Z0. I5. G95 F0.1\n")), "an arc without both I and K");
  EXPECT_EQ(error(program("N 40 M5\nN 50 G33 Z-10. F1.\n")), "G33 with the spindle stopped");
  EXPECT_EQ(error(program("N 40 G1 X30. M8 G95 F0.1\n")), "an M function in a block that moves");
  EXPECT_EQ(error("%1.nc\nN 10 G0 X10. Z0.\nMACHINING\nEND\n"),
            "a block outside the MACHINING section");
  EXPECT_EQ(error("%1.nc\nMACHINING\nN 10 G0 X10. Z0.\n"), "the program has no END");
  EXPECT_EQ(error("%1.nc\nBLANK\nN 1 G20 X80 Z100 K2\n"),
            "section BLANK is not read by the oracle");
}

}  // namespace
}  // namespace oracle

// The oracle's reader of SINUMERIK programs on small hand-written programs, each event's numbers
// computed by hand (mm, X a radius), and the refusals where the meaning is machine data or
// setting data (sinumerik_reader.cc names each source).
#include <gtest/gtest.h>

#include "compare.h"
#include "model.h"
#include "sinumerik_reader.h"

namespace oracle {
namespace {

constexpr const char* kProgram =
    "N10 G18 G710 G40 G90 DIAMON\n; a comment\nN20 T3 D12\nN30 LIMS=2500\nN40 G96 S200 M3\n"
    "N50 G0 X40 Z5\nN60 G1 Z-10 F0.2\nN70 G2 X44 Z-12 I2 K0\nN80 G4 F1.5\nN90 G700\n"
    "N100 G96 S656\nN110 G1 X2.4 Z-0.6 F0.007874\nN120 G97 S500 LIMS=4000 M4\n"
    "N130 G33 Z-1 K0.05\nN140 M8\nN150 G0 X4 Z-1\nN160 M30\n";

TEST(OracleSinumerikReader, AProgramBecomesEvents) {
  const ControlRun r = sinumerik_events(kProgram, false);
  ASSERT_EQ(r.error, "");
  ASSERT_EQ(r.events.size(), 7u);
  const Event& rapid = r.events[0];
  EXPECT_EQ(rapid.motion, MotionKind::kRapid);
  EXPECT_DOUBLE_EQ(rapid.x, 20);  // X40 under DIAMON is a diameter; no decimal point needed
  EXPECT_DOUBLE_EQ(rapid.z, 5);
  EXPECT_EQ(rapid.state.tool, 3);
  EXPECT_EQ(rapid.state.offset, 12);
  EXPECT_TRUE(rapid.state.spindle.on && rapid.state.spindle.css);
  EXPECT_DOUBLE_EQ(rapid.state.spindle.speed, 200);
  EXPECT_DOUBLE_EQ(rapid.state.spindle.limit, 2500);
  // G96 is feed per revolution (group 15): F0.2 is 0.2 mm/rev.
  EXPECT_EQ(r.events[1].state.feed_mode, FeedMode::kPerRev);
  EXPECT_DOUBLE_EQ(r.events[1].state.feed, 0.2);
  const Event& arc = r.events[2];  // from X20 Z-10: I2 a radius, the centre at X22 Z-10
  EXPECT_EQ(arc.motion, MotionKind::kArc);
  EXPECT_EQ(arc.rotation, -1);
  EXPECT_DOUBLE_EQ(arc.cx, 22);
  EXPECT_DOUBLE_EQ(arc.cz, -10);
  EXPECT_DOUBLE_EQ(r.events[3].seconds, 1.5);  // G4 F: seconds, and F0.2 stays
  // After G700: X2.4 a 1.2 in radius, F0.007874 in/rev, S656 ft/min (199.9488 m/min).
  const Event& inch = r.events[4];
  EXPECT_NEAR(inch.x, 30.48, 1e-9);
  EXPECT_NEAR(inch.z, -15.24, 1e-9);
  EXPECT_NEAR(inch.state.feed, 0.2, 1e-4);
  EXPECT_NEAR(inch.state.spindle.speed, 199.9488, 1e-9);
  const Event& thread = r.events[5];  // G33 K: the lead in the unit in force, 0.05 in
  EXPECT_EQ(thread.motion, MotionKind::kThread);
  EXPECT_NEAR(thread.z, -25.4, 1e-9);
  EXPECT_NEAR(thread.lead, 1.27, 1e-9);
  EXPECT_EQ(thread.state.spindle.dir, SpindleDir::kCcw);
  EXPECT_FALSE(thread.state.spindle.css);
  EXPECT_DOUBLE_EQ(thread.state.spindle.speed, 500);
  // G97 keeps feed per revolution: F stays; K is no feed.
  EXPECT_NEAR(r.events[6].state.feed, 0.2, 1e-4);
  EXPECT_TRUE(r.events[6].state.coolant.flood);
}

std::string program(const std::string& body) {
  return "N10 G18 G710 G40 G90 DIAMON\nN20 T1 D1\nN30 G97 S800 M3\nN40 G0 X20 Z2\n" + body +
         "M30\n";
}

TEST(OracleSinumerikReader, BlockDeleteSkipsTheOptionalBlocks) {
  const std::string p = program("/N50 G1 X10 G94 F100\nN60 G1 X12 G95 F0.1\n");
  EXPECT_EQ(sinumerik_events(p, false).events.size(), 3u);
  const ControlRun on = sinumerik_events(p, true);
  ASSERT_EQ(on.events.size(), 2u);
  EXPECT_DOUBLE_EQ(on.events[1].x, 6);
}

// Group 15: the feed type and the spindle mode are one G group.
TEST(OracleSinumerikReader, FeedTypeAndSpindleModeAreOneGroup) {
  // G96 after G94 switches to feed per revolution and deletes F (alarm 10860 at the next feed).
  EXPECT_EQ(
      sinumerik_events(program("G1 X10 G94 F100\nLIMS=3000\nG96 S200\nG1 X12\n"), false).error,
      "a feed move without an F in its unit and a feed type (alarm 10860)");
  // G961 keeps feed per minute: F100 mm/min stays, at constant cutting speed.
  const ControlRun keep =
      sinumerik_events(program("G1 X10 G94 F100\nLIMS=3000\nG961 S200\nG1 X12\n"), false);
  ASSERT_EQ(keep.error, "");
  EXPECT_EQ(keep.events[2].state.feed_mode, FeedMode::kPerMinute);
  EXPECT_DOUBLE_EQ(keep.events[2].state.feed, 100);
  EXPECT_TRUE(keep.events[2].state.spindle.css);
  // G94 ends constant cutting speed; without an S the speed is one the program does not say.
  const ControlRun ends =
      sinumerik_events(program("LIMS=3000\nG96 S200\nG1 X10 F0.1\nG1 X12 G94 F100\n"), false);
  ASSERT_EQ(ends.error, "");
  EXPECT_FALSE(ends.events[2].state.spindle.css);
  EXPECT_DOUBLE_EQ(ends.events[2].state.spindle.speed, -1);
  // G97 in a feed-per-minute program is feed per revolution: F deleted.
  EXPECT_EQ(sinumerik_events(program("G1 X10 G94 F100\nG97 S900\nG1 X12\n"), false).error,
            "a feed move without an F in its unit and a feed type (alarm 10860)");
}

// LIMS limits G97's speed too: S2640 turns at 800 after LIMS=800.
TEST(OracleSinumerikReader, LimsLimitsG97) {
  const ControlRun r = sinumerik_events(
      program("LIMS=800\nG96 S150\nG1 X10 F0.1\nG97 S2640\nG1 X12\nG97 S2640 LIMS=4000\nX14\n"),
      false);
  ASSERT_EQ(r.error, "");
  ASSERT_EQ(r.events.size(), 4u);
  EXPECT_DOUBLE_EQ(r.events[1].state.spindle.limit, 800);
  EXPECT_DOUBLE_EQ(r.events[2].state.spindle.speed, 800);
  EXPECT_DOUBLE_EQ(r.events[3].state.spindle.speed, 2640);
}

// G4 S: spindle revolutions, at S600: 3 revolutions are 0.3 s; the S of the G4 block is no speed.
TEST(OracleSinumerikReader, DwellInSecondsAndRevolutions) {
  const ControlRun r = sinumerik_events(program("G97 S600\nG4 S3\nG4 F2\nG0 X30\n"), false);
  ASSERT_EQ(r.error, "");
  ASSERT_EQ(r.events.size(), 4u);
  EXPECT_DOUBLE_EQ(r.events[1].seconds, 0.3);
  EXPECT_DOUBLE_EQ(r.events[2].seconds, 2);
  EXPECT_DOUBLE_EQ(r.events[3].state.spindle.speed, 600);
  EXPECT_EQ(sinumerik_events(program("G4 F2 M8\n"), false).error,
            "G4 with other words than one F or S");
}

// What is machine data or setting data is refused, not guessed.
TEST(OracleSinumerikReader, MachineDataMeaningsAreRefused) {
  EXPECT_EQ(sinumerik_events("N10 G18 G71 G40 G90 DIAMON\nG1 X10 Z0 G95 F0.1\n", false).error,
            "F under G70 or G71 (read in the basic system, MD10240)");
  EXPECT_EQ(sinumerik_events("N10 G18 G40 G90 DIAMON\nG0 X10 Z0\n", false).error,
            "a length before G70, G71, G700 or G710 (the basic system is MD10240)");
  EXPECT_EQ(sinumerik_events("N10 G18 G710 G40 G90\nG0 X10 Z0\n", false).error,
            "X before DIAMON, DIAM90 or DIAMOF (MD20150)");
  EXPECT_EQ(sinumerik_events(program("T2\n"), false).error,
            "T without D (the edge is MD20270 CUTTING_EDGE_DEFAULT)");
  EXPECT_EQ(sinumerik_events(program("G1 X10 G95 F0.1 M8\n"), false).error,
            "an M code in a block that moves (MD22200)");
  EXPECT_EQ(sinumerik_events(program("G1 X10\n"), false).error,
            "a feed move without an F in its unit and a feed type (alarm 10860)");
  EXPECT_EQ(sinumerik_events(program("M5\nG33 Z-5 K1\n"), false).error,
            "G33 with the spindle stopped");
  EXPECT_EQ(sinumerik_events(program("G41 X10\n"), false).error, "G41 is not read by the oracle");
  EXPECT_EQ(sinumerik_events(program("G96 S200\nG0 X30\n"), false).error,
            "constant cutting speed without LIMS (the limit is SD43230)");
  EXPECT_EQ(sinumerik_events(program("CYCLE99(0, 20, -30, 20, 2, 2, 1.2, 0, 30, 0, 5, 1, 2, "
                                     "300103, 1, 0, 0, 0, 0, 0, 0, 0, 1, \"\", \"\", \"\", 0)\n"),
                             false)
                .error,
            "CYCLE99(…) (a call) is not read");
  // An F given before a switch of units is not read in the new one.
  EXPECT_EQ(sinumerik_events(program("G1 X10 G95 F0.1\nG700\nX1\n"), false).error,
            "a feed move without an F in its unit and a feed type (alarm 10860)");
}

// The reader against the model: the right program matches, a wrong word differs.
TEST(OracleSinumerikReader, AWrongProgramDiffers) {
  const ModelResult m = model_events(
      "UNITS/MM\nLOADTL/1\nSPINDL/800,RPM,CLW\nFEDRAT/0.1,MMPR\nRAPID\nGOTO/10,0,2\n"
      "CIRCLE/10,0,-3,0,1,0,5\nGOTO/15,0,-3\nFINI\n");
  ASSERT_EQ(m.error, "");
  const std::string right = program("G3 X30 Z-3 I0 K-5 G95 F0.1\n");
  const Resolution res{0.001, 0.0001};
  EXPECT_FALSE(
      compare_events(m.events, sinumerik_events(right, false).events, false, res).first.found);
  const std::pair<const char*, const char*> wrong[] = {{"G3 X30", "G2 X30"},
                                                       {"G95 F0.1", "G94 F0.1"},
                                                       {"T1 D1", "T1 D2"},
                                                       {"S800", "S880"},
                                                       {"DIAMON", "DIAMOF"}};
  for (const auto& [from, to] : wrong) {
    std::string w = right;
    w.replace(w.find(from), std::string(from).size(), to);
    EXPECT_TRUE(compare_events(m.events, sinumerik_events(w, false).events, false, res).first.found)
        << to;
  }
}

}  // namespace
}  // namespace oracle

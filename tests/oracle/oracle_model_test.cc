// The model on hand-written CL, each expected event worked out by hand from docs/cl-meaning.md.
#include <gtest/gtest.h>

#include "cl_text.h"
#include "model.h"

namespace oracle {
namespace {

std::vector<Event> events_of(const std::string& cl) {
  ModelResult r = model_events(cl);
  EXPECT_EQ(r.error, "");
  return r.events;
}

void expect_move(const Event& e, MotionKind kind, double x, double z) {
  EXPECT_EQ(e.kind, Event::Kind::kMotion) << e.source;
  EXPECT_EQ(e.motion, kind) << e.source;
  EXPECT_NEAR(e.x, x, 1e-9) << e.source;
  EXPECT_NEAR(e.z, z, 1e-9) << e.source;
}

void expect_feed(const Event& e, double feed, FeedMode mode) {
  EXPECT_TRUE(e.state.feed_given) << e.source;
  EXPECT_NEAR(e.state.feed, feed, 1e-9) << e.source;
  EXPECT_EQ(e.state.feed_mode, mode) << e.source;
}

TEST(OracleReader, StatementsWordsAndContinuation) {
  std::vector<ClStatement> s =
      read_cl("$$ a comment\nfedrat / 0.2 , mmpr\nGOTO/1,$\n 0,2 $$ tail\nRAPID\nPPRINT/A, B\n");
  ASSERT_EQ(s.size(), 4u);
  EXPECT_EQ(s[0].major, "FEDRAT");
  EXPECT_EQ(s[0].line, 2);
  EXPECT_DOUBLE_EQ(s[0].number(0), 0.2);
  EXPECT_EQ(s[0].find("MMPR"), 1);
  EXPECT_EQ(s[1].major, "GOTO");
  EXPECT_EQ(s[1].line, 3);
  ASSERT_EQ(s[1].args.size(), 3u);
  EXPECT_DOUBLE_EQ(s[1].number(2), 2);
  EXPECT_EQ(s[2].major, "RAPID");
  EXPECT_TRUE(s[2].args.empty());
  EXPECT_EQ(s[3].major, "PPRINT");
  EXPECT_TRUE(s[3].args.empty());
}

// 0.2 mm/rev stays 0.2 mm/rev after UNITS/INCHES; later numbers are inches (X0.5 = 12.7 mm); a
// FEDRAT without a mode word is in inches per revolution then (0.01 in = 0.254 mm).
TEST(OracleModel, UnitsSwitchReadsLaterNumbersAndKeepsTheFeed) {
  std::vector<Event> e = events_of(
      "UNITS/MM\nFEDRAT/0.2,MMPR\nGOTO/10,0,0\nUNITS/INCHES\nGOTO/0.5,0,-1\nFEDRAT/0.01\n"
      "GOTO/0.6,0,-1\nUNITS/MM\nGOTO/10,0,-20\nFINI\n");
  ASSERT_EQ(e.size(), 4u);
  expect_move(e[0], MotionKind::kFeed, 10, 0);
  expect_feed(e[0], 0.2, FeedMode::kPerRev);
  expect_move(e[1], MotionKind::kFeed, 12.7, -25.4);
  expect_feed(e[1], 0.2, FeedMode::kPerRev);
  EXPECT_TRUE(e[1].why.units_since_feed);
  expect_move(e[2], MotionKind::kFeed, 15.24, -25.4);
  expect_feed(e[2], 0.254, FeedMode::kPerRev);
  EXPECT_TRUE(e[2].why.feed_without_mode);
  expect_move(e[3], MotionKind::kFeed, 10, -20);
  expect_feed(e[3], 0.254, FeedMode::kPerRev);
}

TEST(OracleModel, FedratWithoutModeKeepsTheMode) {
  std::vector<Event> e = events_of(
      "FEDRAT/100\nGOTO/5,0,0\nFEDRAT/IPR,0.01\nGOTO/6,0,0\nFEDRAT/0.3\nGOTO/7,0,0\n"
      "FEDRAT/50,MMPM\nFEDRAT/80\nGOTO/8,0,0\nFEDRAT/2,IPM\nGOTO/9,0,0\nFINI\n");
  ASSERT_EQ(e.size(), 5u);
  expect_feed(e[0], 100, FeedMode::kPerMinute);  // per minute before any mode word
  expect_feed(e[1], 0.254, FeedMode::kPerRev);
  expect_feed(e[2], 0.3, FeedMode::kPerRev);
  expect_feed(e[3], 80, FeedMode::kPerMinute);
  expect_feed(e[4], 50.8, FeedMode::kPerMinute);
}

TEST(OracleModel, SpindleOffThenOnRestoresCssAndLimit) {
  std::vector<Event> e = events_of(
      "SPINDL/200,SMM,MAXRPM,2500,CCLW\nRAPID\nGOTO/20,0,5\nSPINDL/OFF\nRAPID\nGOTO/20,0,10\n"
      "SPINDL/ON\nRAPID\nGOTO/20,0,5\nSPINDL/800,RPM\nRAPID\nGOTO/21,0,5\nFINI\n");
  ASSERT_EQ(e.size(), 4u);
  const Spindle& a = e[0].state.spindle;
  EXPECT_TRUE(a.on && a.css);
  EXPECT_EQ(a.dir, SpindleDir::kCcw);
  EXPECT_DOUBLE_EQ(a.speed, 200);
  EXPECT_DOUBLE_EQ(a.limit, 2500);
  EXPECT_FALSE(e[1].state.spindle.on);
  const Spindle& c = e[2].state.spindle;
  EXPECT_TRUE(c.on && c.css);
  EXPECT_EQ(c.dir, SpindleDir::kCcw);
  EXPECT_DOUBLE_EQ(c.speed, 200);
  EXPECT_DOUBLE_EQ(c.limit, 2500);
  EXPECT_TRUE(e[2].why.spindle_by_on);
  const Spindle& d = e[3].state.spindle;  // RPM, the direction kept
  EXPECT_TRUE(d.on && !d.css);
  EXPECT_EQ(d.dir, SpindleDir::kCcw);
  EXPECT_DOUBLE_EQ(d.speed, 800);
  EXPECT_DOUBLE_EQ(d.limit, 0);
}

TEST(OracleModel, MaxrpmStaysUntilChanged) {
  std::vector<Event> e = events_of(
      "SPINDL/150,SMM,CLW\nRAPID\nGOTO/10,0,0\nSPINDL/180,SMM,MAXRPM,2000\nRAPID\nGOTO/11,0,0\n"
      "SPINDL/900,RPM\nSPINDL/160,SMM\nRAPID\nGOTO/12,0,0\nUNITS/INCHES\nSPINDL/500,SFM\n"
      "RAPID\nGOTO/0.5,0,0\nFINI\n");
  ASSERT_EQ(e.size(), 4u);
  EXPECT_DOUBLE_EQ(e[0].state.spindle.limit, 3000);  // the machine's limits.max_rpm
  EXPECT_DOUBLE_EQ(e[1].state.spindle.limit, 2000);
  EXPECT_DOUBLE_EQ(e[2].state.spindle.speed, 160);
  EXPECT_DOUBLE_EQ(e[2].state.spindle.limit, 2000);
  EXPECT_TRUE(e[2].why.maxrpm_from_earlier);
  EXPECT_NEAR(e[3].state.spindle.speed, 152.4, 1e-9);  // 500 ft/min
  EXPECT_DOUBLE_EQ(e[3].state.spindle.limit, 2000);
  expect_move(e[3], MotionKind::kRapid, 12.7, 0);
}

TEST(OracleModel, OpskipRangeMarksItsEvents) {
  std::vector<Event> e = events_of(
      "FEDRAT/0.1,MMPR\nSPINDL/500,RPM,CLW\nGOTO/10,0,0\nOPSKIP/ON\nGOTO/12,0,0\nSPINDL/OFF\n"
      "DELAY/1\nOPSKIP/OFF\nGOTO/14,0,-5\nGOTO/15,0,-5\nFINI\n");
  ASSERT_EQ(e.size(), 5u);
  EXPECT_FALSE(e[0].skipped);
  EXPECT_TRUE(e[1].skipped);
  EXPECT_TRUE(e[1].state.spindle.on);
  EXPECT_TRUE(e[2].skipped);
  EXPECT_EQ(e[2].kind, Event::Kind::kDwell);
  EXPECT_DOUBLE_EQ(e[2].seconds, 1);
  EXPECT_FALSE(e[3].skipped);
  EXPECT_TRUE(e[3].why.after_range);
  EXPECT_FALSE(e[3].state.spindle.on);  // the range's SPINDL/OFF holds after it
  expect_move(e[3], MotionKind::kFeed, 14, -5);
  EXPECT_FALSE(e[4].why.after_range);
}

TEST(OracleModel, RapidIsTheNextMotionOnly) {
  std::vector<Event> e = events_of(
      "FEDRAT/100,MMPM\nRAPID\nGOTO/10,0,5\nGOTO/10,0,0\nRAPID\nGODLTA/0,0,-2\nGODLTA/-1\nFINI\n");
  ASSERT_EQ(e.size(), 4u);
  expect_move(e[0], MotionKind::kRapid, 10, 5);
  expect_move(e[1], MotionKind::kFeed, 10, 0);
  expect_move(e[2], MotionKind::kRapid, 10, -2);
  expect_move(e[3], MotionKind::kFeed, 10, -3);
}

TEST(OracleModel, GohomeConsumesRapid) {
  std::vector<Event> e = events_of(
      "FEDRAT/100,MMPM\nGOTO/10,0,0\nRAPID\nGOHOME/50,0,100\nGOTO/40,0,50\nGOHOME/60,0,100\n"
      "FINI\n");
  ASSERT_EQ(e.size(), 4u);
  expect_move(e[1], MotionKind::kRapid, 50, 100);
  expect_move(e[2], MotionKind::kFeed, 40, 50);
  expect_move(e[3], MotionKind::kRapid, 60, 100);
  EXPECT_FALSE(model_events("GOHOME\nFINI\n").error.empty());  // the machine's home: not modelled
}

// Axis -Y: clockwise in (Z, X) seen from +Y (G2); +Y counter-clockwise (G3).
TEST(OracleModel, CircleIsTheNextGotoOnly) {
  std::vector<Event> e = events_of(
      "FEDRAT/0.1,MMPR\nGOTO/15,0,-20\nCIRCLE/17,0,-20,0,-1,0,2\nGOTO/17,0,-22\nGOTO/17,0,-30\n"
      "CIRCLE/19,0,-30,0,1,0,2\nFEDRAT/0.05,MMPR\nGOTO/19,0,-32\nFINI\n");
  ASSERT_EQ(e.size(), 4u);
  expect_move(e[1], MotionKind::kArc, 17, -22);
  EXPECT_DOUBLE_EQ(e[1].cx, 17);
  EXPECT_DOUBLE_EQ(e[1].cz, -20);
  EXPECT_EQ(e[1].rotation, -1);
  expect_move(e[2], MotionKind::kFeed, 17, -30);
  expect_move(e[3], MotionKind::kArc, 19, -32);
  EXPECT_EQ(e[3].rotation, 1);
  expect_feed(e[3], 0.05, FeedMode::kPerRev);
}

TEST(OracleModel, LoadtlAdjustGivesTheOffset) {
  std::vector<Event> e = events_of(
      "LOADTL/3\nRAPID\nGOTO/10,0,0\nLOADTL/4,ADJUST,12\nRAPID\nGOTO/11,0,0\n"
      "TURRET/5,OSETNO,7\nRAPID\nGOTO/12,0,0\nFINI\n");
  ASSERT_EQ(e.size(), 3u);
  EXPECT_EQ(e[0].state.tool, 3);
  EXPECT_EQ(e[0].state.offset, 3);
  EXPECT_EQ(e[1].state.tool, 4);
  EXPECT_EQ(e[1].state.offset, 12);
  EXPECT_EQ(e[2].state.tool, 5);
  EXPECT_EQ(e[2].state.offset, 7);
}

// At 600 rev/min a revolution takes 0.1 s.
TEST(OracleModel, DelayInSecondsAndRevolutions) {
  std::vector<Event> e =
      events_of("SPINDL/600,RPM,CLW\nDELAY/1.5\nDELAY/REV,3\nDELAY/6,REV\nDELAY/2,SEC\nFINI\n");
  ASSERT_EQ(e.size(), 4u);
  EXPECT_DOUBLE_EQ(e[0].seconds, 1.5);
  EXPECT_DOUBLE_EQ(e[1].seconds, 0.3);
  EXPECT_DOUBLE_EQ(e[2].seconds, 0.6);
  EXPECT_DOUBLE_EQ(e[3].seconds, 2);
  EXPECT_FALSE(model_events("SPINDL/100,SMM\nDELAY/REV,3\nFINI\n").error.empty());
}

TEST(OracleModel, ThreadTurnCutsTheSecondGoto) {
  std::vector<Event> e = events_of(
      "SPINDL/500,RPM,CLW\nFEDRAT/0.2,MMPR\nPITCH/1.5,MMPR\nTHREAD/TURN\nRAPID\nGOTO/10,0,3\n"
      "GOTO/10,0,-20\nRAPID\nGOTO/12,0,-20\nUNITS/INCHES\nTHREAD/TURN,0.05\nGOTO/0.4,0,0.1\n"
      "GOTO/0.4,0,-0.5\nTHREAD/TURN\nGOTO/0.4,0,0.1\nGOTO/0.4,0,-0.6\nFINI\n");
  ASSERT_EQ(e.size(), 7u);
  expect_move(e[0], MotionKind::kRapid, 10, 3);
  expect_move(e[1], MotionKind::kThread, 10, -20);
  EXPECT_DOUBLE_EQ(e[1].lead, 1.5);
  expect_move(e[2], MotionKind::kRapid, 12, -20);
  expect_move(e[3], MotionKind::kFeed, 10.16, 2.54);
  expect_feed(e[3], 0.2, FeedMode::kPerRev);
  expect_move(e[4], MotionKind::kThread, 10.16, -12.7);
  EXPECT_NEAR(e[4].lead, 1.27, 1e-12);
  EXPECT_NEAR(e[6].lead, 1.5, 1e-12);  // PITCH/1.5,MMPR before the switch: still 1.5 mm
}

// COUPLE/ON … COUPLE/OFF: every GOTO between one thread cut in a row, at COUPLE/ON's own pitch
// (16 TPI: 25.4/16 = 1.5875 mm) or the modal one; after COUPLE/OFF a GOTO is a feed again.
TEST(OracleModel, CoupleCutsEveryGoto) {
  std::vector<Event> e = events_of(
      "SPINDL/500,RPM,CLW\nFEDRAT/0.2,MMPR\nPITCH/1.5,MMPR\nRAPID\nGOTO/10,0,3\nCOUPLE/ON\n"
      "GOTO/10,0,-20\nGOTO/11.5,0,-21.5\nCOUPLE/OFF\nGOTO/14,0,-21.5\nCOUPLE/ON,TPI,16\n"
      "GOTO/14,0,-30\nCOUPLE/OFF\nFINI\n");
  ASSERT_EQ(e.size(), 5u);
  expect_move(e[1], MotionKind::kThread, 10, -20);
  expect_move(e[2], MotionKind::kThread, 11.5, -21.5);
  EXPECT_DOUBLE_EQ(e[2].lead, 1.5);
  expect_move(e[3], MotionKind::kFeed, 14, -21.5);
  expect_move(e[4], MotionKind::kThread, 14, -30);
  EXPECT_DOUBLE_EQ(e[4].lead, 1.5875);
  EXPECT_NE(model_events("SPINDL/500,RPM\nPITCH/1.5,MMPR\nGOTO/10,0,3\nCOUPLE/ON\nRAPID\n"
                         "GOTO/10,0,-20\nFINI\n")
                .error,
            "");
}

TEST(OracleModel, GodltaAndFromArePositions) {
  std::vector<Event> e =
      events_of("FROM/10,0,5\nFEDRAT/100,MMPM\nGODLTA/2,0,-3\nGODLTA/-4\nFINI\n");
  ASSERT_EQ(e.size(), 2u);
  expect_move(e[0], MotionKind::kFeed, 12, 2);
  expect_move(e[1], MotionKind::kFeed, 12, -2);
}

TEST(OracleModel, CoolantIsTheOneNamed) {
  std::vector<Event> e = events_of(
      "FEDRAT/100,MMPM\nCOOLNT/ON\nGOTO/1,0,0\nCOOLNT/MIST\nGOTO/2,0,0\nCOOLNT/FLOOD\n"
      "GOTO/3,0,0\nCOOLNT/OFF\nGOTO/4,0,0\nFINI\n");
  ASSERT_EQ(e.size(), 4u);
  EXPECT_TRUE(e[0].state.coolant.flood && !e[0].state.coolant.mist);
  EXPECT_TRUE(!e[1].state.coolant.flood && e[1].state.coolant.mist);
  EXPECT_TRUE(e[2].state.coolant.flood && !e[2].state.coolant.mist);
  EXPECT_TRUE(!e[3].state.coolant.flood && !e[3].state.coolant.mist);
}

TEST(OracleModel, UnknownStatementsAreSaid) {
  ModelResult r = model_events("FEDRAT/100,MMPM\nGOTO/1,0,0\nFROB/2\nGOTO/2,0,0\nFINI\n");
  EXPECT_EQ(r.error, "CL line 3: the model does not know FROB (FROB/2)");
  EXPECT_EQ(r.events.size(), 1u);
}

}  // namespace
}  // namespace oracle

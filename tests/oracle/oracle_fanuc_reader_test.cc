// The oracle's reader of Fanuc and Haas programs on small hand-written programs, each event's
// numbers computed by hand (mm, X a radius), and the refusals where the control's meaning is a
// parameter or a setting.
#include <gtest/gtest.h>

#include <cmath>
#include <iterator>

#include "compare.h"
#include "fanuc_reader.h"
#include "model.h"

namespace oracle {
namespace {

constexpr const char* kProgram =
    "%\nO0001\nN10 G18 G21 G40 G97\nN20 T0312\nN30 G50 S2500\nN40 G96 S200 M3\n"
    "N50 G0 X40. Z5.\nN60 G1 Z-10. G99 F0.2\nN70 G2 X44. Z-12. I2. K0.\nN80 G4 X1.5\n"
    "N90 G20\nN100 X2.4 Z-0.6\nN110 G97 S500 M4\nN120 G32 Z-1. F0.05\nN130 M8\n"
    "N140 G0 X4. Z-1.\nN150 M30\n%\n";

TEST(OracleFanucReader, AProgramBecomesEvents) {
  const ControlRun r = fanuc_events(kProgram, Dialect::kFanuc, false);
  ASSERT_EQ(r.error, "");
  ASSERT_EQ(r.events.size(), 7u);
  const Event& rapid = r.events[0];
  EXPECT_EQ(rapid.motion, MotionKind::kRapid);
  EXPECT_DOUBLE_EQ(rapid.x, 20);  // X40. is a diameter
  EXPECT_DOUBLE_EQ(rapid.z, 5);
  EXPECT_EQ(rapid.state.tool, 3);
  EXPECT_EQ(rapid.state.offset, 12);
  EXPECT_TRUE(rapid.state.spindle.on && rapid.state.spindle.css);
  EXPECT_DOUBLE_EQ(rapid.state.spindle.speed, 200);
  EXPECT_DOUBLE_EQ(rapid.state.spindle.limit, 2500);
  EXPECT_EQ(r.events[1].state.feed_mode, FeedMode::kPerRev);
  EXPECT_DOUBLE_EQ(r.events[1].state.feed, 0.2);
  const Event& arc = r.events[2];  // from X20 Z-10: the centre 2 further out in X (I a radius)
  EXPECT_EQ(arc.motion, MotionKind::kArc);
  EXPECT_EQ(arc.rotation, -1);
  EXPECT_DOUBLE_EQ(arc.cx, 22);
  EXPECT_DOUBLE_EQ(arc.cz, -10);
  EXPECT_DOUBLE_EQ(r.events[3].seconds, 1.5);
  // After G20 the numbers are inches: X2.4 a 1.2 in radius; F0.2 and G96 S200 kept, in inches.
  const Event& inch = r.events[4];
  EXPECT_NEAR(inch.x, 30.48, 1e-9);
  EXPECT_NEAR(inch.z, -15.24, 1e-9);
  EXPECT_NEAR(inch.state.feed, 5.08, 1e-9);
  EXPECT_NEAR(inch.state.spindle.speed, 200 * 0.3048, 1e-9);
  const Event& thread = r.events[5];
  EXPECT_EQ(thread.motion, MotionKind::kThread);
  EXPECT_NEAR(thread.z, -25.4, 1e-9);
  EXPECT_NEAR(thread.lead, 1.27, 1e-9);
  EXPECT_EQ(thread.state.spindle.dir, SpindleDir::kCcw);
  EXPECT_FALSE(thread.state.spindle.css);
  EXPECT_DOUBLE_EQ(thread.state.spindle.speed, 500);
  // G32's F is the F in force afterwards: a feed move without F would be at the lead.
  EXPECT_NEAR(r.events[6].state.feed, 1.27, 1e-9);
  EXPECT_TRUE(r.events[6].state.coolant.flood);
}

std::string program(const std::string& body) {
  return "%\nO0001\nN10 G18 G21 G40 G97\nT0101\nG97 S800 M3\nG0 X20. Z2.\n" + body + "M30\n%\n";
}

TEST(OracleFanucReader, BlockDeleteSkipsTheOptionalBlocks) {
  const std::string p = program("/G1 X10. G98 F100.\nG1 X12. G99 F0.1\n");
  EXPECT_EQ(fanuc_events(p, Dialect::kFanuc, false).events.size(), 3u);
  const ControlRun on = fanuc_events(p, Dialect::kFanuc, true);
  ASSERT_EQ(on.events.size(), 2u);
  EXPECT_DOUBLE_EQ(on.events[1].x, 6);
}

// Fanuc: G04 X seconds, P milliseconds without a point; Haas: P, seconds with a point.
TEST(OracleFanucReader, DwellWordsDifferBetweenFanucAndHaas) {
  EXPECT_DOUBLE_EQ(fanuc_events(program("G4 X1.5\n"), Dialect::kFanuc, false).events[1].seconds,
                   1.5);
  EXPECT_DOUBLE_EQ(fanuc_events(program("G4 P1500\n"), Dialect::kFanuc, false).events[1].seconds,
                   1.5);
  EXPECT_EQ(fanuc_events(program("G4 P1.5\n"), Dialect::kFanuc, false).error,
            "G04 P with a decimal point");
  EXPECT_DOUBLE_EQ(fanuc_events(program("G4 P1.5\n"), Dialect::kHaas, false).events[1].seconds,
                   1.5);
  EXPECT_DOUBLE_EQ(fanuc_events(program("G4 P1500\n"), Dialect::kHaas, false).events[1].seconds,
                   1.5);
  EXPECT_EQ(fanuc_events(program("G4 X1.5\n"), Dialect::kHaas, false).error,
            "Haas G04 takes the time in P, not X or U");
}

// G28 U0. then G28 W0.: one return; after it a move must say both axes, and no arc starts there.
TEST(OracleFanucReader, AReferenceReturnLeavesThePositionUnsaid) {
  const ControlRun r =
      fanuc_events(program("G28 U0.\nG28 W0.\nX30. Z1.\n"), Dialect::kFanuc, false);
  ASSERT_EQ(r.error, "");
  ASSERT_EQ(r.events.size(), 3u);
  EXPECT_EQ(r.events[1].home, kHomeX | kHomeZ);
  // X alone: a return the model's GOHOME (every axis) is not.
  EXPECT_EQ(fanuc_events(program("G28 U0.\nX30. Z1.\n"), Dialect::kFanuc, false).events[1].home,
            kHomeX);
  EXPECT_EQ(r.events[2].motion, MotionKind::kRapid);  // G28 is one-shot: G0 stays in force
  const ControlRun z = fanuc_events(program("G28 U0.\nG28 W0.\nZ1.\n"), Dialect::kFanuc, false);
  EXPECT_EQ(z.error, "a move from a reference position the program does not state");
  EXPECT_EQ(z.error_line, 9);
  const ControlRun a =
      fanuc_events(program("G28 U0.\nG3 X30. Z0. I5. K0. G98 F100.\n"), Dialect::kFanuc, false);
  EXPECT_EQ(a.error, "an arc from a reference position the program does not state");
  // Haas: G28 alone returns every axis.
  EXPECT_EQ(fanuc_events(program("G28\nZ1.\n"), Dialect::kHaas, false).error,
            "a move from a reference position the program does not state");
}

// What depends on a parameter or a setting is refused, not guessed.
TEST(OracleFanucReader, ParameterDependentMeaningsAreRefused) {
  EXPECT_EQ(fanuc_events(program("X10\n"), Dialect::kFanuc, false).error,
            "X without a decimal point");
  EXPECT_EQ(fanuc_events(program("G1 X10.\n"), Dialect::kFanuc, false).error,
            "a feed move before F, G98 or G99");
  EXPECT_EQ(fanuc_events("%\nO0001\nT0101\n", Dialect::kFanuc, false).error,
            "a block before G20 or G21 (the power-on unit is a parameter)");
  EXPECT_EQ(fanuc_events(program("M5\nG32 Z-5. F1.\n"), Dialect::kFanuc, false).error,
            "G32 with the spindle stopped");
  EXPECT_EQ(fanuc_events(program("G41 X10.\n"), Dialect::kFanuc, false).error,
            "G41 is not read by the oracle");
  EXPECT_EQ(fanuc_events(program("G1 X10. G98 F100. M8\n"), Dialect::kFanuc, false).error,
            "an M code in a block that moves");
  // A start angle is in 0.001 degree: Q180000, never Q180.
  EXPECT_EQ(fanuc_events(program("G32 Z-5. F1. Q180000\n"), Dialect::kFanuc, false).error, "");
  EXPECT_EQ(fanuc_events(program("G32 Z-5. F1. Q180.\n"), Dialect::kFanuc, false).error,
            "Q with a decimal point");
}

// An arc by R: the centre on the left of the chord for G3 (counter-clockwise in (Z, X)). From
// radius 10 at Z2 to radius 20 at Z-8 with R10: a quarter circle from +Z to +X around (10, -8).
TEST(OracleFanucReader, AnArcByRadius) {
  const ControlRun r =
      fanuc_events(program("G3 X40. Z-8. R10. G98 F100.\n"), Dialect::kFanuc, false);
  ASSERT_EQ(r.error, "");
  const Event& a = r.events[1];
  EXPECT_EQ(a.rotation, 1);
  EXPECT_NEAR(a.cx, 10, 1e-9);
  EXPECT_NEAR(a.cz, -8, 1e-9);
}

// G92: one pass per block from the start point (radius 10 at Z2), X modal Z: rapid in, the thread
// cut, rapid out, rapid back.
TEST(OracleFanucReader, G92CutsOnePassPerBlock) {
  const ControlRun r =
      fanuc_events(program("G92 X16. Z-20. F1.5\nX15. Q180000\n"), Dialect::kFanuc, false);
  ASSERT_EQ(r.error, "");
  ASSERT_EQ(r.events.size(), 9u);
  const double want[8][2] = {{8, 2},   {8, -20},   {10, -20}, {10, 2},
                             {7.5, 2}, {7.5, -20}, {10, -20}, {10, 2}};
  for (int i = 0; i < 8; ++i) {
    const Event& e = r.events[i + 1];
    EXPECT_EQ(e.motion, i % 4 == 1 ? MotionKind::kThread : MotionKind::kRapid) << i;
    EXPECT_DOUBLE_EQ(e.x, want[i][0]) << i;
    EXPECT_DOUBLE_EQ(e.z, want[i][1]) << i;
  }
  EXPECT_DOUBLE_EQ(r.events[2].lead, 1.5);
}

// Fanuc G76 P010060 Q100 R0.05 / X16. Z-20. P1000 Q400: k 1, Δd 0.4, Δdmin 0.1, d 0.05. Depths
// 0.4·√n: 0.4, 0.5657, 0.6928, 0.8; then 0.8944 would add 0.0944 < 0.1: 0.9, then 1.0 past
// k - d: 0.95; then m = 1 pass at 1. Each shifted (1 - depth)·tan 30° toward the start.
TEST(OracleFanucReader, G76ExpandsToItsPasses) {
  const ControlRun r = fanuc_events(
      program("G76 P010060 Q100 R0.05\nG76 X16. Z-20. P1000 Q400 F1.5\n"), Dialect::kFanuc, false);
  ASSERT_EQ(r.error, "");
  const double depths[] = {0.4, 0.4 * std::sqrt(2), 0.4 * std::sqrt(3), 0.8, 0.9, 0.95, 1};
  ASSERT_EQ(r.events.size(), 1 + 4 * std::size(depths));
  for (size_t i = 0; i < std::size(depths); ++i) {
    const Event &in = r.events[1 + 4 * i], &cut = r.events[2 + 4 * i];
    EXPECT_NEAR(in.x, 8 + 1 - depths[i], 1e-9) << i;
    EXPECT_NEAR(in.z, 2 + (1 - depths[i]) * std::tan(M_PI / 6), 1e-9) << i;
    EXPECT_EQ(cut.motion, MotionKind::kThread);
    EXPECT_NEAR(cut.z, -20, 1e-9);
  }
  EXPECT_EQ(fanuc_events(program("G76 P011060 Q100 R0.05\nG76 X16. Z-20. P1000 Q400 F1.5\n"),
                         Dialect::kFanuc, false)
                .error,
            "G76 with a chamfer (where it sits is not documented)");
}

// Haas G76 X16. Z-20. K1. D0.4 P1 (no A: straight in): 0.4·√N below K, then K: 7 passes; P3 with
// D0.3: 0.3, 0.6, 0.9, then 1.
TEST(OracleFanucReader, HaasG76IsOneBlock) {
  const ControlRun r =
      fanuc_events(program("G76 X16. Z-20. K1. D0.4 P1 F1.5\n"), Dialect::kHaas, false);
  ASSERT_EQ(r.error, "");
  ASSERT_EQ(r.events.size(), 1 + 4 * 7u);
  EXPECT_NEAR(r.events[1 + 4 * 5].x, 8 + 1 - 0.4 * std::sqrt(6), 1e-9);
  EXPECT_DOUBLE_EQ(r.events[1 + 4 * 5].z, 2);
  const ControlRun c =
      fanuc_events(program("G76 X16. Z-20. K1. D0.3 P3 F1.5\n"), Dialect::kHaas, false);
  ASSERT_EQ(c.events.size(), 1 + 4 * 4u);
  EXPECT_NEAR(c.events[1 + 4 * 2].x, 8.1, 1e-9);
  EXPECT_EQ(
      fanuc_events(program("G76 X16. Z-20. K1. D0.3 P3 F1.5\n"), Dialect::kFanuc, false).error,
      "address D is not read");
}

// The reader against the model: the right program matches, a wrong word differs.
TEST(OracleFanucReader, AWrongProgramDiffers) {
  const ModelResult m = model_events(
      "UNITS/MM\nLOADTL/1\nSPINDL/800,RPM,CLW\nFEDRAT/0.1,MMPR\nRAPID\nGOTO/10,0,2\n"
      "CIRCLE/10,0,-3,0,1,0,5\nGOTO/15,0,-3\nFINI\n");
  ASSERT_EQ(m.error, "");
  const std::string right = program("G3 X30. Z-3. I0. K-5. G99 F0.1\n");
  const Resolution res{0.001, 0.0001};
  EXPECT_FALSE(
      compare_events(m.events, fanuc_events(right, Dialect::kFanuc, false).events, false, res)
          .first.found);
  const std::pair<const char*, const char*> wrong[] = {
      {"G3 X30.", "G2 X30."}, {"G99 F0.1", "G98 F0.1"}, {"T0101", "T0102"}, {"S800", "S880"}};
  for (const auto& [from, to] : wrong) {
    std::string w = right;
    w.replace(w.find(from), std::string(from).size(), to);
    EXPECT_TRUE(compare_events(m.events, fanuc_events(w, Dialect::kFanuc, false).events, false, res)
                    .first.found)
        << to;
  }
}

}  // namespace
}  // namespace oracle

#include "simulator/control_sim.h"

#include <gtest/gtest.h>

#include <cmath>
#include <numbers>

#include "simulator/sim_test_util.h"

namespace clpost {
namespace {

using testing::shipped;

struct SimRun {
  bool ok = false;
  Simulation sim;
  std::string diagnostics;
};

SimRun run(const Machine& m, std::string_view program) {
  SimRun r;
  Diagnostics d("p.nc");
  reader::LineSource src(program);
  r.ok = simulate_nc(src, m, d, r.sim);
  r.diagnostics = d.render_all();
  return r;
}

constexpr double kEps = 1e-9;

TEST(ControlSim, G33WithAChainedPullOutIsOneCut) {
  SimRun r = run(shipped("generic-lathe"),
                 "%\nG21\nG0 X20 Z5\nG1 X15.08 Z2 F0.2\nG33 Z-20 F1.5\nG33 X18 Z-21.5\nG0 X20\n");
  ASSERT_TRUE(r.ok) << r.diagnostics;
  ASSERT_EQ(r.sim.cuts.size(), 1u);
  const NcCut& c = r.sim.cuts[0];
  EXPECT_NEAR(c.from.x, 7.54, kEps);  // X is a diameter
  EXPECT_NEAR(c.from.z, 2, kEps);
  EXPECT_NEAR(c.to.x, 7.54, kEps);
  EXPECT_NEAR(c.to.z, -20, kEps);
  EXPECT_NEAR(c.end.x, 9, kEps);
  EXPECT_NEAR(c.end.z, -21.5, kEps);
  EXPECT_EQ(c.chain.size(), 2u);
  EXPECT_DOUBLE_EQ(c.lead, 1.5);
  EXPECT_EQ(c.line, 5u);
  EXPECT_EQ(c.source, "G33");
  // Moves: G1, G33, G33, G0 (the first G0 starts from nowhere known: not a move).
  ASSERT_EQ(r.sim.path.moves.size(), 4u);
  EXPECT_EQ(r.sim.path.moves[0].kind, MoveKind::kFeed);
  EXPECT_NEAR(r.sim.path.moves[0].from.x, 10, kEps);
  EXPECT_EQ(r.sim.path.moves[2].kind, MoveKind::kThread);
  EXPECT_NEAR(r.sim.path.moves[3].to.x, 10, kEps);
  EXPECT_NEAR(r.sim.path.moves[3].to.z, -21.5, kEps);
}

TEST(ControlSim, TheFeedAfterAThreadIsItsLinearPullOut) {
  SimRun r = run(shipped("generic-lathe"), "G0 X15.08 Z2\nG33 Z-20 F1.5\nG1 X17.48 F0.2\nG0 X20\n");
  ASSERT_TRUE(r.ok) << r.diagnostics;
  ASSERT_EQ(r.sim.cuts.size(), 1u);
  ASSERT_TRUE(r.sim.cuts[0].linear_pullout.has_value());
  EXPECT_NEAR(r.sim.cuts[0].linear_pullout->x, 8.74, kEps);
  EXPECT_NEAR(r.sim.cuts[0].end.x, 7.54, kEps);
}

TEST(ControlSim, ArcsTakeTheirCentreFromIAndKAsRadii) {
  SimRun r = run(shipped("generic-lathe"), "G0 X10 Z0\nG2 X14 Z-2 I0 K-2 F0.1\n");
  ASSERT_TRUE(r.ok) << r.diagnostics;
  ASSERT_EQ(r.sim.path.moves.size(), 1u);
  const Move& a = r.sim.path.moves[0];
  EXPECT_EQ(a.kind, MoveKind::kArcCw);
  EXPECT_NEAR(a.center.x, 5, kEps);
  EXPECT_NEAR(a.center.z, -2, kEps);
  EXPECT_NEAR(a.to.x, 7, kEps);
}

TEST(ControlSim, SiemensLeadKStartAngleSfAndInch) {
  SimRun r = run(shipped("sinumerik-840d"),
                 "N10 G18 G700 G40 G90 DIAMON\nN20 G0 X1 Z0.2\nN30 G33 Z-1 K0.0625 SF=180\n");
  ASSERT_TRUE(r.ok) << r.diagnostics;
  EXPECT_EQ(r.sim.units, LengthUnit::kInch);
  ASSERT_EQ(r.sim.cuts.size(), 1u);
  EXPECT_DOUBLE_EQ(r.sim.cuts[0].lead, 0.0625);
  ASSERT_TRUE(r.sim.cuts[0].start_angle.has_value());
  EXPECT_DOUBLE_EQ(*r.sim.cuts[0].start_angle, 180);
}

TEST(ControlSim, FanucG92RepeatsWithItsModalWordsAndQInThousandths) {
  SimRun r = run(shipped("fanuc-0i-t"),
                 "N10 G0 X18.598 Z2.\nN20 G92 X15.387 Z-20. F1.5 Q0\nN30 X14.896 Q180000\n"
                 "N40 G0 X20. Z5.\n");
  ASSERT_TRUE(r.ok) << r.diagnostics;
  ASSERT_EQ(r.sim.cuts.size(), 2u);
  const NcCut& a = r.sim.cuts[0];
  const NcCut& b = r.sim.cuts[1];
  EXPECT_NEAR(a.from.x, 7.6935, kEps);
  EXPECT_NEAR(a.from.z, 2, kEps);
  EXPECT_NEAR(a.to.z, -20, kEps);
  EXPECT_DOUBLE_EQ(*a.start_angle, 0);
  EXPECT_NEAR(b.from.x, 7.448, kEps);  // X14.896 with Z and F from the G92 block
  EXPECT_NEAR(b.to.z, -20, kEps);
  EXPECT_DOUBLE_EQ(b.lead, 1.5);
  EXPECT_DOUBLE_EQ(*b.start_angle, 180);
  EXPECT_EQ(b.line, 3u);
  // Each G92 returns to its start: in, cut, out, back; then the G0.
  ASSERT_EQ(r.sim.path.moves.size(), 9u);
  EXPECT_NEAR(r.sim.path.moves[7].to.x, 9.299, kEps);
  EXPECT_NEAR(r.sim.path.moves[7].to.z, 2, kEps);
}

TEST(ControlSim, FanucG76TwoBlocksExpandedWithTheLaw) {
  // Height 0.92, first cut 0.376 (x root n), allowance 0.081, one finish pass, 60 deg tool:
  // rough depths 0.376, 0.376 root 2, 0.376 root 3, 0.752, then k - d = 0.839 (0.376 root 5 =
  // 0.8408 is deeper), finish at 0.92. Every pass ends at Z-20 (cycle_pass_end: fixed) and
  // starts shifted back along the flank by h tan 30.
  SimRun r = run(shipped("fanuc-0i-t"),
                 "N180 G0 X18.598 Z2.\nN190 G76 P010060 Q100 R0.081\n"
                 "N200 G76 X14.16 Z-20. P920 Q376 F1.5\n");
  ASSERT_TRUE(r.ok) << r.diagnostics;
  const double h[] = {0.376, 0.376 * std::sqrt(2.0), 0.376 * std::sqrt(3.0), 0.752, 0.839, 0.92};
  ASSERT_EQ(r.sim.cuts.size(), 6u);
  for (size_t i = 0; i < 6; ++i) {
    const NcCut& c = r.sim.cuts[i];
    EXPECT_NEAR(c.from.x, 7.08 + 0.92 - h[i], 1e-9) << i;
    EXPECT_NEAR(c.from.z, 2 - h[i] * std::tan(std::numbers::pi / 6), 1e-9) << i;
    EXPECT_NEAR(c.to.z, -20, 1e-9) << i;
    EXPECT_TRUE(c.fixed_end);
    EXPECT_EQ(c.source, "G76");
    EXPECT_EQ(c.line, 3u);
  }
}

TEST(ControlSim, SiemensCycle99ArgumentsByTheTemplatesFieldOrder) {
  // VARI 300103: constant cross-section, depth TDEP root(i / NRC).
  SimRun r = run(shipped("sinumerik-840d"),
                 "N10 G18 G710 G40 G90 DIAMON\nN20 G0 X18.598 Z2\n"
                 "N30 CYCLE99(2, 16, -20, 16, 0, 0, 0.92, 0, 0, 0, 6, 0, 1.5, 300103, 0, 1.299, 0, "
                 "0, 0, 0, 0, 0, 1, \"\", \"\", \"\", 0)\n");
  ASSERT_TRUE(r.ok) << r.diagnostics;
  ASSERT_EQ(r.sim.cuts.size(), 6u);
  for (int i = 0; i < 6; ++i) {
    const double d = 0.92 * std::sqrt((i + 1) / 6.0);
    EXPECT_NEAR(r.sim.cuts[i].from.x, 8 - d, 1e-9) << i;
    EXPECT_NEAR(r.sim.cuts[i].to.z, -20, 1e-9) << i;
  }
  EXPECT_DOUBLE_EQ(r.sim.cuts[0].lead, 1.5);
  EXPECT_EQ(r.sim.cuts[0].source, "CYCLE99");
}

TEST(ControlSim, LinuxcncG76InDiameterMode) {
  // G7: I, J, K are diameters. Drive line X9.29904; crest 1.29904 in; depths J root n until K.
  SimRun r = run(shipped("linuxcnc-lathe"),
                 "G7 G18 G21 G90\nG1 X18.59808 Z2. F0.2\n"
                 "G76 P1.5 Z-20. I-2.59808 J0.751177 K1.84 R2 Q30. H0\n");
  ASSERT_TRUE(r.ok) << r.diagnostics;
  ASSERT_EQ(r.sim.cuts.size(), 6u);
  EXPECT_NEAR(r.sim.cuts[0].from.x, 9.29904 - 1.29904 - 0.3755885, 1e-9);
  EXPECT_NEAR(r.sim.cuts[1].from.x, 9.29904 - 1.29904 - 0.3755885 * std::sqrt(2.0), 1e-9);
  EXPECT_NEAR(r.sim.cuts[5].from.x, 9.29904 - 1.29904 - 0.92, 1e-9);
  // G76 leaves the tool on the drive line at the thread's end.
  EXPECT_NEAR(r.sim.path.moves.back().to.x, 9.29904, 1e-9);
  EXPECT_NEAR(r.sim.path.moves.back().to.z, -20, 1e-9);
}

TEST(ControlSim, DwellWordsAreNotPositions) {
  SimRun r = run(shipped("fanuc-0i-t"), "G0 X20 Z5\nG4 X1.5\nG1 Z0 F0.1\n");
  ASSERT_TRUE(r.ok) << r.diagnostics;
  ASSERT_EQ(r.sim.path.moves.size(), 1u);
  EXPECT_NEAR(r.sim.path.moves[0].to.x, 10, kEps);
}

TEST(ControlSim, ErrorsAreDiagnosticsWithTheLineAndColumn) {
  const Machine m = shipped("generic-lathe");
  EXPECT_EQ(run(m, "G0 X1\nG1 X1.2.3\n").diagnostics,
            "p.nc:2:4: error: invalid number 'X1.2.3'\n  G1 X1.2.3\n     ^\n");
  EXPECT_EQ(run(m, "G91 G0 X1\n").diagnostics,
            "p.nc:1:1: error: 'G91': incremental positions are not supported by verify "
            "(absolute G90 only)\n  G91 G0 X1\n  ^\n");
  EXPECT_EQ(run(m, "X1 Z2\n").diagnostics,
            "p.nc:1:1: error: a position with no motion mode (G0, G1, ...) in force\n  X1 Z2\n"
            "  ^\n");
  EXPECT_EQ(run(m, "G0 X1\nG2 X3 Z-1 F0.1\n").diagnostics,
            "p.nc:2:4: error: arc without a centre (I/K)\n  G2 X3 Z-1 F0.1\n     ^\n");
  EXPECT_EQ(run(shipped("linuxcnc-lathe"), "G0 X10 Z1\nG33 Z-5\n").diagnostics,
            "p.nc:2:1: error: synchronized move without a lead (K word)\n  G33 Z-5\n  ^\n");
  EXPECT_EQ(run(m, std::string("G0 X1\n\x01\x02\x03\x00zz", 11)).diagnostics,
            "p.nc: error: not an NC text file (binary data at byte 9)\n");
}

TEST(ControlSim, CycleErrorsNameTheWords) {
  EXPECT_EQ(run(shipped("fanuc-0i-t"), "G0 X20 Z2\nG76 X14.16 Z-20. P920 Q376 F1.5\n").diagnostics,
            "p.nc:2:1: error: G76 with X/Z but no first G76 block (P mmrraa Q R) before it\n"
            "  G76 X14.16 Z-20. P920 Q376 F1.5\n  ^\n");
  EXPECT_EQ(
      run(shipped("linuxcnc-lathe"), "G7\nG0 X20 Z2\nG76 P1.5 Z-20 I-2 J0.5 K0.4\n").diagnostics,
      "p.nc:3:1: error: In G76, K must be greater than J\n"
      "  G76 P1.5 Z-20 I-2 J0.5 K0.4\n  ^\n");
  EXPECT_EQ(run(shipped("heidenhain-pilot"), "N 10 G0 X20 Z2\nN 20 G31 F1.5 U0.92 IC4 V0 H0\n")
                .diagnostics,
            "p.nc:2:6: error: G31 has no G80: the thread cycle's contour is not closed\n"
            "  N 20 G31 F1.5 U0.92 IC4 V0 H0\n       ^\n");
}

TEST(ControlSim, AHaasG76OfNoLengthCutsNothing) {
  // Found by nc_verify_fuzzer (UBSan): alternating infeed (P2) from the thread's own end read
  // the first cut of an empty expansion.
  EXPECT_EQ(
      run(shipped("haas-st"), "G0 X20 Z-20\nG76 X14.16 Z-20. K0.92 D0.3 A60 P2 F1.5\n").diagnostics,
      "p.nc:2:1: error: G76 cuts nothing from Z-20 to Z-20: height K 0.92, first cut D 0.3\n"
      "  G76 X14.16 Z-20. K0.92 D0.3 A60 P2 F1.5\n  ^\n");
}

TEST(ControlSim, CycleCountsOutOfRangeAreRefusedNotRun) {
  // Found by nc_verify_fuzzer: G31 asking for 180000 air cuts (Q) ran them all.
  EXPECT_EQ(run(shipped("heidenhain-pilot"),
                "N 10 G0 X20 Z2\nN 20 G31 F1.5 U0.92 Q180000 IC8 V1 H3 A30\nN 30 G0 X16 Z2\n"
                "N 40 G1 X16 Z-20\nN 50 G80\n")
                .diagnostics,
            "p.nc:2:6: error: Q 180000: a whole number from 0 to 200 expected\n"
            "  N 20 G31 F1.5 U0.92 Q180000 IC8 V1 H3 A30\n       ^\n");
  EXPECT_EQ(run(shipped("linuxcnc-lathe"), "G7\nG0 X20 Z2\nG76 P1.5 Z-20 I-2 J0.5 K1.8 H100000\n")
                .diagnostics,
            "p.nc:3:1: error: H 100000: a whole number from 0 to 200 expected\n"
            "  G76 P1.5 Z-20 I-2 J0.5 K1.8 H100000\n  ^\n");
  EXPECT_EQ(
      run(shipped("sinumerik-840d"),
          "G0 X18 Z2\nCYCLE99(2, 16, -20, 16, 0, 0, 0.92, 0, 0, 0, 2.5, 0, 1.5, 300103, 0, "
          "1.299, 0, 0, 0, 0, 0, 0, 1, \"\", \"\", \"\", 0)\n")
          .diagnostics,
      "p.nc:2:1: error: NRC 2.5: a whole number from 1 to 200 expected\n"
      "  CYCLE99(2, 16, -20, 16, 0, 0, 0.92, 0, 0, 0, 2.5, 0, 1.5, 300103, 0, 1.299, 0, 0, 0, "
      "0, 0, 0, 1, \"\", \"\", \"\", 0)\n  ^\n");
}

}  // namespace
}  // namespace clpost

namespace clpost {
namespace {

// The seed's CYCLE98 example (controllers.md: PO1 0, DM1 30, PO2 -30, DM2 30, PO3 -60, DM3 36,
// PO4 -80, DM4 50, APP 10, ROP 10, TDEP 0.92, FAL/IANG/NSP empty, NRC 5, NID 1, VARI 3,
// NUMTH 1) with one lead for the three segments: the contour moved in by 0.92 sqrt(i/5), run in
// 10 before PO1 along the first segment, ending 10 back along the last one (7, -20)/sqrt(449)
// and running out at 45 degrees over 10; then the idle pass at 0.92.
TEST(ControlSim, SiemensCycle98TheSeedsExample) {
  SimRun r = run(shipped("sinumerik-840d"),
                 "N10 G18 G710 G40 G90 DIAMON\nN20 G0 X70 Z15\n"
                 "N30 CYCLE98(0, 30, -30, 30, -60, 36, -80, 50, 10, 10, 0.92, , , , 5, 1, 2, 2, "
                 "2, 3, 1,)\n");
  ASSERT_TRUE(r.ok) << r.diagnostics;
  ASSERT_EQ(r.sim.cuts.size(), 6u);
  const double s = std::sqrt(449.0);
  for (int i = 0; i < 6; ++i) {
    const double d = 0.92 * std::sqrt(std::min(i + 1, 5) / 5.0);
    const NcCut& c = r.sim.cuts[static_cast<size_t>(i)];
    EXPECT_NEAR(c.from.x, 15 - d, 1e-9) << i;
    EXPECT_NEAR(c.from.z, 10, 1e-9) << i;
    ASSERT_EQ(c.chain.size(), 4u) << i;  // two corners, the end of the last segment, run-out
    EXPECT_NEAR(c.chain[0].x, 15 - d, 1e-9) << i;
    EXPECT_NEAR(c.chain[0].z, -30, 1e-9) << i;
    EXPECT_NEAR(c.chain[1].x, 18 - d, 1e-9) << i;
    EXPECT_NEAR(c.chain[1].z, -60, 1e-9) << i;
    EXPECT_NEAR(c.to.x, 25 - d - 70 / s, 1e-9) << i;
    EXPECT_NEAR(c.to.z, -80 + 200 / s, 1e-9) << i;
    EXPECT_NEAR(c.end.x, c.to.x + 270 / s, 1e-9) << i;
    EXPECT_NEAR(c.end.z, c.to.z - 130 / s, 1e-9) << i;
    EXPECT_DOUBLE_EQ(c.lead, 2);
    EXPECT_EQ(c.source, "CYCLE98");
  }
}

TEST(ControlSim, SiemensCycle98WithOneLeadPerSegmentIsNotExpanded) {
  // The seed's call as printed: PP1 1.5, PP2 2, PP3 2.
  SimRun r = run(shipped("sinumerik-840d"),
                 "N10 G18 G710 G40 G90 DIAMON\nN20 G0 X70 Z15\n"
                 "N30 CYCLE98(0, 30, -30, 30, -60, 36, -80, 50, 10, 10, 0.92, , , , 5, 1, 1.5, 2, "
                 "2, 3, 1,)\n");
  EXPECT_FALSE(r.ok);
  EXPECT_NE(r.diagnostics.find("p.nc:3:5: error: CYCLE98 is not expanded: PP2 2 differs from PP1 "
                               "1.5: one lead per chain is expanded\n"),
            std::string::npos)
      << r.diagnostics;
}

}  // namespace
}  // namespace clpost

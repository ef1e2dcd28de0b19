#include "interpreter/interpreter.h"
#include "interpreter/post.h"
#include "interpreter/statement_table.h"
#include "machine/machine_test_util.h"

#include <gtest/gtest.h>

#include "machine/machine_loader.h"
#include "reader/cl_reader.h"

namespace clpost {
namespace {

struct Posted {
  std::string nc;
  std::string diags;
  size_t errors = 0;
};

Machine generic(std::vector<std::string> sets = {}) {
  Machine m;
  std::string errors;
  sets.push_back("block_numbers.enabled=false");
  sets.push_back("templates.program_header=[]");  // the header's own tests: cycle_time_test.cc
  EXPECT_TRUE(
      load_machine("generic-lathe", {CLPOST_SOURCE_DIR}, sets, shipped_controls(), m, errors))
      << errors;
  return m;
}

Posted post(const std::string& cl, const Machine& m, PostOptions opts = {}) {
  PostedText r = post_text(cl, m, "t.cl", opts);
  return Posted{r.program, r.diags.render_all(), r.diags.error_count()};
}

constexpr const char* kHeader = "%\nO0001\nG18 G21 G40 G90\n";

TEST(Interpreter, FeedDialectsGiveTheSameProgram) {
  Machine m = generic();
  // FEDRAT/f,MMPR and FEDRAT/MMPR,f; SPINDL/n,RPM,CLW and SPINDL/RPM,n,CLW.
  Posted a = post("SPINDL/800,RPM,CLW\nFEDRAT/0.2,MMPR\nGOTO/10,0,0\nFINI\n", m);
  Posted b = post("SPINDL/RPM,800,CLW\nFEDRAT/MMPR,0.2\nGOTO/10,0,0\nFINI\n", m);
  EXPECT_EQ(a.nc, std::string(kHeader) + "G97 S800 M3\nG1 X20. Z0. G95 F0.2\nM30\n%\n");
  EXPECT_EQ(a.nc, b.nc);
  EXPECT_EQ(a.diags, "");
}

TEST(Interpreter, InchFeedInAMetricProgramIsConverted) {
  // 0.01 in/rev = 0.254 mm/rev; 10 ipm = 254 mm/min.
  Posted p = post("FEDRAT/0.01,IPR\nGOTO/10,0,0\nFEDRAT/IPM,10\nGOTO/10,0,-5\nFINI\n", generic());
  EXPECT_EQ(p.nc, std::string(kHeader) + "G1 X20. Z0. G95 F0.254\nZ-5. G94 F254.\nM30\n%\n");
}

TEST(Interpreter, RapidIsOneShot) {
  Posted p = post("FEDRAT/100,MMPM\nRAPID\nGOTO/10,0,5\nGOTO/10,0,0\nRAPID/\nGOTO/12,0,0\nFINI\n",
                  generic());
  EXPECT_EQ(p.nc, std::string(kHeader) + "G0 X20. Z5.\nG1 Z0. G94 F100.\nG0 X24.\nM30\n%\n");
}

TEST(Interpreter, ConstantSurfaceSpeedUsesTheLimit) {
  Posted p = post("SPINDL/SMM,180,CCLW,MAXRPM,2500\nFINI\n", generic());
  EXPECT_EQ(p.nc, std::string(kHeader) + "G50 S2500\nG96 S180 M4\nM30\n%\n");
  // Without MAXRPM the machine's limit (4000) applies.
  Posted q = post("SPINDL/SMM,180,CLW\nFINI\n", generic());
  EXPECT_EQ(q.nc, std::string(kHeader) + "G50 S4000\nG96 S180 M3\nM30\n%\n");
  // A MAXRPM above the machine's limit is lowered to it.
  Posted r = post("SPINDL/SMM,180,CLW,MAXRPM,9000\nFINI\n", generic());
  EXPECT_EQ(r.nc, std::string(kHeader) + "G50 S4000\nG96 S180 M3\nM30\n%\n");
}

TEST(Interpreter, SpindleOverTheMachineLimitIsAnError) {
  Posted p = post("SPINDL/4500,RPM,CLW\nFINI\n", generic());
  EXPECT_EQ(p.errors, 1u);
  EXPECT_EQ(p.diags,
            "t.cl:1:8: error: spindle speed 4500 rpm exceeds the machine's maximum 4000 rpm\n"
            "  SPINDL/4500,RPM,CLW\n"
            "         ^\n");
}

TEST(Interpreter, GotoArgumentCount) {
  Posted p = post("RAPID\nGOTO/1,2,3,4\nFINI\n", generic());
  EXPECT_EQ(p.diags,
            "t.cl:2:12: error: GOTO/ takes x,y[,z[,i,j,k]]: 2, 3 or 6 numbers, found 4\n"
            "  GOTO/1,2,3,4\n"
            "             ^\n");
  Posted q = post("RAPID\nGOTO/1,0,CLW\nFINI\n", generic());
  EXPECT_EQ(q.diags,
            "t.cl:2:10: error: expected Z but found 'CLW'\n"
            "  GOTO/1,0,CLW\n"
            "           ^\n");
}

TEST(Interpreter, FeedMoveWithoutFeedIsAnError) {
  Posted p = post("GOTO/1,0,3\nFINI\n", generic());
  EXPECT_EQ(p.diags,
            "t.cl:1:1: error: feed move before any FEDRAT/: the feed is unknown\n"
            "  GOTO/1,0,3\n"
            "  ^\n");
}

TEST(Interpreter, YOnALatheWarnsOnceWithAFixedRadialAxis) {
  Posted p = post("RAPID\nGOTO/1,2,3\nRAPID\nGOTO/1,5,3\nFINI\n", generic({"cl.radial_axis=x"}));
  EXPECT_EQ(p.errors, 0u);
  EXPECT_EQ(p.diags,
            "t.cl:2:1: warning: Y = 2 but a lathe has no such axis: ignored (the first of such "
            "points; is this a milling program?)\n"
            "  GOTO/1,2,3\n"
            "  ^\n");
}

TEST(Interpreter, ArcDirectionAndCentre) {
  // Fillet R2 from (r15, z-20) to (r17, z-22) about (r17, z-20), CL axis -Y: clockwise, G2.
  Posted p = post(
      "FEDRAT/0.1,MMPR\nGOTO/15,0,-20\nCIRCLE/17,0,-20,0,-1,0,2\nGOTO/17,0,-22\n"
      "CIRCLE/17,0,-20,0,1,0,2\nGOTO/15,0,-20\nFINI\n",
      generic());
  EXPECT_EQ(p.diags, "");
  EXPECT_EQ(p.nc, std::string(kHeader) +
                      "G1 X30. Z-20. G95 F0.1\nG2 X34. Z-22. I2. K0.\n"
                      "G3 X30. Z-20. I0. K2.\nM30\n%\n");
}

TEST(Interpreter, ArcErrors) {
  Posted off_plane = post(
      "FEDRAT/0.1,MMPR\nGOTO/15,0,-20\nCIRCLE/17,0,-20,0,0,1,2\nGOTO/17,0,-22\nFINI\n", generic());
  EXPECT_EQ(off_plane.diags,
            "t.cl:3:1: error: CIRCLE axis (0, 0, 1) is not normal to the lathe plane: the arc "
            "cannot be cut on a lathe\n"
            "  CIRCLE/17,0,-20,0,0,1,2\n"
            "  ^\n");
  Posted not_on = post(
      "FEDRAT/0.1,MMPR\nGOTO/15,0,-20\nCIRCLE/17,0,-20,0,-1,0,2\nGOTO/17,0,-23\nFINI\n", generic());
  EXPECT_EQ(not_on.diags,
            "t.cl:4:1: error: arc end point is not on the circle of line 3: distance from the "
            "centre 2 at "
            "the start, 3 at the end\n"
            "  GOTO/17,0,-23\n"
            "  ^\n");
}

TEST(Interpreter, RemappedAxesAndDiameterInput) {
  // A CAM system writing the turning plane as XY with X the axis and Y a diameter.
  Machine m = generic({"cl.radial_axis=y", "cl.axial_axis=x", "cl.radial_is_diameter=true"});
  Posted p = post("RAPID\nGOTO/-5,40,0\nFINI\n", m);
  EXPECT_EQ(p.diags, "");
  EXPECT_EQ(p.nc, std::string(kHeader) + "G0 X40. Z-5.\nM30\n%\n");
}

// A CIRCLE/ whose GOTO ends where the tool is writes nothing, with a warning: the block would be
// "I0. K-2." alone (X and Z unchanged, G3 modal), a full circle on the control. Found by the
// round-trip fuzzer.
TEST(Interpreter, AnArcEndingWhereItStartsCutsNothing) {
  Posted p =
      post("FEDRAT/0.2,MMPR\nGOTO/10,0,0\nCIRCLE/10,0,-2,0,1,0,2\nGOTO/10,0,0\nGOTO/12,0,0\nFINI\n",
           generic());
  EXPECT_EQ(p.nc, std::string(kHeader) + "G1 X20. Z0. G95 F0.2\nX24.\nM30\n%\n");
  EXPECT_EQ(p.diags,
            "t.cl:4:1: warning: the arc of the CIRCLE/ at line 3 ends where it starts: nothing is "
            "cut (a full circle is no lathe profile)\n"
            "  GOTO/10,0,0\n"
            "  ^\n");
}

TEST(Interpreter, TextStatements) {
  Posted p = post("PARTNO SHAFT 12\nPPRINT rough (OD)\nINSERT G65 P9010\nFINI\n", generic());
  EXPECT_EQ(p.nc, std::string(kHeader) + "(SHAFT 12)\n(rough OD)\nG65 P9010\nM30\n%\n");
}

// INSERT's text is the user's: it may change the motion mode, the feed or the position, so the
// next move writes its motion code, both axes and its feed again (without the INSERT the second
// GOTO would be "Z-10." alone).
TEST(Interpreter, AnInsertMakesTheNextMoveStateEverything) {
  Posted p =
      post("FEDRAT/0.2,MMPR\nGOTO/10,0,0\nINSERT G98 G0 Z50.\nGOTO/10,0,-10\nFINI\n", generic());
  EXPECT_EQ(p.nc, std::string(kHeader) +
                      "G1 X20. Z0. G95 F0.2\nG98 G0 Z50.\nG1 X20. Z-10. G95 F0.2\nM30\n%\n");
}

TEST(Interpreter, ToolCoolantCompDwellStops) {
  Posted p = post(
      "LOADTL/4,ADJUST,14\nLOAD/TOOL,5\nCOOLNT/ON\nCOOLNT/OFF\nCUTCOM/LEFT\nCUTCOM/OFF\n"
      "DELAY/2\nSTOP\nOPSTOP\nFINI\n",
      generic());
  EXPECT_EQ(p.nc,
            std::string(kHeader) + "T0414\nT0505\nM8\nM9\nG41\nG40\nG4 X2.\nM0\nM1\nM30\n%\n");
}

// DELAY/REV,n on a machine that dwells in seconds: n revolutions at 600 rpm are n/10 s.
TEST(Interpreter, DwellInRevolutionsBecomesSecondsThroughTheRpm) {
  Posted p = post("SPINDL/600,RPM,CLW\nDELAY/REV,3\nDELAY/1.5\nFINI\n", generic());
  EXPECT_EQ(p.nc, std::string(kHeader) + "G97 S600 M3\nG4 X0.3\nG4 X1.5\nM30\n%\n");
  EXPECT_EQ(p.diags, "");
}

// A machine whose dwell is in revolutions: 2 s at 600 rpm are 20 revolutions, never "2".
TEST(Interpreter, DwellInSecondsBecomesRevolutionsThroughTheRpm) {
  Machine m = generic({"templates.dwell=[\"G4 U{revolutions}\"]"});
  Posted p = post("SPINDL/600,RPM,CLW\nDELAY/2\nDELAY/REV,0.5\nFINI\n", m);
  EXPECT_EQ(p.nc, std::string(kHeader) + "G97 S600 M3\nG4 U20.\nG4 U0.5\nM30\n%\n");
  EXPECT_EQ(p.diags, "");
}

TEST(Interpreter, DwellThatCannotBeConvertedIsAnError) {
  Posted stopped = post("DELAY/REV,3\nFINI\n", generic());
  EXPECT_EQ(stopped.diags,
            "t.cl:1:1: error: machine 'generic-lathe' dwells in seconds: a dwell of 3 revolutions "
            "needs the spindle turning at a set RPM to convert, and the spindle is stopped\n"
            "  DELAY/REV,3\n"
            "  ^\n");
  Machine m = generic({"templates.dwell=[\"G4 U{revolutions}\"]"});
  Posted css = post("SPINDL/SFM,200,MAXRPM,2000,CLW\nDELAY/2\nFINI\n", m);
  EXPECT_EQ(css.errors, 1u);
  EXPECT_NE(css.diags.find("t.cl:2:1: error: machine 'generic-lathe' dwells in revolutions: a "
                           "dwell of 2 seconds needs the spindle turning at a set RPM to convert, "
                           "and the spindle runs at constant surface speed\n"),
            std::string::npos)
      << css.diags;
  EXPECT_EQ(css.nc.find("G4 U"), std::string::npos);
}

// A machine file without a dwell template: the DELAY is an error, not silently left out.
TEST(Interpreter, DwellWithoutATemplateIsAnError) {
  Machine m = generic();
  m.templates.erase("dwell");
  Posted p = post("DELAY/2\nFINI\n", m);
  EXPECT_EQ(p.diags,
            "t.cl:1:1: error: machine 'generic-lathe' has no template 'dwell' (templates.dwell "
            "in its machine or post file)\n"
            "  DELAY/2\n"
            "  ^\n");
}

TEST(Interpreter, UnitsInchesGiveG20AndInchCoordinates) {
  Posted p = post("UNITS/INCHES\nRAPID\nGOTO/1.25,0,0.1\nFINI\n", generic());
  EXPECT_EQ(p.nc, "%\nO0001\nG18 G20 G40 G90\nG0 X2.5 Z0.1\nM30\n%\n");
}

TEST(Interpreter, StatementsAfterFiniAreIgnoredWithANote) {
  Posted p = post("FINI\nRAPID\nGOTO/1,0,0\n", generic());
  EXPECT_EQ(p.nc, std::string(kHeader) + "M30\n%\n");
  EXPECT_EQ(p.diags, "t.cl:2:1: note: statements after FINI are ignored\n  RAPID\n  ^\n");
}

// Hole cycles on the spindle axis are posted (hole_cycles_test.cc); other cycles are refused
// with their holes.
TEST(Interpreter, OtherCyclesAreRefusedNotDropped) {
  Posted p = post("CYCLE/THREADMILLING,5,MMPM,100\nGOTO/0,0,0\nCYCLE/OFF\nFINI\n", generic());
  EXPECT_EQ(p.errors, 1u);
  EXPECT_NE(p.diags.find(
                "t.cl:1:1: error: CYCLE/THREADMILLING is not supported on machine 'generic-lathe'"),
            std::string::npos);
}

}  // namespace
}  // namespace clpost

namespace clpost {
namespace {

TEST(InterpreterThreads, FeedAboveTheMachineLimitStopsWithTheThreeNumbers) {
  // lead 2.5 x 4000 rpm = 10000 per minute: exactly the limit is allowed; 2.6 x 4000 is not.
  Machine m = generic();
  Posted ok = post(
      "SPINDL/4000,RPM,CLW\nRAPID\nGOTO/12,0,2\nTHREAD/TURN,MMPR,2.5\nRAPID\nGOTO/10,0,2\nGOTO/"
      "10,0,-20\nFINI\n",
      m);
  EXPECT_EQ(ok.errors, 0u) << ok.diags;
  Posted bad = post(
      "SPINDL/4000,RPM,CLW\nRAPID\nGOTO/12,0,2\nTHREAD/TURN,MMPR,2.6\nRAPID\nGOTO/10,0,2\nGOTO/"
      "10,0,-20\nFINI\n",
      m);
  EXPECT_EQ(
      bad.diags,
      "t.cl:4:1: error: thread feed too fast for machine 'generic-lathe': lead 2.6 x 4000 rpm = "
      "10400 per minute, above its maximum feed 10000\n"
      "  THREAD/TURN,MMPR,2.6\n"
      "  ^\n");
}

TEST(InterpreterThreads, ConstantSurfaceSpeedBecomesG97ForTheThreadAndComesBack) {
  // 120 m/min at the thread's largest diameter 24 mm: 1000*120/(pi*24) = 1591.5 -> 1591 rpm.
  Posted p = post(
      "SPINDL/SMM,120,CLW,MAXRPM,3000\nRAPID\nGOTO/12,0,2\nCOUPLE/ON,MMPR,1.5\nGOTO/12,0,-20\n"
      "COUPLE/OFF\nFINI\n",
      generic());
  EXPECT_EQ(p.diags, "");
  EXPECT_EQ(
      p.nc,
      std::string(kHeader) +
          "G50 S3000\nG96 S120 M3\nG0 X24. Z2.\n(constant surface speed 120 off for the "
          "thread: 1591 rpm)\nG97 S1591 M3\nG33 Z-20. F1.5\nG50 S3000\nG96 S120 M3\nM30\n%\n");
}

TEST(InterpreterThreads, ThreadWithTheSpindleStoppedIsAnError) {
  Posted p =
      post("RAPID\nGOTO/12,0,2\nPITCH/1.5,MMPR\nCOUPLE/ON\nGOTO/12,0,-20\nCOUPLE/OFF\nFINI\n",
           generic());
  EXPECT_EQ(
      p.diags,
      "t.cl:4:1: error: thread cut with the spindle stopped: program SPINDL/ before the thread\n"
      "  COUPLE/ON\n"
      "  ^\n");
}

TEST(InterpreterThreads, UnterminatedSequencesAreErrorsAtTheirStart) {
  Posted t = post(
      "SPINDL/500,RPM,CLW\nRAPID\nGOTO/15,0,5\nTHREAD/ON,DEPTH,1,CUTS,2,MMPR,1.5\nGOTO/10,0,2\n",
      generic());
  EXPECT_EQ(t.diags,
            "t.cl:4:1: error: THREAD/ON without THREAD/OFF (the file ends first)\n"
            "  THREAD/ON,DEPTH,1,CUTS,2,MMPR,1.5\n"
            "  ^\n"
            "t.cl:5: warning: the file ends without FINI: the program end was added\n");
  Posted c = post("SPINDL/500,RPM,CLW\nRAPID\nGOTO/15,0,5\nCOUPLE/ON,MMPR,1.5\nCOUPLE/ON\nFINI\n",
                  generic());
  EXPECT_EQ(c.diags,
            "t.cl:5:1: error: COUPLE/ON inside COUPLE/ON of line 4: COUPLE/OFF missing\n"
            "  COUPLE/ON\n"
            "  ^\n"
            "t.cl:4:1: error: COUPLE/ON without COUPLE/OFF (the file ends first)\n"
            "  COUPLE/ON,MMPR,1.5\n"
            "  ^\n");
}

}  // namespace
}  // namespace clpost

namespace clpost {
namespace {

TEST(InterpreterThreads, PerAxisFeedLimits) {
  // Taper from radius 10 at Z2 to radius 12 at Z-18, lead 2 at 1000 rpm: Z moves
  // 2 x 1000 = 2000 per minute, X 2000 x 2/20 = 200 (radius).
  const std::string cl =
      "SPINDL/1000,RPM,CLW\nRAPID\nGOTO/14,0,4\nTHREAD/TAPER,MMPR,2\nRAPID\nGOTO/10,0,2\n"
      "GOTO/12,0,-18\nFINI\n";
  Posted ok = post(cl, generic({"limits.max_feed_x=200", "limits.max_feed_z=2000"}));
  EXPECT_EQ(ok.errors, 0u) << ok.diags;
  Posted x = post(cl, generic({"limits.max_feed_x=150"}));
  EXPECT_EQ(x.diags,
            "t.cl:4:1: error: thread feed too fast for machine 'generic-lathe': the X axis moves "
            "200 per minute (lead 2 x 1000 rpm), above its limit 150 (limits.max_feed_x)\n"
            "  THREAD/TAPER,MMPR,2\n"
            "  ^\n");
  Posted z = post(cl, generic({"limits.max_feed_z=1999"}));
  EXPECT_EQ(z.diags,
            "t.cl:4:1: error: thread feed too fast for machine 'generic-lathe': the Z axis moves "
            "2000 per minute (lead 2 x 1000 rpm), above its limit 1999 (limits.max_feed_z)\n"
            "  THREAD/TAPER,MMPR,2\n"
            "  ^\n");
}

}  // namespace
}  // namespace clpost

// ---- hostile and odd input ----------------------------------------------------------------------

namespace clpost {
namespace {

struct OddRun {
  std::string nc;
  std::string diags;
  size_t errors = 0;
  size_t kept = 0;
  PostStats stats;
};

OddRun run_cl(const std::string& cl) {
  PostedText p = post_text(cl, generic(), "t.cl");
  OddRun r;
  r.nc = p.program;
  r.diags = p.diags.render_all();
  r.errors = p.diags.error_count();
  r.kept = p.diags.kept().size();
  r.stats = p.summary.stats;
  return r;
}

size_t count(const std::string& text, const std::string& what) {
  size_t n = 0;
  for (size_t at = text.find(what); at != std::string::npos; at = text.find(what, at + 1)) ++n;
  return n;
}

constexpr const char* kThreadStart = "SPINDL/500,RPM,CLW\nRAPID\nGOTO/15,0,5\n";

TEST(OddInput, NanAndInfAreWordsNotNumbers) {
  OddRun r = run_cl("FEDRAT/0.1,MMPR\nGOTO/nan,0,1\nGOTO/1,0,inf\nGOTO/1,0,-inf\nFINI\n");
  EXPECT_EQ(r.diags,
            "t.cl:2:6: error: expected X but found 'NAN'\n"
            "  GOTO/nan,0,1\n"
            "       ^\n"
            "t.cl:3:10: error: expected Z but found 'INF'\n"
            "  GOTO/1,0,inf\n"
            "           ^\n"
            "t.cl:4:10: error: invalid number '-inf'\n"
            "  GOTO/1,0,-inf\n"
            "           ^\n");
  EXPECT_EQ(r.stats.motions, 0u);
}

TEST(OddInput, CoordinatesOfABillionAreOutOfRange) {
  OddRun r = run_cl(
      "FEDRAT/0.1,MMPR\nGOTO/1e9,0,0\nGOTO/0,0,-1000000000\nFROM/1e9,0,0\nGOTO/1000000,0,-1e6\n"
      "FINI\n");
  EXPECT_EQ(r.diags,
            "t.cl:2:6: error: X '1e9' is out of range: CL values must be between -1000000 "
            "and 1000000\n"
            "  GOTO/1e9,0,0\n"
            "       ^\n"
            "t.cl:3:10: error: Z '-1000000000' is out of range: CL values must be between "
            "-1000000 and 1000000\n"
            "  GOTO/0,0,-1000000000\n"
            "           ^\n"
            "t.cl:4:6: error: X '1e9' is out of range: CL values must be between -1000000 "
            "and 1000000\n"
            "  FROM/1e9,0,0\n"
            "       ^\n");
  // The limit itself is a coordinate like any other (X is a diameter).
  EXPECT_EQ(r.nc, std::string(kHeader) + "G1 X2000000. Z-1000000. G95 F0.1\nM30\n%\n");
}

TEST(OddInput, FeedSpeedAndOffsetOutOfRange) {
  OddRun r = run_cl(
      "FEDRAT/1e300,MMPM\nSPINDL/1e7,RPM\nSPINDL/SMM,100,MAXRPM,1e12\nLOADTL/1,ADJUST,1e300\n"
      "LOADTL/1,ADJUST,-2\nDELAY/1e9\nFINI\n");
  EXPECT_EQ(r.errors, 6u) << r.diags;
  EXPECT_NE(r.diags.find("t.cl:1:8: error: feed '1e300' is out of range"), std::string::npos)
      << r.diags;
  EXPECT_NE(r.diags.find("t.cl:2:8: error: spindle speed '1e7' is out of range"), std::string::npos)
      << r.diags;
  EXPECT_NE(r.diags.find("t.cl:3:23: error: MAXRPM '1e12' is out of range"), std::string::npos)
      << r.diags;
  EXPECT_NE(r.diags.find("t.cl:4:17: error: tool offset must be a whole number 0..9999, got 1e300"),
            std::string::npos)
      << r.diags;
  EXPECT_NE(r.diags.find("t.cl:5:17: error: tool offset must be a whole number 0..9999, got -2"),
            std::string::npos)
      << r.diags;
  EXPECT_NE(r.diags.find("t.cl:6:7: error: a dwell time in seconds '1e9' is out of range"),
            std::string::npos)
      << r.diags;
  EXPECT_EQ(r.nc, std::string(kHeader) + "M30\n%\n");
}

TEST(OddInput, TenThousandUnterminatedThreadOns) {
  std::string cl = kThreadStart;
  for (int i = 0; i < 10000; ++i) cl += "THREAD/ON,DEPTH,1,CUTS,2,MMPR,1.5\nGOTO/10,0,2\n";
  OddRun r = run_cl(cl);
  // Each THREAD/ON after the first is an error, and the first one never ends.
  EXPECT_EQ(r.errors, 10000u);
  EXPECT_EQ(r.kept, Diagnostics::kMaxKept);
  EXPECT_EQ(r.diags.substr(0, r.diags.find('\n') + 1),
            "t.cl:6:1: error: THREAD/ON inside the thread started at line 4: THREAD/OFF "
            "missing\n");
  // 10000 errors and the missing-FINI warning, 200 of them shown.
  const std::string last = "t.cl: note: 9801 more diagnostics not shown\n";
  ASSERT_GT(r.diags.size(), last.size());
  EXPECT_EQ(r.diags.substr(r.diags.size() - last.size()), last);
  EXPECT_EQ(count(r.nc, "G33"), 0u);
  EXPECT_EQ(r.stats.threads, 0u);
}

TEST(OddInput, TenThousandNestedThreadOnsAndOffs) {
  std::string cl = kThreadStart;
  for (int i = 0; i < 10000; ++i) cl += "THREAD/ON,DEPTH,1,CUTS,2,MMPR,1.5\n";
  cl += "GOTO/10,0,2\nGOTO/10,0,-20\n";
  for (int i = 0; i < 10000; ++i) cl += "THREAD/OFF\n";
  cl += "FINI\n";
  OddRun r = run_cl(cl);
  // The first ON and the first OFF make one good thread; 9999 ONs and 9999 OFFs are errors.
  EXPECT_EQ(r.errors, 19998u);
  EXPECT_EQ(r.stats.threads, 1u);
  EXPECT_EQ(r.stats.passes, 2u);
  EXPECT_EQ(r.diags.substr(0, r.diags.find('\n') + 1),
            "t.cl:5:1: error: THREAD/ON inside the thread started at line 4: THREAD/OFF "
            "missing\n");
  const std::string last = "t.cl: note: 19798 more diagnostics not shown\n";
  EXPECT_EQ(r.diags.substr(r.diags.size() - last.size()), last);
}

TEST(OddInput, ThreadWith200PassesIsCutAnd201IsRefused) {
  OddRun ok = run_cl(std::string(kThreadStart) +
                     "THREAD/ON,DEPTH,2,CUTS,200,MMPR,1.5\nGOTO/10,0,2\nGOTO/10,0,-20\nTHREAD/OFF\n"
                     "FINI\n");
  EXPECT_EQ(ok.diags, "");
  EXPECT_EQ(ok.stats.threads, 1u);
  EXPECT_EQ(ok.stats.passes, 200u);
  EXPECT_EQ(count(ok.nc, "G33"), 200u);
  OddRun bad =
      run_cl(std::string(kThreadStart) +
             "THREAD/ON,DEPTH,2,CUTS,201,MMPR,1.5\nGOTO/10,0,2\nGOTO/10,0,-20\nTHREAD/OFF\n"
             "FINI\n");
  EXPECT_EQ(bad.diags,
            "t.cl:4:24: error: CUTS count 201 is more than the 200 passes a thread may have\n"
            "  THREAD/ON,DEPTH,2,CUTS,201,MMPR,1.5\n"
            "                         ^\n");
  EXPECT_EQ(count(bad.nc, "G33"), 0u);
  // 199 roughing passes and 2 finish passes are 201 too.
  OddRun fin = run_cl(std::string(kThreadStart) +
                      "THREAD/ON,DEPTH,2,CUTS,199,FINCUT,2,0.01,MMPR,1.5\nGOTO/10,0,2\n"
                      "GOTO/10,0,-20\nTHREAD/OFF\nFINI\n");
  EXPECT_EQ(fin.errors, 1u);
  EXPECT_NE(fin.diags.find("the thread needs 201 passes (199 roughing + 2 finish)"),
            std::string::npos)
      << fin.diags;
  EXPECT_EQ(count(fin.nc, "G33"), 0u);
}

TEST(OddInput, CutsZeroOrNegative) {
  for (const char* cuts : {"0", "-3", "-0.5"}) {
    OddRun r = run_cl(std::string(kThreadStart) + "THREAD/ON,DEPTH,1,CUTS," + cuts +
                      ",MMPR,1.5\nGOTO/10,0,2\nGOTO/10,0,-20\nTHREAD/OFF\nFINI\n");
    EXPECT_EQ(r.diags, std::string("t.cl:4:24: error: CUTS count must be a positive whole number; "
                                   "got ") +
                           cuts + "\n  THREAD/ON,DEPTH,1,CUTS," + cuts +
                           ",MMPR,1.5\n                         ^\n");
    EXPECT_EQ(count(r.nc, "G33"), 0u) << cuts;
    EXPECT_EQ(count(r.nc, "G1 X20. Z-20."), 0u) << cuts;  // the GOTOs are not posted as moves
  }
}

// Fuzzer find: COUPLE/ON with no position before it read before its path (UBSan) and cut the
// GOTOs anyway.
TEST(OddInput, CoupleWithoutAStartPointCutsNothing) {
  OddRun r = run_cl(
      "SPINDL/500,RPM,CLW\nCOUPLE/ON,MMPR,1.5\nGOTO/12,0,-20\nGOTO/13,0,-21\n"
      "COUPLE/OFF\nFINI\n");
  EXPECT_EQ(r.diags,
            "t.cl:2:1: error: COUPLE/ON needs a start point: no GOTO or FROM before it\n"
            "  COUPLE/ON,MMPR,1.5\n"
            "  ^\n");
  EXPECT_EQ(count(r.nc, "G33"), 0u);
  EXPECT_EQ(r.stats.threads, 0u);
  EXPECT_EQ(r.stats.passes, 0u);
  // The same for a pitch the machine cannot cut: one error, nothing cut.
  OddRun v = run_cl(std::string(kThreadStart) +
                    "COUPLE/ON,MMPR,1.5,INCR,0.1\nGOTO/12,0,-20\nCOUPLE/OFF\nFINI\n");
  EXPECT_EQ(v.errors, 1u) << v.diags;
  EXPECT_EQ(count(v.nc, "G33"), 0u);
  EXPECT_EQ(v.stats.threads, 0u);
}

TEST(OddInput, MillionsOfErrorsKeepMemoryBounded) {
  // 300 000 feed moves before any FEDRAT/: every one is an error, 200 are shown.
  std::string cl;
  for (int i = 0; i < 300000; ++i) cl += "GOTO/1,0,1\n";
  OddRun r = run_cl(cl);
  EXPECT_EQ(r.errors, 300000u);
  EXPECT_EQ(r.kept, Diagnostics::kMaxKept);
  EXPECT_EQ(count(r.diags, "\n"), 3 * Diagnostics::kMaxKept + 1);
  EXPECT_EQ(r.diags.substr(0, 60), "t.cl:1:1: error: feed move before any FEDRAT/: the feed is u");
  const std::string last = "t.cl: note: 299801 more diagnostics not shown\n";
  EXPECT_EQ(r.diags.substr(r.diags.size() - last.size()), last);
}

// ---- statements the reader could not read (reader/statement.h, Statement::problem) ----------

TEST(Interpreter, UnknownWordsWithUnreadableArgumentsBecomeComments) {
  Posted p = post(
      "PART_OPE/Phase d'usinage.1\n"
      "OP_NAME/FIN RAYON - G2\n"
      "OPDATA/ACCURACY, 0.001,TYPE,Finition de $\n"
      "profil,MMPR\n"
      "FINI\n",
      generic());
  EXPECT_EQ(p.errors, 0u);
  EXPECT_EQ(p.nc, std::string(kHeader) +
                      "(PART_OPE/Phase d'usinage.1)\n"
                      "(OP_NAME/FIN RAYON - G2)\n"
                      "(OPDATA/ACCURACY, 0.001,TYPE,Finition de profil,MMPR)\n"
                      "M30\n%\n");
  EXPECT_EQ(p.diags,
            "t.cl:1:1: warning: unknown statement 'PART_OPE' written as a comment\n"
            "  PART_OPE/Phase d'usinage.1\n"
            "  ^\n"
            "t.cl:2:1: warning: unknown statement 'OP_NAME' written as a comment\n"
            "  OP_NAME/FIN RAYON - G2\n"
            "  ^\n"
            "t.cl:3:1: warning: unknown statement 'OPDATA' written as a comment\n"
            "  OPDATA/ACCURACY, 0.001,TYPE,Finition de $\n"
            "  ^\n");
}

TEST(Interpreter, UnknownWordsWithUnreadableArgumentsAreErrorsWhenStrict) {
  PostOptions strict;
  strict.strict = true;
  Posted p = post("OP_NAME/FIN RAYON - G2\nFINI\n", generic(), strict);
  EXPECT_EQ(p.diags,
            "t.cl:1:1: error: unknown statement 'OP_NAME' (--strict)\n"
            "  OP_NAME/FIN RAYON - G2\n"
            "  ^\n");
}

TEST(Interpreter, KnownWordsWithUnreadableArgumentsAreErrorsAtTheirColumn) {
  Posted p = post("GOTO/10,0,-1.2.3\nPITCH/(1/0)\nSPINDL/500 RPM\nINTOL/(0.1\nFINI\n", generic());
  EXPECT_EQ(p.diags,
            "t.cl:1:11: error: invalid number '-1.2.3'\n"
            "  GOTO/10,0,-1.2.3\n"
            "            ^\n"
            "t.cl:2:9: error: division by zero\n"
            "  PITCH/(1/0)\n"
            "          ^\n"
            "t.cl:3:12: error: missing ',' before 'RPM'\n"
            "  SPINDL/500 RPM\n"
            "             ^\n"
            "t.cl:4:7: error: missing ')' to close this '('\n"
            "  INTOL/(0.1\n"
            "        ^\n");
}

TEST(Interpreter, ModifierWordsAreRefusedNotDropped) {
  // GOFWD reads its modifiers (geometric_motion_test.cc); any other word refuses them.
  Posted p = post("RAPID, GOTO/1,0,0\nFINI\n", generic());
  EXPECT_EQ(p.errors, 1u);
  EXPECT_EQ(p.diags,
            "t.cl:1:1: error: RAPID,GOTO/: words before the major word (APT motion modifiers) "
            "are not supported; the statement may move the tool, so it cannot be left out\n"
            "  RAPID, GOTO/1,0,0\n"
            "  ^\n");
}

TEST(Interpreter, UnknownWordsWithNestedDefinitionsAreCommentsAsWritten) {
  Posted p = post("DSIS/(PLANE/(POINT/2,0,2),PERPTO,(VECTOR/0,1,0))\nFINI\n", generic());
  EXPECT_EQ(p.nc, std::string(kHeader) + "(DSIS/PLANE/POINT/2,0,2,PERPTO,VECTOR/0,1,0)\nM30\n%\n");
  EXPECT_EQ(p.diags,
            "t.cl:1:1: warning: unknown statement 'DSIS' written as a comment\n"
            "  DSIS/(PLANE/(POINT/2,0,2),PERPTO,(VECTOR/0,1,0))\n"
            "  ^\n");
}

}  // namespace
}  // namespace clpost

namespace clpost {
namespace {

TEST(StatementTable, EveryWordHasOneHandlerAndTheLookupIsExact) {
  std::span<const StatementEntry> t = statement_table();
  ASSERT_GT(t.size(), 40u);
  for (size_t i = 0; i < t.size(); ++i) {
    EXPECT_NE(t[i].handler, nullptr) << t[i].major;
    if (i > 0) {
      EXPECT_LT(t[i - 1].major, t[i].major);  // sorted, no word twice
    }
    EXPECT_EQ(find_statement(t[i].major), &t[i]);
  }
  EXPECT_EQ(find_statement("GOTO")->handler, &goto_stmt);
  EXPECT_EQ(find_statement("TOOL PATH")->handler, &tool_path_stmt);
  EXPECT_EQ(find_statement("TURRET")->handler, find_statement("LOADTL")->handler);
  for (std::string_view unknown : {"", "GOT", "GOTOX", "goto", "AAA", "ZZZZ"}) {
    EXPECT_EQ(find_statement(unknown), nullptr) << unknown;
  }
}

TEST(InterpreterThreads, OnlyGotosStandInsideCouple) {
  // A RAPID, CIRCLE or SPINDL inside COUPLE/ON cannot be cut synchronized: each is an error (a
  // RAPID used to be carried past COUPLE/OFF to the next move).
  Posted p = post(
      "SPINDL/500,RPM,CLW\nRAPID\nGOTO/10,0,2\nCOUPLE/ON,MMPR,2\nGOTO/10,0,-18\nRAPID\n"
      "SPINDL/600,RPM\nGOTO/10,0,-28\nCOUPLE/OFF\nFINI\n",
      generic());
  EXPECT_EQ(p.diags,
            "t.cl:6:1: error: RAPID is not allowed inside COUPLE/ON (line 4) ... COUPLE/OFF; "
            "expected GOTO or COUPLE/OFF\n"
            "  RAPID\n"
            "  ^\n"
            "t.cl:7:1: error: SPINDL is not allowed inside COUPLE/ON (line 4) ... COUPLE/OFF; "
            "expected GOTO or COUPLE/OFF\n"
            "  SPINDL/600,RPM\n"
            "  ^\n");
}

TEST(InterpreterThreads, SinglePassThreadEndsAtTheFirstOtherStatement) {
  // THREAD/TURN, its start and end; the third GOTO belongs to it too (no statement between):
  // the planner's error, at that GOTO.
  Posted three = post(
      "SPINDL/500,RPM,CLW\nRAPID\nGOTO/12,0,5\nTHREAD/TURN,MMPR,2\nRAPID\nGOTO/10,0,2\n"
      "GOTO/10,0,-18\nGOTO/12,0,-20\nFINI\n",
      generic());
  EXPECT_EQ(three.diags,
            "t.cl:8:1: error: THREAD/TURN takes exactly 2 GOTOs (thread start, thread end); this "
            "is GOTO 3 of 3 (use THREAD/ON for a chamfer pull-out)\n"
            "  GOTO/12,0,-20\n"
            "  ^\n"
            "t.cl:4:1: note: the thread starts here\n"
            "  THREAD/TURN,MMPR,2\n"
            "  ^\n");
  // A RAPID after the end GOTO ends the thread: cut, then the rapid away.
  Posted ok = post(
      "SPINDL/500,RPM,CLW\nRAPID\nGOTO/12,0,5\nTHREAD/TURN,MMPR,2\nRAPID\nGOTO/10,0,2\n"
      "GOTO/10,0,-18\nRAPID\nGOTO/12,0,-20\nFINI\n",
      generic());
  EXPECT_EQ(ok.diags, "");
  EXPECT_EQ(ok.nc,
            std::string(kHeader) +
                "G97 S500 M3\nG0 X24. Z5.\nX20. Z2.\nG33 Z-18. F2.\nG0 X24. Z-20.\nM30\n%\n");
}

TEST(InterpreterThreads, CoupledVariableLeadStartsEachMoveAtItsLead) {
  // INCR 0.1 per revolution from lead 2: after the first 20 mm the lead is
  // sqrt(2^2 + 2 x 0.1 x 20) = sqrt(8) = 2.828427 (K^2 grows by 2 dK per unit of travel).
  Machine m;
  std::string errors;
  ASSERT_TRUE(load_machine("sinumerik-840d", {CLPOST_SOURCE_DIR},
                           {"block_numbers.enabled=false", "templates.program_header=[]"},
                           shipped_controls(), m, errors))
      << errors;
  Posted p = post(
      "SPINDL/500,RPM,CLW\nRAPID\nGOTO/10,0,2\nCOUPLE/ON,MMPR,2,INCR,0.1\nGOTO/10,0,-18\n"
      "GOTO/10,0,-28\nCOUPLE/OFF\nFINI\n",
      m);
  EXPECT_EQ(p.diags, "");
  EXPECT_NE(p.nc.find("G34 Z-18 K2 F0.1\nZ-28 K2.828427 F0.1\n"), std::string::npos) << p.nc;
}

}  // namespace
}  // namespace clpost

namespace clpost {
namespace {

// THREAD/ON,...,CHAIN (threading.md section 11): the GOTOs up to THREAD/OFF are the contour, cut
// as one synchronized block per segment; the tool returns to P0's X (radius 20, X40.).
TEST(InterpreterThreads, ChainIsPlannedAndCutSegmentBySegment) {
  Posted p = post(
      "SPINDL/500,RPM,CLW\nRAPID\nGOTO/20,0,5\nTHREAD/ON,MMPR,1.5,DEPTH,0.5,OPTION,0,CHAIN\n"
      "GOTO/15,0,0\nGOTO/15,0,-10\nGOTO/16,0,-20\nTHREAD/OFF\nFINI\n",
      generic());
  EXPECT_EQ(p.diags, "");
  EXPECT_EQ(p.nc, std::string(kHeader) +
                      "G97 S500 M3\nG0 X40. Z5.\n(thread line 4: 1 passes, pitch 1.5, depth 0.5)\n"
                      "(pass 1 depth 0.5000 rough)\nZ0.\nX29.\nG33 Z-10. F1.5\nX31. Z-20. F1.5\n"
                      "G0 X40.\nZ0.\nM30\n%\n");
}

// 22 GOTOs: the error is at the 22nd (line 26), with a note at THREAD/ON; nothing is written.
TEST(InterpreterThreads, ChainOfTwentyTwoGotosIsAnErrorAtTheLast) {
  std::string cl = "SPINDL/500,RPM,CLW\nRAPID\nGOTO/20,0,5\nTHREAD/ON,MMPR,1.5,DEPTH,0.5,CHAIN\n";
  for (int i = 0; i < 22; ++i) cl += "GOTO/15,0," + std::to_string(-i) + "\n";
  cl += "THREAD/OFF\nFINI\n";
  Posted p = post(cl, generic());
  EXPECT_EQ(p.errors, 1u);
  EXPECT_EQ(p.diags,
            "t.cl:26:1: error: THREAD/ON,CHAIN takes at most 21 GOTOs before THREAD/OFF (20 "
            "segments); this is GOTO 22\n"
            "  GOTO/15,0,-21\n"
            "  ^\n"
            "t.cl:4:1: note: the thread sequence starts here\n"
            "  THREAD/ON,MMPR,1.5,DEPTH,0.5,CHAIN\n"
            "  ^\n");
}

}  // namespace
}  // namespace clpost

namespace clpost {
namespace {

// CATIA writes its tools' defaults as SPINDL/0.398,RPM: S0 would be a spindle that does not turn.
TEST(Interpreter, SpindleSpeedThatRoundsToZeroIsAnError) {
  Posted p = post("SPINDL/0.398,RPM,CLW\nFINI\n", generic());
  EXPECT_EQ(p.diags,
            "t.cl:1:8: error: spindle speed 0.398 would be written as S0 (formats.S: 0 "
            "decimals): the spindle would not turn\n"
            "  SPINDL/0.398,RPM,CLW\n"
            "         ^\n");
  EXPECT_EQ(post("SPINDL/0.5,RPM,CLW\nFINI\n", generic()).errors, 0u);  // rounds to S1
}

// Every message that shows an argument says what is there: an empty argument, the end of the
// statement after a last ',', a quoted text; never an empty ''.
TEST(Interpreter, MessagesSayWhatAnEmptyArgumentIs) {
  const std::pair<const char*, const char*> cases[] = {
      {"SPINDL/1000,,CLW",
       "t.cl:2:13: error: SPINDL/: expected a speed and RPM, SMM, SFM, CLW, CCLW, MAXRPM, OFF, ON, "
       "found an empty argument"},
      {"FEDRAT/0.1,MMPR,",
       "t.cl:2:17: error: FEDRAT/: expected a feed and one of MMPM, MMPR, IPM, IPR, PERMIN, "
       "PERREV, found the end of the statement after ','"},
      {"SYN/'A',",
       "t.cl:2:9: error: SYN/ takes quoted words, found the end of the statement after ','"},
      {"TLON,GOFWD/(CIRCLE/1,,2,3),ON,(LINE/0,0,0,1,0,0)",
       "t.cl:2:22: error: expected a number in the definition, found an empty argument"},
      {"PSIS/(PLANE/0,1,0,)",
       "t.cl:2:19: error: expected a number in the definition, found the end of the definition "
       "after ','"},
      {"TLON,GOFWD/,ON,(LINE/0,0,0,1,0,0)",
       "t.cl:2:12: error: expected a geometry definition, found an empty argument"},
      {"TLON,GOFWD/(CIRCLE/0,0,0,5),,(LINE/0,0,0,1,0,0)",
       "t.cl:2:29: error: expected TO, ON, PAST or TANTO before the check surface, found an empty "
       "argument"},
      {"PITCH/1.5,MULTRD,",
       "t.cl:2:11: error: expected the number of starts after MULTRD, found the end of the "
       "statement after ','"},
      {"PITCH/,1.5",
       "t.cl:2:7: error: expected a pitch word, found an empty argument; valid words: TPI, IPR, "
       "MMPR, PERREV, MULTRD, INCR, DECR"},
      {"THREAD/ON,,DEPTH,1",
       "t.cl:2:11: error: expected a thread parameter word, found an empty argument; valid words: "
       "DEPTH, CUTS, STEP, FINCUT, OPTION, CUTANG, TLANGL, ATANGL, CHAMFR, RETURN, CHAIN, TPI, "
       "IPR, MMPR, PERREV, MULTRD, INCR, DECR"},
      {"CYCLE/UNDCUT,DIAM,,",
       "t.cl:2:19: error: CYCLE/UNDCUT: DIAM needs a number, found an empty argument"},
      {"CYCLE/UNDCUT,,",
       "t.cl:2:14: error: CYCLE/UNDCUT: expected a word, found an empty argument; valid words: "
       "DIAM, AT, FORM"},
      {"CYCLE/,",
       "t.cl:2:7: error: CYCLE/ needs the cycle's kind first (DRILL, DEEP, BRKCHP, TAP, BORE, "
       "REAM, OFF, …), found an empty argument"},
      {"CYCLE/DRILL,,3",
       "t.cl:2:13: error: CYCLE/DRILL: expected a cycle word, found an empty argument"},
      {"CYCLE/DRILL,DEPTH,3,'X'",
       "t.cl:2:21: error: CYCLE/DRILL: expected a cycle word, found the text 'X'"},
      {"GOTO/1,0,", "t.cl:2:10: error: expected Z but found the end of the statement after ','"},
      {"AUXFUN/,", "t.cl:2:8: error: expected a code number but found an empty argument"},
      {"AUXFUN/5,,3",
       "t.cl:2:10: warning: AUXFUN/: the words after the number are not written (',3')"},
  };
  for (const auto& [cl, message] : cases) {
    Posted p = post("FROM/0,0,0\n" + std::string(cl) + "\nFINI\n", generic());
    EXPECT_EQ(p.diags.substr(0, p.diags.find('\n')), message) << cl;
    EXPECT_EQ(p.diags.find("''"), std::string::npos) << p.diags;
  }
  // A last empty argument is not words left unwritten.
  Posted p = post("COOLNT/ON,\nAUXFUN/5,\nFINI\n", generic());
  EXPECT_EQ(p.diags, "");
}

}  // namespace
}  // namespace clpost

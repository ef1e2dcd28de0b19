#include "interpreter/interpreter.h"

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
  EXPECT_TRUE(load_machine("generic-lathe", {CLPOST_SOURCE_DIR}, sets, m, errors)) << errors;
  return m;
}

Posted post(const std::string& cl, const Machine& m, PostOptions opts = {}) {
  Posted p;
  Diagnostics d("t.cl");
  StringSink sink;
  NcProgram prog(m, sink);
  Interpreter in(m, prog, d, opts);
  ClReader reader(std::string_view(cl), d);
  Statement st;
  while (reader.next(st)) in.statement(st);
  in.end_of_input(reader.line());
  p.nc = sink.out;
  p.diags = d.render_all();
  p.errors = d.error_count();
  return p;
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

TEST(Interpreter, YOnALatheWarnsOnce) {
  Posted p = post("RAPID\nGOTO/1,2,3\nRAPID\nGOTO/1,5,3\nFINI\n", generic());
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

TEST(Interpreter, TextStatements) {
  Posted p = post("PARTNO SHAFT 12\nPPRINT rough (OD)\nINSERT G65 P9010\nFINI\n", generic());
  EXPECT_EQ(p.nc, std::string(kHeader) + "(SHAFT 12)\n(rough OD)\nG65 P9010\nM30\n%\n");
}

TEST(Interpreter, ToolCoolantCompDwellStops) {
  Posted p = post(
      "LOADTL/4,ADJUST,14\nLOAD/TOOL,5\nCOOLNT/ON\nCOOLNT/OFF\nCUTCOM/LEFT\nCUTCOM/OFF\n"
      "DELAY/2\nSTOP\nOPSTOP\nFINI\n",
      generic());
  EXPECT_EQ(p.nc,
            std::string(kHeader) + "T0414\nT0505\nM8\nM9\nG41\nG40\nG4 X2.\nM0\nM1\nM30\n%\n");
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

TEST(Interpreter, DrillingCyclesAreRefusedNotDropped) {
  Posted p = post("CYCLE/DRILL,5,MMPM,100\nGOTO/0,0,0\nCYCLE/OFF\nFINI\n", generic());
  EXPECT_EQ(p.errors, 1u);
  EXPECT_NE(
      p.diags.find("t.cl:1:1: error: CYCLE/DRILL is not supported on machine 'generic-lathe'"),
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

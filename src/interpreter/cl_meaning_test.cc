// What the CL means (docs/cl-meaning.md), one test per decision, each found wrong before its fix
// (issue "Exit 0 means the program is right", cases A-G): the lines a program must have, on
// LinuxCNC (whose own rs274 the oracle test runs, tests/oracle/) and on Fanuc, and on every
// shipped machine a program that verifies or a located error.
#include <gtest/gtest.h>

#include "interpreter/post_test_util.h"
#include "machine/machine_test_util.h"

namespace clpost {
namespace {

using test::load;
using test::post;
using test::Posted;

constexpr const char* kHead = "UNITS/MM\nLOADTL/1\nSPINDL/500,RPM,CLW\nFEDRAT/0.2,MMPR\n";

std::string cl(const std::string& body) {
  return kHead + body + "FINI\n";
}

// `text` is in the program of `cl` on `machine`, posted without an error.
void expect_lines(const std::string& machine, const std::string& cl, const std::string& text) {
  const Posted p = post(cl, load(machine));
  EXPECT_EQ(p.errors, 0u) << machine << "\n" << p.diags;
  EXPECT_NE(p.nc.find(text), std::string::npos) << machine << ": no\n" << text << "in\n" << p.nc;
}

// A: a feed and a pitch given before UNITS/INCHES keep their physical value: 0.2 mm/rev is
// 0.007874 in/rev (F to 0.000001 in an inch program), the 1.5 mm lead 0.05905512 in.
TEST(ClMeaning, UnitsKeepTheFeedAndPitchAlreadyGiven) {
  const std::string a =
      cl("PITCH/1.5,MMPR\nGOTO/15,0,5\nUNITS/INCHES\nTHREAD/TURN\nGOTO/0.4,0,0.2\n"
         "GOTO/0.4,0,-1\n");
  expect_lines("linuxcnc-lathe", a, "G20\nX0.8 Z0.2 F0.007874\nG33 Z-1. K0.05905512\n");
  expect_lines("sinumerik-840d", a, "G700\nX0.8 Z0.2 F0.007874\n");
}

// HEIDENHAIN DIN reads a whole program in one unit, its PROGRAM HEAD's UNIT or else control
// parameter 1, set when the program is created (CNC PILOT 4290 manual, "Program section codes");
// "[INCH]" is a comment. A UNITS/ other than the machine's is an error naming the control (it was
// written as "[INCH]" and inch numbers, which the control read as mm: the oracle's HEIDENHAIN
// reader, tests/oracle/heidenhain_reader.cc).
TEST(ClMeaning, HeidenhainReadsAProgramInOneUnit) {
  const Posted p = post(cl("GOTO/10,0,5\nUNITS/INCHES\nGOTO/1,0,-1\n"), load("heidenhain-pilot"));
  EXPECT_EQ(p.errors, 1u);
  EXPECT_NE(p.diags.find("t.cl:6:7: error: machine 'heidenhain-pilot' (heidenhain) reads the whole "
                         "program in mm: the unit is set once, outside the program's blocks, and "
                         "UNITS/INCHES cannot change it (a control set to inches takes the "
                         "whole CL with the machine key units: in, e.g. --set units=in)"),
            std::string::npos)
      << p.diags;
  const Posted start =
      post("UNITS/INCHES\nLOADTL/1\nRAPID\nGOTO/1,0,1\nFINI\n", load("heidenhain-pilot"));
  EXPECT_EQ(start.errors, 1u) << start.diags;
  EXPECT_NE(start.diags.find("t.cl:1:7: error: machine 'heidenhain-pilot'"), std::string::npos);
  // The same inch CL on a control set to inches (units: in): posted, X a diameter in inches.
  const Posted inch = post("UNITS/INCHES\nLOADTL/1\nRAPID\nGOTO/1,0,1\nFINI\n",
                           load("heidenhain-pilot", {"units=in"}));
  EXPECT_EQ(inch.errors, 0u) << inch.diags;
  EXPECT_NE(inch.nc.find("G0 X2. Z1.\n"), std::string::npos) << inch.nc;
  expect_lines("heidenhain-pilot", cl("GOTO/10,0,5\nUNITS/MM\nGOTO/10,0,-1\n"), "Z-1.");
}

// A G97 speed above the limit of an earlier G96 (G26 S) raises the limit to itself: HEIDENHAIN's
// G26 caps a constant speed too (MANUALplus 4110 manual, 1.5 "Feed rate and spindle speed"). It
// turned at the 1500 rpm limit, not at the CL's 3000 (the oracle's HEIDENHAIN reader).
TEST(ClMeaning, HeidenhainRaisesTheSpeedLimitForAConstantSpeed) {
  expect_lines("heidenhain-pilot",
               cl("SPINDL/200,SMM,MAXRPM,1500,CLW\nGOTO/10,0,5\nSPINDL/3000,RPM\nGOTO/10,0,-1\n"),
               "G26 S1500\nG96 S200 M3\nG1 X20. Z5. G95 F0.2\nG97 S3000 M3\nG26 S3000\nZ-1.\n");
}

// B: every position is written in full after the switch: X20 (a 10 in radius), not X left out
// because it read 20 (mm) before.
TEST(ClMeaning, UnitsWriteEveryPositionAgain) {
  const std::string b = cl("GOTO/10,0,5\nUNITS/INCHES\nGOTO/10,0,-1\n");
  expect_lines("linuxcnc-lathe", b, "G20\nX20. Z-1. F0.007874\n");
  expect_lines("fanuc-0i-t", b, "G20\nX20. Z-1. F0.007874\n");
}

// An arc right after a switch: its start was where the tool is, in the new units (it was refused
// with "arc end point is not on the circle"); GODLTA moves from there too.
TEST(ClMeaning, UnitsConvertWhereTheToolIs) {
  const std::string arc =
      cl("GOTO/25.4,0,0\nUNITS/INCHES\nCIRCLE/0,0,0,0,1,0,1.0\nGOTO/0,0,-1\nGODLTA/0,0,-1\n");
  expect_lines("generic-lathe", arc, "G20\nG3 X0. Z-1. I-1. K0. F0.007874\nG1 Z-2.\n");
}

// C: RAPID makes the next motion a rapid; GOHOME is that motion.
TEST(ClMeaning, GohomeConsumesRapid) {
  const std::string c = cl("GOTO/20,0,5\nRAPID\nGOHOME/100,0,100\nGOTO/10,0,-5\n");
  expect_lines("fanuc-0i-t", c, "G28 U0.\nG28 W0.\nG1 X20. Z-5. G99 F0.2\n");
  expect_lines("linuxcnc-lathe", c, "G0 X200. Z100.\nG1 X20. Z-5.\n");
}

// An arc right after GOHOME on a machine whose home is its reference return (`G28 U0.`,
// `G28 W0.`): the control starts the arc at the reference position, which the program does not
// state, and I and K were measured from the point before GOHOME (found by the oracle's Fanuc
// reader, seed 7: `G3 … I14.914 K13.674` after `G28 W0.`). Refused at the GOTO; on LinuxCNC,
// where GOHOME/x,y,z is a rapid to the point, the arc starts there.
TEST(ClMeaning, AnArcDoesNotStartAtTheMachinesHome) {
  const std::string a = cl("GOTO/20,0,5\nGOHOME/30,0,10\nCIRCLE/30,0,0,0,1,0,10\nGOTO/20,0,0\n");
  for (const char* machine : {"fanuc-0i-t", "haas-st"}) {
    const Posted p = post(a, load(machine));
    EXPECT_EQ(p.diags,
              "t.cl:8:1: error: an arc cannot start at the machine's home (GOHOME at line 6 wrote "
              "its home template, a position the program does not state): move to the arc's "
              "start first\n  GOTO/20,0,0\n  ^\n")
        << machine;
  }
  expect_lines("linuxcnc-lathe", a, "G0 X60. Z10.\nG3 X40. Z0. I0. K-10.\n");
  expect_lines("fanuc-0i-t",
               cl("GOTO/20,0,5\nGOHOME/30,0,10\nGOTO/30,0,10\nCIRCLE/30,0,0,0,1,0,10\n"
                  "GOTO/20,0,0\n"),
               "G28 W0.\nG1 X60. Z10. G99 F0.2\nG3 X40. Z0. I0. K-10.\n");
}

// A G32 block's start angle is in the control's unit, 0.001 degree without a decimal point, as
// G92's (format thread_angle): the second start of a chained two-start thread is Q180000, not
// Q180. (Fanuc: "for a shift angle of 180 degrees, specify Q180000"; a decimal point is not
// allowed). Found by the oracle's Fanuc reader on samples/golden/fanuc-0i-t.
TEST(ClMeaning, AThreadBlocksStartAngleIsInThousandthsOfADegree) {
  const std::string t =
      "UNITS/MM\nLOADTL/5\nSPINDL/400,RPM,CLW\nFEDRAT/0.2,MMPR\nRAPID\nGOTO/20,0,6\n"
      "THREAD/ON,MMPR,1.5,MULTRD,2,DEPTH,0.92,CUTS,4,OPTION,0,CHAIN\nGOTO/12,0,0\n"
      "GOTO/12,0,-15\nGOTO/14,0,-25\nTHREAD/OFF\nFINI\n";
  for (const char* machine : {"fanuc-0i-t", "haas-st"}) {
    expect_lines(machine, t, "G32 Z-15. F3. Q0\n");
    expect_lines(machine, t, "G32 Z-15. F3. Q180000\n");
  }
}

// A hole cycle right after GOHOME on a machine whose home is its reference return: the cycle
// starts where the tool is (Fanuc's R is measured from it: R-8. from the reference, not from
// Z10), so the program moves to the hole's start first. Found by reading the Fanuc program
// after the arc case; the cycle block was written straight after G28 W0.
TEST(ClMeaning, AHoleCycleAfterTheMachinesHomeStartsFromItsStart) {
  const std::string h =
      "UNITS/MM\nLOADTL/2\nSPINDL/1500,RPM,CLW\nFEDRAT/0.1,MMPR\nRAPID\nGOTO/0,0,10\n"
      "GOHOME/0,0,10\nCYCLE/DRILL,DEPTH,3,MMPR,0.05,CLEAR,2\nGOTO/0,0,0\nCYCLE/OFF\nFINI\n";
  expect_lines("fanuc-0i-t", h,
               "G28 W0.\n(HOLE AT CL LINE 9: DRILLING TO Z-3.)\nG0 X0. Z10.\n"
               "G99 G83 X0. Z-3. R-8. F0.05\n");
  expect_lines("haas-st", h,
               "G28 W0.\n(HOLE AT CL LINE 9: DRILLING TO Z-3.)\nG0 X0. Z10.\n"
               "G99 G81 X0. Z-3. R2. F0.05\n");
}

// D: LinuxCNC's M6 stops the spindle; the CL left it turning, so it turns again before the next
// motion (and only then: a SPINDL/ after the LOADTL/ says it instead).
TEST(ClMeaning, AToolChangeLeavesTheSpindleAsTheClLeftIt) {
  expect_lines("linuxcnc-lathe", cl("GOTO/20,0,5\nLOADTL/2\nGOTO/18,0,-5\n"),
               "T2 M6 G43 H2\nG97 S500 M3\nG1 X36. Z-5.");
  expect_lines("linuxcnc-lathe", cl("GOTO/20,0,5\nLOADTL/2\nSPINDL/700,RPM,CLW\nGOTO/18,0,-5\n"),
               "T2 M6 G43 H2\nG97 S700 M3\nG1 X36. Z-5.");
  expect_lines("fanuc-0i-t", cl("GOTO/20,0,5\nLOADTL/2\nGOTO/18,0,-5\n"),
               "T0202\nG1 X36. Z-5. G99 F0.2\n");
}

// E: the first block after OPSKIP/OFF states the motion, X, Z and F again: with block delete on
// the control skipped X20 Z-5.
TEST(ClMeaning, OpskipRangesLeaveTheRestExact) {
  const std::string e = cl("GOTO/20,0,5\nOPSKIP/ON\nGOTO/10,0,-5\nOPSKIP/OFF\nGOTO/10,0,-10\n");
  expect_lines("linuxcnc-lathe", e, "/X20. Z-5.\nG1 X20. Z-10. G95 F0.2\n");
  expect_lines("fanuc-0i-t", e, "/X20. Z-5.\nG1 X20. Z-10. G99 F0.2\n");
  // A spindle or coolant change inside the range is stated again after it.
  const std::string s =
      cl("GOTO/20,0,5\nOPSKIP/ON\nSPINDL/800,RPM,CLW\nCOOLNT/FLOOD\nGOTO/10,0,-5\nOPSKIP/OFF\n"
         "GOTO/10,0,-10\n");
  expect_lines("fanuc-0i-t", s, "/G97 S800 M3\n/M8\n/X20. Z-5.\nG97 S800 M3\nM8\nG1 X20. Z-10.");
}

// F: MAXRPM stays in force; SPINDL/ON restores speed, mode, direction and limit.
TEST(ClMeaning, SpindleOnRestoresTheClsLimit) {
  const std::string f =
      "UNITS/MM\nLOADTL/1\nSPINDL/200,SMM,CLW,MAXRPM,1500\nFEDRAT/0.2,MMPR\nGOTO/20,0,5\n"
      "SPINDL/OFF\nSPINDL/ON\nSPINDL/180,SMM\nGOTO/10,0,-5\nFINI\n";
  expect_lines("linuxcnc-lathe", f, "M5\nG96 D1500 S200 M3\nG96 D1500 S180 M3\n");
  expect_lines("fanuc-0i-t", f, "M5\nG50 S1500\nG96 S200 M3\nG50 S1500\nG96 S180 M3\n");
}

// FEDRAT/f without a mode word keeps the mode in force (it became per minute).
TEST(ClMeaning, FedratWithoutAModeKeepsTheMode) {
  expect_lines("fanuc-0i-t", cl("GOTO/20,0,5\nFEDRAT/0.1\nGOTO/10,0,-5\n"),
               "G1 X40. Z5. G99 F0.2\nX20. Z-5. F0.1\n");
}

// G: LOADTL/n,ADJUST,m selects offset m: LinuxCNC G43 H12; a control whose tool change cannot
// say it refuses, at the offset.
TEST(ClMeaning, TheOffsetReachesTheProgramOrIsRefused) {
  const std::string g =
      "UNITS/MM\nLOADTL/2,ADJUST,12\nSPINDL/500,RPM,CLW\nFEDRAT/0.2,MMPR\nGOTO/20,0,5\nFINI\n";
  expect_lines("linuxcnc-lathe", g, "T2 M6 G43 H12\n");
  expect_lines("fanuc-0i-t", g, "T0212\n");
  const Posted h = post(g, load("heidenhain-pilot"));
  EXPECT_EQ(h.diags,
            "t.cl:2:17: error: machine 'heidenhain-pilot' cannot select offset 12 with tool 2: its "
            "tool_change template writes no {offset}, and the tool number selects offset 2\n"
            "  LOADTL/2,ADJUST,12\n"
            "                  ^\n");
}

}  // namespace
}  // namespace clpost

namespace clpost {
namespace {

// No comment carries a character the control reads as control: Fanuc's and Haas's '%' (the end
// of the program text) and the comment's own delimiters (nested parentheses end it early),
// whatever the machine file's comments.forbidden says.
TEST(ClMeaning, CommentsCarryNoControlCharacter) {
  const std::string c = "UNITS/MM\nPPRINT 50% OFF (A)\nFINI\n";
  for (const char* machine : {"fanuc-0i-t", "haas-st"}) {
    const test::Posted p = test::post(c, test::load(machine, {"comments.forbidden="}));
    EXPECT_NE(p.nc.find("(50 OFF A)"), std::string::npos) << machine << "\n" << p.nc;
  }
  EXPECT_NE(test::post(c, test::load("linuxcnc-lathe")).nc.find("(50% OFF A)"), std::string::npos);
}

}  // namespace
}  // namespace clpost

namespace clpost {
namespace {

// CIRCLE/ applies to the next GOTO only: a RAPID before that GOTO, or anything else that moves
// the tool in between, is an error at its CL line (a RAPID was ignored and GODLTA taken as the
// arc's end).
TEST(ClMeaning, ACircleIsForItsGotoOnly) {
  const std::string head = "UNITS/MM\nLOADTL/1\nSPINDL/500,RPM,CLW\nFEDRAT/0.2,MMPR\nGOTO/10,0,0\n";
  const Machine m = test::load("generic-lathe");
  EXPECT_EQ(test::post(head + "CIRCLE/0,0,0,0,1,0,10\nRAPID\nGOTO/0,0,-10\nFINI\n", m).diags,
            "t.cl:8:1: error: RAPID before the GOTO of CIRCLE/ (line 6): an arc is cut at the "
            "feed, there is no rapid arc\n  GOTO/0,0,-10\n  ^\n");
  EXPECT_EQ(
      test::post(head + "CIRCLE/0,0,0,0,1,0,10\nGODLTA/0,0,-1\nGOTO/0,0,-10\nFINI\n", m).diags,
      "t.cl:7:1: error: GODLTA between CIRCLE/ (line 6) and its GOTO: a CIRCLE applies to "
      "the next GOTO only\n  GODLTA/0,0,-1\n  ^\n");
  const test::Posted ok = test::post(head + "CIRCLE/0,0,0,0,1,0,10\nGOTO/0,0,-10\nFINI\n", m);
  EXPECT_EQ(ok.errors, 0u) << ok.diags;
  EXPECT_NE(ok.nc.find("G3 X0. Z-10. I-10. K0.\n"), std::string::npos) << ok.nc;
}

}  // namespace
}  // namespace clpost

namespace clpost {
namespace {

// An arc that the output's resolution rounds to nothing is a straight move, never a full circle:
// a centre 0.0004 mm off the start is I0. K0. at Fanuc's 3 decimals (a block the control reads
// as a full circle, or an arc of no radius it alarms on) while its end, X20.0016, is X20.002.
// LinuxCNC's I has 5 decimals: there the arc can be said, and is.
TEST(ClMeaning, AnArcRoundedToNoRadiusIsAStraightMove) {
  const std::string a = cl("GOTO/10,0,0\nCIRCLE/10.0004,0,0,0,1,0,0.0004\nGOTO/10.0008,0,0\n");
  const test::Posted p = test::post(a, test::load("fanuc-0i-t"));
  EXPECT_EQ(p.diags,
            "t.cl:7:1: warning: the arc of the CIRCLE/ at line 6 (radius 0.0004) is written with I "
            "and K zero at this machine's resolution: written as a straight move\n"
            "  GOTO/10.0008,0,0\n  ^\n");
  EXPECT_NE(p.nc.find("G1 X20. Z0. G99 F0.2\n(ARC OF RADIUS 0.0004 WRITTEN AS A STRAIGHT MOVE)\n"
                      "X20.002\nM30"),
            std::string::npos)
      << p.nc;
  const test::Posted l = test::post(a, test::load("linuxcnc-lathe"));
  EXPECT_EQ(l.diags, "");
  EXPECT_NE(l.nc.find("X20.0016 I0.0004 K0.\n"), std::string::npos) << l.nc;
}

// A feed per revolution with the spindle stopped never moves (the control waits for the
// spindle): an error at the move, not a program that exits 0 and stalls.
TEST(ClMeaning, AFeedPerRevolutionNeedsTheSpindle) {
  const std::string stopped = cl("GOTO/20,0,5\nSPINDL/OFF\nGOTO/10,0,-5\n");
  EXPECT_EQ(test::post(stopped, test::load("fanuc-0i-t")).diags,
            "t.cl:7:1: error: feed move per revolution with the spindle stopped (SPINDL/OFF at "
            "line 6): the control waits for the spindle and never moves; program SPINDL/ before "
            "it, or a feed per minute\n  GOTO/10,0,-5\n  ^\n");
  // A rapid, or a feed per minute, needs no spindle.
  const std::string rapid = cl("GOTO/20,0,5\nSPINDL/OFF\nRAPID\nGOTO/10,0,-5\n");
  EXPECT_EQ(test::post(rapid, test::load("fanuc-0i-t")).errors, 0u);
  const std::string per_min = cl("GOTO/20,0,5\nSPINDL/OFF\nFEDRAT/100,MMPM\nGOTO/10,0,-5\n");
  EXPECT_EQ(test::post(per_min, test::load("fanuc-0i-t")).errors, 0u);
  // Before any SPINDL/ the spindle is the machine's: no error.
  EXPECT_EQ(test::post("UNITS/MM\nLOADTL/1\nFEDRAT/0.2,MMPR\nGOTO/20,0,5\nFINI\n",
                       test::load("fanuc-0i-t"))
                .errors,
            0u);
}

}  // namespace
}  // namespace clpost

namespace clpost {
namespace {

// Inch output is written with the control's least input increment: X and Z to 0.0001 in on
// Fanuc, Haas and SINUMERIK (Control::inch_length_increment; HEIDENHAIN reads a program in one
// unit, HeidenhainReadsAProgramInOneUnit), and on the two machines
// without a registered control (their post files' inch_decimals); LinuxCNC's doubles keep its 5
// decimals. A feed per revolution to what each control takes: 0.2 mm/rev is 0.0078740 in/rev,
// F0.007874 (Haas reads F to 0.0001 in: F0.0079). Before: X2.469 Z-0.543 and F0.0079.
TEST(ClMeaning, InchOutputHasTheControlsLeastIncrement) {
  const std::string in = cl("GOTO/10,0,5\nUNITS/INCHES\nGOTO/1.23456,0,-0.54321\n");
  expect_lines("fanuc-0i-t", in, "G20\nX2.4691 Z-0.5432 F0.007874\n");
  expect_lines("haas-st", in, "G20\nX2.4691 Z-0.5432 F0.0079\n");
  // SINUMERIK: G700, whose F is read in inches too (G70's F is in the basic system, MD10240).
  expect_lines("sinumerik-840d", in, "G700\nX2.4691 Z-0.5432 F0.007874\n");
  expect_lines("generic-lathe", in, "X2.4691 Z-0.5432 F0.007874\n");
  expect_lines("nct-2000t", in, "X2.4691 Z-0.5432 F0.007874\n");
  expect_lines("linuxcnc-lathe", in, "G20\nX2.46912 Z-0.54321 F0.007874\n");
  // Back to mm: 3 decimals again.
  expect_lines("fanuc-0i-t",
               cl("GOTO/10,0,5\nUNITS/INCHES\nGOTO/1.23456,0,-0.54321\nUNITS/MM\n"
                  "GOTO/10.12345,0,-1\n"),
               "G20\nX2.4691 Z-0.5432 F0.007874\nG21\nX20.247 Z-1. F0.2\n");
  // An arc's centre too: I and K to 0.0001 in.
  expect_lines("fanuc-0i-t",
               cl("UNITS/INCHES\nGOTO/1,0,0\nCIRCLE/0.1234,0,0,0,1,0,0.8766\nGOTO/0.1234,0,"
                  "-0.8766\n"),
               "G3 X0.2468 Z-0.8766 I-0.8766 K0.\n");
}

}  // namespace
}  // namespace clpost

namespace clpost {
namespace {

// SINUMERIK's feed type and spindle mode are one G group (group 15): G96 is feed per revolution
// at constant cutting speed, G97 feed per revolution at a constant speed, G94/G95 end constant
// cutting speed, and a change of feed type deletes F; LIMS limits G97's speed too (the SINUMERIK
// Programming Manual Fundamentals, "Constant cutting speed"; controls/sinumerik). The oracle's
// reader of SINUMERIK programs (tests/oracle/sinumerik_reader.h) found each. Before:
// "G96 S200 M3" then "X30 Z-5" (G96 had made the feed 100 mm/rev with F deleted: alarm 10860),
// "G94 F100" under G96 (constant cutting speed ended), "G97 S900 M3" at LIMS=2500's limit, and
// then "X24 Z-8" at feed per revolution.
TEST(ClMeaning, SinumerikWritesTheFeedTypeWithTheSpindleMode) {
  const std::string in =
      "UNITS/MM\nLOADTL/1\nFEDRAT/100,MMPM\nSPINDL/800,RPM,CLW\nGOTO/20,0,5\n"
      "SPINDL/200,SMM,MAXRPM,2500\nGOTO/15,0,-5\nSPINDL/900,RPM\nGOTO/12,0,-8\n"
      "FEDRAT/0.1,MMPR\nGOTO/10,0,-9\nSPINDL/150,SMM\nFEDRAT/120,MMPM\nGOTO/9,0,-10\nFINI\n";
  expect_lines("sinumerik-840d", in,
               "G97 S800 LIMS=4000 M3\nG1 X40 Z5 G94 F100\nLIMS=2500\nG96 S200 M3\n"
               "X30 Z-5 G961 F100\nG97 S900 LIMS=4000 M3\nX24 Z-8 G94 F100\nX20 Z-9 G95 F0.1\n"
               "LIMS=2500\nG96 S150 M3\nX18 Z-10 G961 F120\n");
  // Feed per revolution throughout: G96 and G97 keep it, F is not written again.
  expect_lines("sinumerik-840d", cl("GOTO/20,0,5\nSPINDL/200,SMM\nGOTO/15,0,-5\n"),
               "G1 X40 Z5 G95 F0.2\nLIMS=4000\nG96 S200 M3\nX30 Z-5\n");
  // A hole cycle's and CYCLE96's feed under constant surface speed: G96, not G95 (which ended
  // it before the cycle).
  const std::string cycles =
      cl("SPINDL/200,SMM\nGOTO/20,0,5\nGOTO/0,0,3\nCYCLE/DRILL,DEPTH,5,MMPR,0.05,CLEAR,2\n"
         "GOTO/0,0,0\nCYCLE/OFF\nGOTO/20,0,5\nCYCLE/UNDCUT,DIAM,20,AT,-10,FORM,A\n");
  expect_lines("sinumerik-840d", cycles, "G17 G96 F0.05\nCYCLE81(3, 2, 0, -5)\n");
  expect_lines("sinumerik-840d", cycles, "G96 F0.2\nCYCLE96(20, -10, \"A\")\n");
  // A machine without limits.max_rpm: the speed is its own limit (before: an error, "template
  // 'spindle_rpm' needs {max_rpm}").
  const Posted p = post(cl("GOTO/20,0,5\n"), load("sinumerik-840d", {"limits.max_rpm=0"}));
  EXPECT_EQ(p.errors, 0u) << p.diags;
  EXPECT_NE(p.nc.find("G97 S500 LIMS=500 M3\n"), std::string::npos) << p.nc;
}

}  // namespace
}  // namespace clpost

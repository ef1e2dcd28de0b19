// Holes on the spindle axis: CYCLE/DRILL … in the forms CAM systems write, per control.
#include <gtest/gtest.h>

#include "interpreter/post_test_util.h"

namespace clpost {
namespace {

using test::load;
using test::post;
using test::Posted;

// The body of a program: what lies between the start template's lines and the end's.
std::string body(const std::string& nc, const std::string& first, const std::string& last) {
  const size_t a = nc.find(first);
  const size_t b = nc.rfind(last);
  if (a == std::string::npos || b == std::string::npos || b < a) return "<no body>\n" + nc;
  return nc.substr(a, b - a);
}

// SolidWorks CAM's drilling form: depth 12 below the top at Z0, R plane 2 above it, back to
// the retract plane Z20 (RTRCTO 20 above the top).
constexpr const char* kSolidWorksDrill =
    "SPINDL/1000,RPM,CLW\nRAPID\nGOTO/0,0,20\n"
    "CYCLE/INIT\nCYCLE/DRILL,FEDTO,12.,MMPM,100.,RAPTO,2.,RTRCTO,20.,DWELL,0\n"
    "GOTO/0,0,0\nCYCLE/OFF\nFINI\n";

TEST(HoleCycles, DrillOnAMachineWithoutCyclesIsMoves) {
  Posted p = post(kSolidWorksDrill, load("generic-lathe"));
  EXPECT_EQ(p.diags, "");
  EXPECT_EQ(body(p.nc, "G97", "M30"),
            "G97 S1000 M3\nG0 X0. Z20.\n(hole at CL line 6: drilling to Z-12.)\nZ2.\n"
            "G1 Z-12. G94 F100.\nG0 Z20.\n");
}

TEST(HoleCycles, DrillOnHaasIsG81WithTheRPlaneAbsolute) {
  Posted p = post(kSolidWorksDrill, load("haas-st"));
  EXPECT_EQ(p.diags, "");
  EXPECT_EQ(body(p.nc, "G97 S", "M30"),
            "G97 S1000 M3\nG0 X0. Z20.\n(HOLE AT CL LINE 6: DRILLING TO Z-12.)\n"
            "G98 G81 X0. Z-12. R2. F100.\nG80\n");
}

// SolidWorks' DEEP2 with a first peck of 5 and then pecks of 2 to Z-8.6: a cycle's peck word is
// one number, so the moves are written. Pecks count from the R plane Z3 (11.6 to the bottom):
// 5 -> Z-2, out to R, back in to 4.5 (0.5 clearance, generic) -> Z-1.5; 7 -> Z-4, back to -3.5;
// 9 -> Z-6, back to -5.5; 11 -> Z-8, back to -7.5; 11.6 -> Z-8.6; out to Z20.
constexpr const char* kDeep2 =
    "SPINDL/1000,RPM,CLW\nRAPID\nGOTO/0,0,20\n"
    "CYCLE/DEEP2,FEDTO,8.6,1STPECK,5.,SUBPECK,2.,MMPM,100.,RAPTO,3.,RTRCTO,20.\n"
    "GOTO/0,0,0\nCYCLE/OFF\nFINI\n";

TEST(HoleCycles, PecksAreExpandedWhenTheCycleCannotSayThem) {
  const std::string moves =
      "Z3.\nG1 Z-2. G94 F100.\nG0 Z3.\nZ-1.5\nG1 Z-4.\nG0 Z3.\nZ-3.5\nG1 Z-6.\nG0 Z3.\n"
      "Z-5.5\nG1 Z-8.\nG0 Z3.\nZ-7.5\nG1 Z-8.6\nG0 Z20.\n";
  Posted g = post(kDeep2, load("generic-lathe"));
  EXPECT_EQ(g.diags, "");
  EXPECT_EQ(body(g.nc, "(hole", "M30"), "(hole at CL line 5: peck drilling to Z-8.6)\n" + moves);
  Posted f = post(kDeep2, load("fanuc-0i-t"));
  EXPECT_EQ(body(f.nc, "(HOLE", "M30"),
            "(HOLE AT CL LINE 5: PECK DRILLING TO Z-8.6)\n(HOLE_PECK NOT USED: FIRST PECK 5 "
            "DIFFERS FROM THE NEXT PECKS 2: 'HOLE_PECK' HAS ONE PECK WORD. MOVES INSTEAD)\n"
            "Z3.\nG1 Z-2. G98 F100.\nG0 Z3.\nZ-1.5\nG1 Z-4.\nG0 Z3.\nZ-3.5\nG1 Z-6.\nG0 Z3.\n"
            "Z-5.5\nG1 Z-8.\nG0 Z3.\nZ-7.5\nG1 Z-8.6\nG0 Z20.\n");
}

// Creo's DEEP form with constant pecks on the Fanuc 0i-T: G83 with R from the initial level
// (Z10) to the R point (Z2): -8, Q 5 mm in micrometres.
constexpr const char* kCreoDeep =
    "SPINDL/800,RPM,CLW\nFEDRAT/0.1,MMPR\nRAPID\nGOTO/0,0,10\n"
    "CYCLE / DEEP, DEPTH, 20.0, STEP, 5.0, MMPR, 0.1, CLEAR,$\n 2.0\nGOTO/0,0,0\nCYCLE/OFF\nFINI\n";

TEST(HoleCycles, FanucPeckDrillingIsG83) {
  Posted p = post(kCreoDeep, load("fanuc-0i-t"));
  EXPECT_EQ(p.diags, "");
  EXPECT_EQ(
      body(p.nc, "(HOLE", "M30"),
      "(HOLE AT CL LINE 7: PECK DRILLING TO Z-20.)\nG99 G83 X0. Z-20. R-8. Q5000 F0.1\nG80\n");
}

TEST(HoleCycles, SiemensPeckDrillingIsCycle83InG17) {
  Posted p = post(kCreoDeep, load("sinumerik-840d"));
  EXPECT_EQ(p.diags, "");
  EXPECT_EQ(body(p.nc, "; hole", "M30"),
            "; hole at CL line 7: peck drilling to Z-20\nG17 G95 F0.1\n"
            "CYCLE83(10, 2, 0, -20, , , 5, 5, 0, 0, 1, 1)\nG18\n");
}

// Tapping M10x1.5 at 500 rpm: the feed is the lead per revolution.
constexpr const char* kTap =
    "SPINDL/500,RPM,CLW\nRAPID\nGOTO/0,0,10\nCYCLE/TAP,DEPTH,15,PITCH,1.5,MMPM,750,CLEAR,3\n"
    "GOTO/0,0,0\nCYCLE/OFF\nFINI\n";

TEST(HoleCycles, RigidTappingPerControl) {
  Posted l = post(kTap, load("linuxcnc-lathe"));
  EXPECT_EQ(l.diags, "");
  EXPECT_EQ(body(l.nc, "(hole", "M2"),
            "(hole at CL line 5: tapping to Z-15.)\nG0 X0. Z3.\nG33.1 Z-15. K1.5\nG0 Z10.\n");
  Posted f = post(kTap, load("fanuc-0i-t"));
  EXPECT_EQ(body(f.nc, "(HOLE", "M30"),
            "(HOLE AT CL LINE 5: TAPPING TO Z-15.)\nM29 S500\nG99 G84 X0. Z-15. R-7. F1.5\nG80\n");
  // Without rigid tapping the Fanuc writes G84 for a floating holder.
  Posted ff = post(kTap, load("fanuc-0i-t", {"holes.rigid_tapping=false"}));
  EXPECT_EQ(body(ff.nc, "(HOLE", "M30"),
            "(HOLE AT CL LINE 5: TAPPING TO Z-15.)\nG99 G84 X0. Z-15. R-7. F1.5\nG80\n");
}

TEST(HoleCycles, TappingAsMovesReversesTheSpindle) {
  Posted p = post(kTap, load("generic-lathe"));
  EXPECT_EQ(p.diags, "");
  EXPECT_EQ(body(p.nc, "(hole", "M30"),
            "(hole at CL line 5: tapping to Z-15.)\nZ3.\nG1 Z-15. G95 F1.5\nG97 S500 M4\n"
            "Z3.\nG97 S500 M3\nG0 Z10.\n");
}

TEST(HoleCycles, ATapFeedThatIsNotLeadTimesRpmIsAnError) {
  std::string cl = kTap;
  cl.replace(cl.find("750"), 3, "700");
  Posted p = post(cl, load("generic-lathe"));
  EXPECT_EQ(p.errors, 1u);
  EXPECT_NE(p.diags.find("t.cl:5:1: error: CYCLE/TAP of line 4: feed 700 per minute is not the "
                         "tap's lead 1.5 x 500 rpm = 750: the tap would strip the thread"),
            std::string::npos)
      << p.diags;
}

// Pro/E's tap: 20 threads per inch in an inch program, 600 rpm: lead 0.05 in, F0.05 per rev.
TEST(HoleCycles, ProETapWithTpi) {
  Posted p = post(
      "UNITS/INCHES\nSPINDL/600,RPM,CLW\nRAPID\nGOTO/0,0,1\n"
      "CYCLE / TAP, DEPTH, 1.550000, TPI, 20.000000, CLEAR, 0.250000\nGOTO/0,0,0\nCYCLE / OFF\n"
      "FINI\n",
      load("haas-st"));
  EXPECT_EQ(p.diags, "");
  EXPECT_EQ(body(p.nc, "(HOLE", "M30"),
            "(HOLE AT CL LINE 6: TAPPING TO Z-1.55)\nG99 G84 X0. Z-1.55 R0.25 F0.05\nG80\n");
}

// A left-hand tap (spindle CCLW) on the Haas, whose G84 turns the spindle M3 itself: moves.
TEST(HoleCycles, LeftHandTapOnHaasIsMoves) {
  std::string cl = kTap;
  cl.replace(cl.find("CLW"), 3, "CCLW");
  Posted p = post(cl, load("haas-st"));
  EXPECT_EQ(p.diags, "");
  EXPECT_EQ(body(p.nc, "(HOLE", "M30"),
            "(HOLE AT CL LINE 5: TAPPING TO Z-15.)\n(HOLE_TAP NOT USED: A LEFT-HAND TAP, SPINDLE "
            "COUNTER-CLOCKWISE: 'HOLE_TAP' TURNS THE SPINDLE CLOCKWISE, HOLES.TAP_TURNS_CW. MOVES "
            "INSTEAD)\nZ3.\nG1 Z-15. G99 F1.5\nG97 S500 M3\nZ3.\nG97 S500 M4\nG0 Z10.\n");
}

// CATIA's short form: total depth and clearance, the feed in force.
TEST(HoleCycles, CatiaTapUsesTheFeedInForce) {
  Posted p = post(
      "SPINDL/400,RPM,CLW\nFEDRAT/1.5,MMPR\nRAPID\nGOTO/0,0,1\nCYCLE/TAP,   20.000000,    "
      "1.000000\nGOTO  /    0.00000,    0.00000,    0.00000\nCYCLE/OFF\nFINI\n",
      load("fanuc-0i-t"));
  EXPECT_EQ(p.diags, "");
  EXPECT_EQ(body(p.nc, "(HOLE", "M30"),
            "(HOLE AT CL LINE 6: TAPPING TO Z-20.)\nM29 S400\nG99 G84 X0. Z-20. R0. F1.5\nG80\n");
}

TEST(HoleCycles, AHoleOffTheCentreLineNeedsLiveTooling) {
  Posted p = post(
      "SPINDL/1000,RPM,CLW\nRAPID\nGOTO/17.5,0,20\n"
      "CYCLE/DRILL,FEDTO,5.,MMPM,125.,RAPTO,3.,RTRCTO,100.\nGOTO/17.5,0,0\nCYCLE/OFF\nFINI\n",
      load("generic-lathe"));
  EXPECT_EQ(p.errors, 1u);
  EXPECT_NE(p.diags.find("t.cl:5:1: error: CYCLE/DRILL hole at CL line 5 is 17.5 off the "
                         "spindle's centre line (GOTO/17.5,0,0): a hole off the centre line "
                         "needs live tooling, which a lathe post does not write"),
            std::string::npos)
      << p.diags;
}

TEST(HoleCycles, ChipBreakingAndDwell) {
  // BRKCHP on LinuxCNC: G73 with Q; a DRILL with a dwell of 0.5 s: G82 P0.5.
  Posted p = post(
      "SPINDL/1000,RPM,CLW\nRAPID\nGOTO/0,0,10\nCYCLE/BRKCHP,DEPTH,10,STEP,2,MMPR,0.05,CLEAR,1\n"
      "GOTO/0,0,0\nCYCLE/DRILL,DEPTH,3,MMPR,0.05,CLEAR,1,DWELL,0.5\nGOTO/0,0,0\nCYCLE/OFF\nFINI\n",
      load("linuxcnc-lathe"));
  EXPECT_EQ(p.diags, "");
  EXPECT_EQ(body(p.nc, "(hole", "M2"),
            "(hole at CL line 5: chip-breaking drilling to Z-10.)\nG17\n"
            "G98 G95 G73 X0. Y0 Z-10. R1. Q2. F0.05\nG80\nG18\n"
            "(hole at CL line 7: drilling to Z-3.)\nG17\nG98 G95 G82 X0. Y0 Z-3. R1. P0.5 F0.05\n"
            "G80\nG18\n");
}

// NX names the kind as a word of DRILL: CYCLE/DRILL,DEEP,RAPTO,c,FEDTO,d,MMPM,f,STEP,p.
TEST(HoleCycles, NxDeepDrill) {
  Posted p = post(
      "SPINDL/800,RPM,CLW\nRAPID\nGOTO/0,0,10\n"
      "CYCLE/DRILL,DEEP,RAPTO,2.0000,FEDTO,20.0000,MMPM,80.0000,STEP,5\nGOTO/0,0,0\nCYCLE/OFF\n"
      "FINI\n",
      load("haas-st"));
  EXPECT_EQ(p.diags, "");
  EXPECT_EQ(body(p.nc, "(HOLE", "M30"),
            "(HOLE AT CL LINE 5: PECK DRILLING TO Z-20.)\nG98 G83 X0. Z-20. R2. Q5. F80.\nG80\n");
}

TEST(HoleCycles, AThousandPecksAtMost) {
  // From the R plane Z2 to Z-20: 22 / 0.01 = 2200 pecks.
  Posted p = post(
      "SPINDL/800,RPM,CLW\nRAPID\nGOTO/0,0,10\nCYCLE/DEEP,DEPTH,20,STEP,0.01,MMPM,80,CLEAR,2\n"
      "GOTO/0,0,0\nCYCLE/OFF\nFINI\n",
      load("generic-lathe"));
  EXPECT_NE(p.diags.find("t.cl:5:1: error: CYCLE/DEEP hole at CL line 5: pecks of 0.01 over 22 "
                         "make 2200 pecks, more than 1000"),
            std::string::npos)
      << p.diags;
}

TEST(HoleCycles, BadCycleWords) {
  Posted p = post("CYCLE/DRILL,DEPTH,MMPM,100\nCYCLE/DEEP,FROB,3\nCYCLE/BORE,MMPM,5\nFINI\n",
                  load("generic-lathe"));
  EXPECT_EQ(p.errors, 3u);
  EXPECT_NE(p.diags.find("t.cl:1:13: error: CYCLE/DRILL: DEPTH needs a number after it"),
            std::string::npos)
      << p.diags;
  EXPECT_NE(p.diags.find("t.cl:2:12: error: CYCLE/DEEP: unknown word 'FROB'"), std::string::npos)
      << p.diags;
  EXPECT_NE(p.diags.find("t.cl:3:1: error: CYCLE/BORE needs a depth greater than 0"),
            std::string::npos)
      << p.diags;
}

// CYCLE/DRILL continued with `$` onto an empty line: the empty last argument is shown after its
// ',' on the cycle's line and said to be the end of the statement, never an empty ''.
TEST(HoleCycles, AContinuationOntoAnEmptyLineIsTheEndOfTheStatement) {
  Posted p = post("CYCLE/DRILL,$\n\nGOTO/0,0,0\nCYCLE/OFF\nFINI\n", load("generic-lathe"));
  EXPECT_EQ(p.errors, 1u);
  EXPECT_EQ(p.diags,
            "t.cl:1:13: error: CYCLE/DRILL: expected a cycle word, found the end of the statement "
            "after ','\n"
            "  CYCLE/DRILL,$\n"
            "              ^\n");
}

// ---- CATIA with ICAM's table (reference/cam/ICAM_MM_pptable_cycles_and_millturn_excerpt.txt) --

constexpr const char* kIcamStart = "SPINDL/600,RPM,CLW\nRAPID\nGOTO/0,0,10\n";

std::string icam(const std::string& cycle) {
  return std::string(kIcamStart) + cycle + "\nGOTO/0,0,0\nCYCLE/OFF\nFINI\n";
}

// RETURN is CATIA's jump distance above the CLEAR plane: RETURN,0 leaves the tool at the R plane
// (Z2), not at its start (Z10).
TEST(HoleCycles, IcamReturnZeroRetractsToTheRPlane) {
  Posted p = post(icam("CYCLE/DRILL,DEPTH,4.6,MMPR,0.08,CLEAR,2,RETURN,0"), load("generic-lathe"));
  EXPECT_EQ(p.diags, "");
  EXPECT_EQ(body(p.nc, "(hole", "M30"),
            "(hole at CL line 5: drilling to Z-4.6)\nZ2.\nG1 Z-4.6 G95 F0.08\nG0 Z2.\n");
}

// RETURN,5 with CLEAR,2: the retract plane is 7 above the hole's top; the Haas cycle returns to
// its initial level Z10, then the tool goes to Z7.
TEST(HoleCycles, IcamReturnIsMeasuredFromTheClearPlane) {
  Posted p = post(icam("CYCLE/DRILL,DEPTH,4.6,MMPR,0.08,CLEAR,2,RETURN,5"), load("haas-st"));
  EXPECT_EQ(p.diags, "");
  EXPECT_EQ(
      body(p.nc, "(HOLE", "M30"),
      "(HOLE AT CL LINE 5: DRILLING TO Z-4.6)\nG99 G81 X0. Z-4.6 R2. F0.08\nG80\nG0 X0. Z7.\n");
}

// REV,2 at 600 rpm dwells 0.2 s; SEC (CATIA's other delay unit) and DWELL are seconds.
TEST(HoleCycles, IcamDwellUnits) {
  const std::string rev = icam("CYCLE/DRILL,DEPTH,3,MMPR,0.05,CLEAR,1,RETURN,0,REV,2");
  Posted l = post(rev, load("linuxcnc-lathe"));
  EXPECT_EQ(l.diags, "");
  EXPECT_EQ(body(l.nc, "(hole", "M2"),
            "(hole at CL line 5: drilling to Z-3.)\nG17\nG98 G95 G82 X0. Y0 Z-3. R1. P0.2 F0.05\n"
            "G80\nG18\nG0 X0. Z1.\n");
  Posted g = post(rev, load("generic-lathe"));
  EXPECT_EQ(g.diags, "");
  EXPECT_EQ(body(g.nc, "(hole", "M30"),
            "(hole at CL line 5: drilling to Z-3.)\nZ1.\nG1 Z-3. G95 F0.05\nG4 X0.2\nG0 Z1.\n");
  Posted sec =
      post(icam("CYCLE/DRILL,DEPTH,3,MMPR,0.05,CLEAR,1,RETURN,0,SEC,0.2"), load("linuxcnc-lathe"));
  EXPECT_EQ(sec.nc, l.nc);
  // Revolutions need a set RPM to become seconds.
  Posted css = post(
      "SPINDL/200,SMM,CLW\nRAPID\nGOTO/0,0,10\n"
      "CYCLE/DRILL,DEPTH,3,MMPR,0.05,CLEAR,1,RETURN,0,REV,2\nGOTO/0,0,0\nCYCLE/OFF\n"
      "FINI\n",
      load("generic-lathe"));
  EXPECT_EQ(css.diags,
            "t.cl:5:1: error: CYCLE/DRILL of line 4 dwells 2 revolutions (REV): the spindle must "
            "turn at a set RPM (SPINDL/n,RPM) to write the dwell in seconds\n"
            "  GOTO/0,0,0\n"
            "  ^\n");
}

// ICAM's chip breaking: CLEAR,c,backoff. LinuxCNC's G73 backs off by its own 0.254 mm
// (holes.peck_clearance): a back-off of 0.3 is written as moves, 0.254 as the cycle.
TEST(HoleCycles, IcamChipBreakBackOff) {
  Posted m = post(icam("CYCLE/BRKCHP,DEPTH,5,STEP,2,MMPR,0.05,CLEAR,1,0.3,RETURN,0"),
                  load("linuxcnc-lathe"));
  EXPECT_EQ(m.diags, "");
  EXPECT_EQ(body(m.nc, "(hole", "M2"),
            "(hole at CL line 5: chip-breaking drilling to Z-5.)\n(hole_chip_break not used: each "
            "peck backs off 0.3, the control by its own setting holes.peck_clearance 0.254. moves "
            "instead)\nZ1.\nG1 Z-1. G95 F0.05\nG0 Z-0.7\nG1 Z-3.\nG0 Z-2.7\nG1 Z-5.\nG0 Z1.\n");
  Posted c = post(icam("CYCLE/BRKCHP,DEPTH,5,STEP,2,MMPR,0.05,CLEAR,1,0.254,RETURN,0"),
                  load("linuxcnc-lathe"));
  EXPECT_EQ(c.diags, "");
  EXPECT_EQ(body(c.nc, "(hole", "M2"),
            "(hole at CL line 5: chip-breaking drilling to Z-5.)\nG17\n"
            "G98 G95 G73 X0. Y0 Z-5. R1. Q2. F0.05\nG80\nG18\nG0 X0. Z1.\n");
}

// NC_COUNTERSINKING: CYCLE/FACE, a drill to depth with a dwell.
TEST(HoleCycles, IcamCountersinkIsADrillWithADwell) {
  Posted p =
      post(icam("CYCLE/FACE,DEPTH,1,MMPR,0.05,CLEAR,1,RETURN,0,SEC,0.5"), load("linuxcnc-lathe"));
  EXPECT_EQ(p.diags, "");
  EXPECT_EQ(body(p.nc, "(hole", "M2"),
            "(hole at CL line 5: drilling to Z-1.)\nG17\nG98 G95 G82 X0. Y0 Z-1. R1. P0.5 F0.05\n"
            "G80\nG18\nG0 X0. Z1.\n");
}

// INVERS (NC_REVERSE_THREADING) with the spindle counter-clockwise: the left-hand tap it says.
TEST(HoleCycles, IcamReverseTapWithTheSpindleCounterClockwise) {
  Posted p = post(
      "SPINDL/600,RPM,CCLW\nRAPID\nGOTO/0,0,10\n"
      "CYCLE/TAP,DEPTH,10,MMPR,1.5,CLEAR,2,INVERS\nGOTO/0,0,0\nCYCLE/OFF\nFINI\n",
      load("generic-lathe"));
  EXPECT_EQ(p.diags, "");
  EXPECT_EQ(body(p.nc, "(hole", "M30"),
            "(hole at CL line 5: tapping to Z-10.)\nZ2.\nG1 Z-10. G95 F1.5\nG97 S600 M3\nZ2.\n"
            "G97 S600 M4\nG0 Z10.\n");
}

// What cannot be written is an error at the word that asks for it.
TEST(HoleCycles, IcamWordsThatCannotBeWritten) {
  const std::pair<const char*, const char*> cases[] = {
      {"CYCLE/BORE,ORIENT,90,DEPTH,10,MMPR,0.1,CLEAR,2,0.2,RETURN,0,REV,1",
       "t.cl:4:12: error: CYCLE/BORE: ORIENT (CATIA's Boring Spindle Stop: the spindle stopped at "
       "an angle and the tool moved off the wall before it leaves) cannot be written for a hole "
       "on a lathe's spindle axis, where the part turns and the tool does not\n"
       "  CYCLE/BORE,ORIENT,90,DEPTH,10,MMPR,0.1,CLEAR,2,0.2,RETURN,0,REV,1\n"
       "             ^\n"},
      {"CYCLE/BORE,DEPTH,10,MMPR,0.1,CLEAR,2,INVERS",
       "t.cl:4:38: error: CYCLE/BORE: INVERS (ICAM writes it on CYCLE/TAP for CATIA's Reverse "
       "Threading) would make this a back boring, from the far side of the part: not written for "
       "a hole on a lathe's spindle axis\n"
       "  CYCLE/BORE,DEPTH,10,MMPR,0.1,CLEAR,2,INVERS\n"
       "                                       ^\n"},
      {"CYCLE/TAP,DEPTH,10,MMPR,1.5,CLEAR,2,INVERS",
       "t.cl:4:37: error: CYCLE/TAP: INVERS (CATIA's Reverse Threading, a left-hand tap) while the "
       "spindle turns clockwise (SPINDL of line 1): whether INVERS reverses it is not written "
       "down, so the tap's direction is in doubt; program SPINDL/…,CCLW for the tap\n"
       "  CYCLE/TAP,DEPTH,10,MMPR,1.5,CLEAR,2,INVERS\n"
       "                                      ^\n"},
      {"CYCLE/DRILL,DEPTH,4.6,MMPR,0.08,RETURN,0",
       "t.cl:4:33: error: CYCLE/DRILL: RETURN is a distance above the CLEAR plane, and the cycle "
       "has no CLEAR\n"
       "  CYCLE/DRILL,DEPTH,4.6,MMPR,0.08,RETURN,0\n"
       "                                  ^\n"},
      {"CYCLE/DRILL,DEPTH,4.6,MMPR,0.08,RAPTO,2,RTRCTO,20,RETURN,0",
       "t.cl:4:51: error: CYCLE/DRILL: RETURN and RTRCTO both give the plane the tool retracts to\n"
       "  CYCLE/DRILL,DEPTH,4.6,MMPR,0.08,RAPTO,2,RTRCTO,20,RETURN,0\n"
       "                                                    ^\n"},
      {"CYCLE/BRKCHP,DEPTH,5,STEP,2,MMPR,0.05,CLEAR,1,0,RETURN,0",
       "t.cl:4:47: error: CYCLE/BRKCHP: the chip-break back-off 0 after CLEAR must be positive\n"
       "  CYCLE/BRKCHP,DEPTH,5,STEP,2,MMPR,0.05,CLEAR,1,0,RETURN,0\n"
       "                                                ^\n"},
      {"CYCLE/CIRCUL,DEPTH,5,PITCH,1,DIAMET,10,CLEAR,3,RAPTO,1,OPTION,1,STEP,1,CUTS,1,MMPM,100",
       "t.cl:4:1: error: CYCLE/CIRCUL is not supported on machine 'generic-lathe': its holes would "
       "be lost; post the drilling with a milling post or output it as motion\n"
       "  CYCLE/CIRCUL,DEPTH,5,PITCH,1,DIAMET,10,CLEAR,3,RAPTO,1,OPTION,1,STEP,1,CUTS,1,MMPM,100\n"
       "  ^\n"},
  };
  for (const auto& [cycle, diags] : cases) {
    Posted p = post(icam(cycle), load("generic-lathe"));
    EXPECT_EQ(p.errors, 1u) << cycle;
    EXPECT_EQ(p.diags, diags);
  }
}

// Each hole carries the diameter the CL gave its tool (the setup sheet's): CUTTER/ before the
// tool change it describes (CATIA, SolidWorks), CUTTER/ after a change before the tool moves,
// NX's TLDATA/DRILL,MILL,d; a tool without any has none (not the last tool's), and UNITS/
// converts what was given.
TEST(HoleCycles, EachHoleCarriesItsToolsDiameter) {
  const char* cl =
      "FROM/0,0,20\nCUTTER/8.5\nLOADTL/1\nSPINDL/1000,RPM,CLW\n"        // lines 1-4
      "CYCLE/DRILL,DEPTH,10,MMPM,100,CLEAR,2\nGOTO/0,0,0\nCYCLE/OFF\n"  // line 6: 8.5
      "LOADTL/2\nCUTTER/6\n"                                            // T2's own
      "CYCLE/DRILL,DEPTH,10,MMPM,100,CLEAR,2\nGOTO/0,0,0\nCYCLE/OFF\n"  // line 11: 6
      "LOADTL/3\n"                                                      // none given
      "CYCLE/DRILL,DEPTH,10,MMPM,100,CLEAR,2\nGOTO/0,0,0\nCYCLE/OFF\n"  // line 15: none
      "TLDATA/DRILL,MILL,12.7,0,100,118,35\nLOADTL/4\nUNITS/INCHES\n"
      "CYCLE/DRILL,DEPTH,0.5,IPM,4,CLEAR,0.1\nGOTO/0,0,0\nCYCLE/OFF\nFINI\n";  // line 21
  PostedText r = post_text(cl, load("generic-lathe"), "t.cl");
  ASSERT_EQ(r.diags.error_count(), 0u) << r.diags.render_all();
  ASSERT_EQ(r.summary.holes.size(), 4u);
  EXPECT_EQ(r.summary.holes[0].cl_line, 6u);
  EXPECT_EQ(r.summary.holes[0].tool_diameter, 8.5);
  EXPECT_EQ(r.summary.holes[1].tool_diameter, 6);
  EXPECT_EQ(r.summary.holes[2].tool_diameter, std::nullopt);
  // 12.7 mm is 0.5 in.
  ASSERT_TRUE(r.summary.holes[3].tool_diameter);
  EXPECT_NEAR(*r.summary.holes[3].tool_diameter, 0.5, 1e-12);
}

}  // namespace
}  // namespace clpost

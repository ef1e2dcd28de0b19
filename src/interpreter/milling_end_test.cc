// The end of a live tool's milling (live_path.cc, LivePath::leave_milling; docs/millturn.md, "What
// a tool change does"): the same before a tool change and at the program end. And cutter
// compensation against the plane: the plane before G41/G42, G40 before the plane goes back.
#include <gtest/gtest.h>

#include <string>

#include "interpreter/post_test_util.h"

namespace clpost {
namespace {

using test::load;
using test::post;
using test::Posted;

// Face milling at C0: a line from the part's (10, 5) to (20, 10) 1 deep, then a rapid retract,
// then FINI. The line lies on the ray at 26.5651 degrees (atan 5/10), so without Y it is one
// X Z move at that C: radius sqrt(125) = 11.1803 (diameter 22.3607) to 22.3607 (44.7214).
constexpr const char* kFaceThenFini =
    "LOADTL/3,MILL\nSPINDL/2000,RPM,CLW\nROTABL/0,CAXIS\nRAPID\nGOTO/10,5,2\n"
    "FEDRAT/100,MMPM\nGOTO/10,5,-1\nGOTO/20,10,-1\nRAPID\nGOTO/20,10,2\nFINI\n";

// haas-st-20y: X Y Z in G17 at C0. At FINI, as before a tool change, Y back to 0 (a rapid from
// the CL's retract, Z2) and G18, the live tool stopped (M135); then C unclamped (M15) and
// disengaged (M155) before M30. Before: M30 came right after the retract, the live tool running,
// C engaged, G17 and Y10 in force.
TEST(MillingEnd, FaceMillingThenFiniOnHaasSt20y) {
  Posted p = post(kFaceThenFini, load("haas-st-20y"));
  EXPECT_EQ(p.errors, 0u) << p.diags;
  EXPECT_EQ(p.nc,
            "%\nO00001\nG18 G21 G40 G97\nT0303\nM154\nM133 P2000\nG0 C0.\nM14\nG17\n"
            "G0 X20. Y5. Z2.\nG98 G1 X20. Y5. Z-1. F100.\nG1 X40. Y10. Z-1. F100.\n"
            "G0 X40. Y10. Z2.\nG0 Y0.\nG18\nM135\nM15\nM155\nM30\n%\n");
}

// fanuc-0i-tf-live (no Y): X Z C. The XZC move unclamped C (M74), so the end is the live tool's
// stop (M72) and C's release (M75) before M30; no G18 or Y (never left).
TEST(MillingEnd, FaceMillingThenFiniOnFanuc0iTfLive) {
  Posted p = post(kFaceThenFini, load("fanuc-0i-tf-live"));
  EXPECT_EQ(p.errors, 0u) << p.diags;
  EXPECT_EQ(p.nc,
            "%\nO0001\nG18 G21 G40 G97\nT0303\nM76\nM70 S2000\nG0 C0.\nM73\nM74\n"
            "G0 X22.361 Z2. C26.565\nG1 X22.361 Z-1. G98 F100.\nX44.721\nG0 Z2.\nM72\nM75\n"
            "M30\n%\n");
}

// linuxcnc-lathe-c: the live tool is spindle 1, stopped (M5 $1) before M2; C has no engage or
// clamp code. rs274 runs it: tests/rs274_test.cc, Rs274.MillTurnEndsMillingBeforeTheProgramEnd.
TEST(MillingEnd, FaceMillingThenFiniOnLinuxcncLatheC) {
  Posted p = post(kFaceThenFini, load("linuxcnc-lathe-c"));
  EXPECT_EQ(p.errors, 0u) << p.diags;
  EXPECT_EQ(p.nc,
            "%\nG7 G18 G21 G90 G40 G80\nT3 M6 G43 H3\nM3 $1 S2000\nG0 C0.\n"
            "G0 X22.36068 Z2. C26.5651\nG1 X22.36068 Z-1. G94 F100.\nX44.72136\nG0 Z2.\n"
            "M5 $1\nM2\n%\n");
}

// One end in one place: before a tool change the same blocks as at FINI (C stays engaged for a
// next milling tool); a turning tool loaded and the program ended without its SPINDL: C is
// released at the end all the same. A file without FINI ends the same way (with its warning).
TEST(MillingEnd, ToolChangeAndProgramEndEndTheMillingAlike) {
  std::string cl = kFaceThenFini;
  cl.replace(cl.find("FINI"), 4, "LOADTL/1\nFINI");
  Posted p = post(cl, load("haas-st-20y"));
  EXPECT_EQ(p.errors, 0u) << p.diags;
  EXPECT_NE(p.nc.find("G0 X40. Y10. Z2.\nG0 Y0.\nG18\nM135\nT0101\nM15\nM155\nM30\n%\n"),
            std::string::npos)
      << p.nc;
  std::string no_fini = kFaceThenFini;
  no_fini.erase(no_fini.find("FINI"));
  Posted q = post(no_fini, load("haas-st-20y"));
  EXPECT_EQ(q.errors, 0u) << q.diags;
  EXPECT_NE(q.nc.find("G0 X40. Y10. Z2.\nG0 Y0.\nG18\nM135\nM15\nM155\nM30\n%\n"),
            std::string::npos)
      << q.nc;
  EXPECT_NE(q.diags.find("t.cl:10: warning: the file ends without FINI"), std::string::npos)
      << q.diags;
}

// A radial tool (axis 1,0,0) on haas-st-20y: C at the index, X its depth. CUTCOM/LEFT writes
// G19 (the plane of the peripheral work) before G41 — before, G41 came first and G19 at the
// arc, under compensation (Fanuc alarm PS0037, rs274 "Cannot change planes with cutter radius
// compensation on"). The half circle about X from Y5 to Y-5 (centre Y0 Z-10, counter-clockwise
// about +X) is G3 with J-5 K0. The CL leaves compensation on and retracts to radius 40: G40
// before Y0 and G18.
constexpr const char* kRadialComp =
    "LOADTL/3,MILL\nSPINDL/2000,RPM,CLW\nROTABL/0,CAXIS\nRAPID\nGOTO/30,0,-10,1,0,0\n"
    "FEDRAT/100,MMPM\nGOTO/20,0,-10,1,0,0\nCUTCOM/LEFT\nGOTO/20,5,-10,1,0,0\n"
    "CIRCLE/20,0,-10,1,0,0,5\nGOTO/20,-5,-10,1,0,0\nGOTO/40,-5,-10,1,0,0\nFINI\n";

TEST(MillingEnd, PlaneBeforeCompensationAndG40BeforeThePlaneGoesBack) {
  Posted p = post(kRadialComp, load("haas-st-20y"));
  EXPECT_EQ(p.errors, 0u) << p.diags;
  EXPECT_NE(p.nc.find("G0 X60. Z-10.\nG1 X40. G98 F100.\nG19\nG41\n"
                      "G98 G1 X40. Y5. Z-10. F100.\nG3 X40. Y-5. Z-10. J-5. K0. F100.\n"
                      "G1 X80. Y-5. Z-10. F100.\nG40\nG0 Y0.\nG18\nM135\nM15\nM155\nM30\n"),
            std::string::npos)
      << p.nc;
}

// A face tool's CUTCOM/RIGHT before any motion: G17 before G42 (before: G42, then G17 at the
// first move). CUTCOM/OFF in the CL: one G40, none added at the end.
TEST(MillingEnd, FaceToolsPlaneBeforeCompensation) {
  std::string cl = kFaceThenFini;
  cl.replace(cl.find("RAPID"), 5, "CUTCOM/RIGHT\nRAPID");
  cl.replace(cl.rfind("RAPID"), 5, "CUTCOM/OFF\nRAPID");
  Posted p = post(cl, load("haas-st-20y"));
  EXPECT_EQ(p.errors, 0u) << p.diags;
  EXPECT_NE(p.nc.find("M14\nG17\nG42\nG0 X20. Y5. Z2.\nG98 G1 X20. Y5. Z-1. F100.\n"
                      "G1 X40. Y10. Z-1. F100.\nG40\nG0 X40. Y10. Z2.\nG0 Y0.\nG18\nM135\n"),
            std::string::npos)
      << p.nc;
  EXPECT_EQ(p.nc.find("G40\n", p.nc.find("G40\n") + 1), std::string::npos) << p.nc;
}

// Under compensation in G19, an arc about Z (G17) would change the plane: a located error at
// its GOTO, nothing silently written.
TEST(MillingEnd, AnArcInAnotherPlaneUnderCompensationIsALocatedError) {
  std::string cl = kRadialComp;
  cl.replace(cl.find("CIRCLE/20,0,-10,1,0,0,5\nGOTO/20,-5,-10"), 38,
             "CIRCLE/20,0,-15,0,0,1,5\nGOTO/20,-5,-15");
  Posted p = post(cl, load("haas-st-20y"));
  EXPECT_EQ(p.errors, 1u) << p.diags;
  EXPECT_NE(p.diags.find("t.cl:11:1: error: milling motion with live tool 3 (loaded at line 1): "
                         "the arc is not in G19, the plane cutter compensation (CUTCOM) is on "
                         "in, and a control refuses a plane change under G41/G42: give the tool "
                         "centre's path (CUTCOM/OFF) (docs/millturn.md)"),
            std::string::npos)
      << p.diags;
}

// Polar interpolation (G112) with CUTCOM/LEFT still on at FINI: G40 first (a control refuses
// to leave the mode or change the plane under G41/G42), then G113, then G18, then the live tool
// stopped and C released. The points are the part's at C0 (no ROTABL): (10,0), (0,10), (-10,0).
TEST(MillingEnd, CompensationEndsBeforePolarInterpolationAndThePlane) {
  Posted p = post(
      "LOADTL/3,MILL\nSPINDL/2000,RPM,CLW\nFEDRAT/100,MMPM\nRAPID\nGOTO/10,0,2\n"
      "GOTO/10,0,-1\nCUTCOM/LEFT\nGOTO/0,10,-1\nGOTO/-10,0,-1\nFINI\n",
      load("haas-st-20y", {"millturn.polar_interpolation=true"}));
  EXPECT_EQ(p.errors, 0u) << p.diags;
  EXPECT_NE(p.nc.find("G112\nG17\nG0 X10. Y0. Z2.\nG98 G1 X10. Y0. Z-1. F100.\nG41\n"
                      "G1 X0. Y10. Z-1. F100.\nG1 X-10. Y0. Z-1. F100.\nG40\nG113\nG18\nM135\n"
                      "M155\nM30\n"),
            std::string::npos)
      << p.nc;
}

// A radial tool (axis along the part's Y, so C90) approaches at the part's Y 15 (X30., Y0.),
// plunges to 8 (X16.), moves 3 along Y, and the CL retracts it sideways to the part's (19, 0):
// X0. Y-19. at its depth Z2, the cutter on the centre line beside the part. The post's own
// Y 0 from there (before: `G0 X0. Y-19. Z2.`, then `G0 Y0.`) would take the tip to X0. Y0.,
// through the part: X goes back out first to the approach's X30. (issue 25, PATH1's T3 -> T1).
TEST(MillingEnd, ARadialToolGoesOutToItsApproachXBeforeY0) {
  Posted p = post(
      "LOADTL/3,MILL\nSPINDL/2000,RPM,CLW\nMULTAX/ON\nRAPID\nGOTO/0,15,2,0,1,0\n"
      "FEDRAT/100,MMPM\nGOTO/0,8,2,0,1,0\nGOTO/3,8,2,0,1,0\nRAPID\n"
      "GOTO/19,0,2,0,1,0\nLOADTL/1\nFINI\n",
      load("haas-st-20y"));
  EXPECT_EQ(p.errors, 0u) << p.diags;
  EXPECT_EQ(p.nc,
            "%\nO00001\nG18 G21 G40 G97\nT0303\nM154\nM133 P2000\nG0 C90.\nM14\n"
            "G0 X30. Y0. Z2.\nG98 G1 X16. Y0. Z2. F100.\nG1 X16. Y-3. Z2. F100.\n"
            "G0 X0. Y-19. Z2.\nG0 X30.\nG0 Y0.\nM135\nT0101\nM15\nM155\nM30\n%\n");
}

}  // namespace
}  // namespace clpost

// A live tool's face milling (milling_motion.cc, docs/millturn.md): X Z C computed by the post
// on machines without Y, X Y Z in G17 at the C index on haas-st-20y.
#include <fmt/format.h>
#include <gtest/gtest.h>

#include "interpreter/post_test_util.h"

namespace clpost {
namespace {

using test::load;
using test::post;
using test::Posted;

// A quarter circle of radius 10 about the centre at Z-1 (index 0), then a line through the
// centre line from (0, 10) to (0, -10).
constexpr const char* kQuarterAndSlot =
    "LOADTL/3,MILL\nSPINDL/2000,RPM,CLW\nROTABL/0,CAXIS\nRAPID\nGOTO/10,0,2\n"
    "FEDRAT/100,MMPM\nGOTO/10,0,-1\nCIRCLE/0,0,-1,0,0,1,10\nGOTO/0,10,-1\nGOTO/0,-10,-1\nFINI\n";

// The arc (radius 10) as chords within half the tolerance (0.0025): 2.5 degrees each (sagitta
// 10 (1 - cos 1.25°) = 0.00238), each one C move at X20. Fanuc takes F over the combined move
// (degrees as mm): the chord is 20 sin 1.25° = 0.43630 mm at 100 mm/min, 0.0043630 min, the C
// move 2.5 in that time: F573.0032. The slot through the centre: straight in at C90 to X0, C
// turned 180 there in two steps (the shortest way of a rollover control), straight out at C270.
TEST(MillingMotion, XzcArcAndCentreCrossingOnFanuc) {
  Posted p = post(kQuarterAndSlot, load("fanuc-0i-tf-live"));
  EXPECT_EQ(p.errors, 0u) << p.diags;
  EXPECT_NE(p.nc.find("G0 C0.\nM73\nG0 X20. Z2.\nG1 Z-1. G98 F100.\nM74\n"
                      "G1 X20. Z-1. C2.5 F573.0032\nG1 X20. Z-1. C5. F573.0032\n"),
            std::string::npos)
      << p.nc;
  EXPECT_NE(p.nc.find("G1 X20. Z-1. C90. F573.0032\nG1 X0. Z-1. G98 F100.\n"
                      "G1 X0. Z-1. C180. F100.\nG1 X0. Z-1. C270. F100.\nG1 X20. Z-1. G98 F100.\n"
                      "M72\nM75\nM30\n"),
            std::string::npos)
      << p.nc;
}

// LinuxCNC: G93, F = 1 / minutes of the chord: 100 / 0.43630 = 229.2013; a C turn on the centre
// line at the feed read as degrees per minute (90 degrees: F1.1111); G94 again for the moves
// that do not turn C (exact along X and Z).
TEST(MillingMotion, XzcInInverseTimeOnLinuxcnc) {
  Posted p = post(kQuarterAndSlot, load("linuxcnc-lathe-c"));
  EXPECT_EQ(p.errors, 0u) << p.diags;
  EXPECT_NE(p.nc.find("G1 Z-1. G94 F100.\nG93 G1 X20. Z-1. C2.5 F229.2013\n"
                      "G1 X20. Z-1. C5. F229.2013\n"),
            std::string::npos)
      << p.nc;
  EXPECT_NE(p.nc.find("G1 X20. Z-1. C90. F229.2013\nG1 X0. Z-1. G94 F100.\n"
                      "G93 G1 X0. Z-1. C180. F1.1111\nG1 X0. Z-1. C270. F1.1111\n"
                      "G1 X20. Z-1. G94 F100.\n"),
            std::string::npos)
      << p.nc;
}

// A continuous C (LinuxCNC) keeps turning the same way: a second lap of the circle goes on from
// C360 to C720, where a rollover control (Fanuc) writes 0 <= C < 360. A full circle of radius
// 10 is 141 chords of 360/141 = 2.5532 degrees (20 sin 1.2766° = 0.44558 mm: G93 F224.427).
TEST(MillingMotion, ContinuousCGoesOnRolloverCWraps) {
  const std::string cl =
      "LOADTL/3,MILL\nSPINDL/2000,RPM,CLW\nROTABL/0,CAXIS\nRAPID\nGOTO/10,0,-1\n"
      "FEDRAT/100,MMPM\nCIRCLE/0,0,-1,0,0,1,10\nGOTO/10,0,-1\nCIRCLE/0,0,-1,0,0,1,10\n"
      "GOTO/10,0,-1\nFINI\n";
  Posted l = post(cl, load("linuxcnc-lathe-c"));
  EXPECT_EQ(l.errors, 0u) << l.diags;
  EXPECT_NE(l.nc.find("C360. F224.427\nG1 X20. Z-1. C362.5532 F224.427\n"), std::string::npos)
      << l.nc;
  EXPECT_NE(l.nc.find("C720. F224.427\nM5 $1\nM2\n"), std::string::npos) << l.nc;
  Posted f = post(cl, load("fanuc-0i-tf-live"));
  EXPECT_EQ(f.errors, 0u) << f.diags;
  EXPECT_NE(f.nc.find("C357.447 F573.0052\nG1 X20. Z-1. C0. F573.0051\nG1 X20. Z-1. C2.553 "),
            std::string::npos)
      << f.nc;
  EXPECT_EQ(f.nc.find("C360."), std::string::npos) << f.nc;
}

// haas-st-20y: the face work in G17 at the C index (clamped), X a diameter, Y and Z as the
// CL's; the arc (counter-clockwise about +Z) is G3 with I and J from its start; Y0 and G18 before
// the tool change and at the program end (milling_end_test.cc).
TEST(MillingMotion, FaceMillingInXyzOnHaasSt20y) {
  Posted p = post(kQuarterAndSlot, load("haas-st-20y"));
  EXPECT_EQ(p.errors, 0u) << p.diags;
  EXPECT_NE(p.nc.find("M154\nM133 P2000\nG0 C0.\nM14\nG17\nG0 X20. Y0. Z2.\n"
                      "G98 G1 X20. Y0. Z-1. F100.\nG3 X0. Y10. Z-1. I-10. J0. F100.\n"
                      "G1 X0. Y-10. Z-1. F100.\nG0 Y0.\nG18\nM135\nM15\nM155\nM30\n"),
            std::string::npos)
      << p.nc;
  Posted q = post(std::string(kQuarterAndSlot)
                      .replace(std::string(kQuarterAndSlot).find("FINI"), 4, "LOADTL/1\nFINI"),
                  load("haas-st-20y"));
  EXPECT_NE(q.nc.find("G1 X0. Y-10. Z-1. F100.\nG0 Y0.\nG18\nM135\nT0101\n"), std::string::npos)
      << q.nc;
}

// What is not written: polar interpolation asked for, a feed per revolution without the live
// tool's rpm, a CIRCLE/ about another axis: located errors, the tool's later motions not
// reported again.
TEST(MillingMotion, WhatIsNotWrittenIsALocatedError) {
  // fanuc-0i-tf-live ships G12.1 with C the virtual axis, but how it takes X in the mode is not
  // pinned (machines/fanuc-0i-tf-live.yaml quotes the sources that disagree).
  Posted polar =
      post(kQuarterAndSlot, load("fanuc-0i-tf-live", {"millturn.polar_interpolation=true"}));
  EXPECT_EQ(polar.errors, 1u) << polar.diags;
  EXPECT_NE(polar.diags.find("t.cl:5:1: error: milling motion with live tool 3 (loaded at line "
                             "1): machine 'fanuc-0i-tf-live' asks for polar interpolation "
                             "(millturn.polar_interpolation: true), and millturn.polar_x is "
                             "unknown: how the control takes X in the mode (a radius or a "
                             "diameter) is not pinned"),
            std::string::npos)
      << polar.diags;
  Posted axis = post(
      "LOADTL/3,MILL\nSPINDL/2000,RPM,CLW\nROTABL/0,CAXIS\nRAPID\nGOTO/10,0,2\nFEDRAT/100,MMPM\n"
      "CIRCLE/0,0,-1,1,0,0,10\nGOTO/0,10,-1\nFINI\n",
      load("linuxcnc-lathe-c"));
  EXPECT_NE(axis.diags.find("t.cl:7:1: error: milling motion with live tool 3 (loaded at line 1): "
                            "CIRCLE/ about the axis (1, 0, 0), not the spindle axis"),
            std::string::npos)
      << axis.diags;
  // Per revolution of the live tool: 0.05 x 2000 rpm = 100 mm/min, as the MMPM program.
  std::string per_rev = kQuarterAndSlot;
  per_rev.replace(per_rev.find("FEDRAT/100,MMPM"), 15, "FEDRAT/0.05,MMPR");
  Posted rev = post(per_rev, load("linuxcnc-lathe-c"));
  EXPECT_EQ(rev.errors, 0u) << rev.diags;
  EXPECT_NE(rev.nc.find("G93 G1 X20. Z-1. C2.5 F229.2013\n"), std::string::npos) << rev.nc;
}

}  // namespace
}  // namespace clpost

namespace clpost {
namespace {

// A radial live tool (tool axis 1,0,0) on haas-st-20y: C stays at the index (the axis is +X
// already), X is the depth (diameter), Y across; CATIA's HELICAL/ of MillTurn3x_PATH1 (lines
// 83-87: about the X axis, radius 0.75, 180 degrees from Y0.75 to Y-0.75, X 0.00737 deeper,
// INDIRV +Z at the start: positive about +X) is G3 in G19 with J and K from its start. The
// CL leaves the tool at its depth: before the post's Y0 it goes out to its approach's X18.858.
TEST(MillingMotion, RadialToolAndCatiaHelicalOnHaasSt20y) {
  const std::string cl =
      "LOADTL/3,MILL\nSPINDL/3000,RPM,CLW\nFEDRAT/150,MMPM\nRAPID\nGOTO/9.42906,0.75,3,1,0,0\n"
      "GOTO/3.92323,0.75,3.0,1,0,0\n"
      "HELICAL/CENTER,3.92323,0.00000,3.00000,INDIRV,0.00000,0.00000,1.00000,AXIS,1.00000,"
      "0.00000,0.00000,PITCH,0.01474,RADIUS,0.75000,ANGLE,180.00000,HEIGHT,0.00737,ROUND,"
      "0.50000,END,3.91586,-0.75000,3.00000\n"
      "GOTO/3.90178,-0.75,1.5,1,0,0\nLOADTL/1\nFINI\n";
  Posted p = post(cl, load("haas-st-20y"));
  EXPECT_EQ(p.errors, 0u) << p.diags;
  EXPECT_NE(p.nc.find("G0 C0.\nM14\nG0 X18.858 Y0.75 Z3.\nG98 G1 X7.846 Y0.75 Z3. F150.\nG19\n"
                      "G3 X7.832 Y-0.75 Z3. J-0.75 K0. F150.\nG1 X7.804 Y-0.75 Z1.5 F150.\n"
                      "G0 X18.858\nG0 Y0.\nG18\nM135\n"),
            std::string::npos)
      << p.nc;
  // The tool from the other side (tool axis -1,0,0, as linear_3x_PATH2's tool 33): C turns 180
  // past the index and the point is turned back: GOTO/-3.92906,0.1,z is X7.858 Y-0.1.
  Posted q = post(
      "LOADTL/3,MILL\nSPINDL/3000,RPM,CLW\nROTABL/0,CAXIS\nFEDRAT/150,MMPM\nRAPID\n"
      "GOTO/-9.42906,0,-2.78441,-1,0,0\nGOTO/-3.92906,0.1,-2.78441,-1,0,0\nFINI\n",
      load("haas-st-20y"));
  EXPECT_EQ(q.errors, 0u) << q.diags;
  // (A rollover control turns 180 degrees in two steps of 90, the way the shortest is.)
  EXPECT_NE(q.nc.find("G0 C0.\nM14\nM15\nG0 C90.\nG0 C180.\nM14\nG0 X18.858 Y0. Z-2.784\n"
                      "G98 G1 X7.858 Y-0.1 Z-2.784 F150.\n"),
            std::string::npos)
      << q.nc;
}

}  // namespace
}  // namespace clpost

namespace clpost {
namespace {

// TLON,GOFWD of a milling tool around a cylinder about X (CATIA, MillTurn3x_PATH1 line 197):
// from (3.5, 0.75, 3), INDIRV +Z, ON,2,INTOF the plane z 3 (the start on it is the first): the
// half turn to (3.5, -0.75, 3), G3 in G19. PSIS/ across X is skipped. TO a check surface is a
// located error (the tool's radius in 3D is not offset).
TEST(MillingMotion, GeometricMotionAroundACylinderOnHaasSt20y) {
  const std::string head =
      "LOADTL/3,MILL\nSPINDL/3000,RPM,CLW\nFEDRAT/150,MMPM\nRAPID\nGOTO/9,0.75,3,1,0,0\n"
      "GOTO/3.5,0.75,3,1,0,0\nPSIS/(PLANE/(POINT/3.5,0,3),PERPTO,(VECTOR/1,0,0))\n"
      "INDIRV/0,0,1\n";
  const std::string check =
      "(PLANE/PERPTO,(PLANE/(POINT/3.5,0,3),PERPTO,(VECTOR/1,0,0)),(POINT/3.5,0,3),"
      "(POINT/3.5,-0.75,3))\n";
  Posted p = post(head + "TLON,GOFWD/(CYLNDR/3.5,0,3,1,0,0,0.75),ON,2,INTOF," + check + "FINI\n",
                  load("haas-st-20y"));
  EXPECT_EQ(p.errors, 0u) << p.diags;
  EXPECT_NE(p.nc.find("G1 X7. Y0.75 Z3. F150.\nG19\nG3 X7. Y-0.75 Z3. J-0.75 K0. F150.\n"),
            std::string::npos)
      << p.nc;
  Posted to = post(head + "TLON,GOFWD/(CYLNDR/3.5,0,3,1,0,0,0.75),TO," + check + "FINI\n",
                   load("haas-st-20y"));
  EXPECT_NE(to.diags.find("t.cl:9:40: error: GOFWD/ of a milling tool: only ON a check plane is "
                          "written (TO, PAST and TANTO need the tool's radius in 3D)"),
            std::string::npos)
      << to.diags;
}

}  // namespace
}  // namespace clpost

namespace clpost {
namespace {

// A face tool on the -Z side (tool axis 0,0,-1: MillTurn3x_PATH1's tool 5, line 870, whose
// turning has the part at Z >= 0): the CL frame is written as it is, so X (diameter) Y Z and C
// are those a 0,0,1 tool gets, and only CUTCOM's side differs: APT's LEFT is seen from the tool
// (from -Z), G41/G42 in G17 from +Z, so LEFT is G42. CATIA's (CIRCLE/0,0.15,0,0.6) after AUTOPS
// lies in the plane normal to the tool axis: from (-0.6, 0.15), INDIRV +Y, ON the plane through
// the line x 0: a quarter turn to (0, 0.75), clockwise seen from +Z (G2), I0.6 J0 from the
// start.
std::string face_tool_cl(const std::string& k) {
  const std::string axis = ",0,0," + k + "\n";
  return "LOADTL/5,MILL\nSPINDL/3000,RPM,CLW\nROTABL/30,CAXIS\nFEDRAT/150,MMPM\nRAPID\n"
         "GOTO/-0.1,0.05,-5.5" +
         axis + "GOTO/-0.1,0.05,0" + axis + "CUTCOM/LEFT,1\nGOTO/-0.6,0.15,0" + axis +
         "AUTOPS\nINDIRV/0,1,0\n"
         "TLON,GOFWD/(CIRCLE/0,0.15,0,0.6),ON,(LINE/0,0.15,0,0,0.75,0)\n"
         "GOTO/1.5,0.75,0.01\nCUTCOM/OFF\nGOTO/0.1,0.05,0.01\nFINI\n";
}

TEST(MillingMotion, FaceToolFromMinusZOnHaasSt20y) {
  const std::string path =
      "G0 C30.\nM14\nG17\nG0 X-0.2 Y0.05 Z-5.5\nG98 G1 X-0.2 Y0.05 Z0. F150.\n{}\n"
      "G1 X-1.2 Y0.15 Z0. F150.\nG2 X0. Y0.75 Z0. I0.6 J0. F150.\nG1 X3. Y0.75 Z0.01 F150.\n"
      "G40\nG1 X0.2 Y0.05 Z0.01 F150.\n";
  Posted minus = post(face_tool_cl("-1"), load("haas-st-20y"));
  EXPECT_EQ(minus.errors, 0u) << minus.diags;
  EXPECT_NE(minus.nc.find(fmt::format(fmt::runtime(path), "G42")), std::string::npos) << minus.nc;
  EXPECT_NE(minus.diags.find("t.cl:8:1: note: CUTCOM/ with a live tool whose axis is 0,0,-1: the "
                             "CL's side is seen from the tool, on the -Z side; the control's "
                             "G41/G42 from +Z: written as the other side"),
            std::string::npos)
      << minus.diags;
  EXPECT_NE(minus.diags.find("t.cl:6:1: note: tool axis 0,0,-1: a face tool on the -Z side, "
                             "working a face that looks toward -Z (the part at +Z of it, as this "
                             "CL's frame has it); written in the CL's frame, as the turning is"),
            std::string::npos)
      << minus.diags;
  Posted plus = post(face_tool_cl("1"), load("haas-st-20y"));
  EXPECT_EQ(plus.errors, 0u) << plus.diags;
  EXPECT_NE(plus.nc.find(fmt::format(fmt::runtime(path), "G41")), std::string::npos) << plus.nc;
}

// Still refused: a tilted tool axis; a live tool's cutter compensation on a machine without Y
// (its X Z C are the post's: G41/G42 would offset the lathe's X and Z).
TEST(MillingMotion, TiltedAxisAndCompensationWithoutYAreLocatedErrors) {
  Posted tilted =
      post("LOADTL/5,MILL\nSPINDL/3000,RPM,CLW\nFEDRAT/150,MMPM\nGOTO/0,0,1,0,0.6,0.8\nFINI\n",
           load("haas-st-20y"));
  EXPECT_NE(tilted.diags.find("t.cl:4:1: error: milling motion with live tool 5 (loaded at line "
                              "1): the tool axis (0, 0.6, 0.8) is neither along Z (a face tool, "
                              "0,0,1 or 0,0,-1) nor radial (k 0): a tilted live tool is not "
                              "written"),
            std::string::npos)
      << tilted.diags;
  Posted xzc = post(face_tool_cl("-1"), load("linuxcnc-lathe-c"));
  EXPECT_EQ(xzc.errors, 1u) << xzc.diags;
  EXPECT_NE(xzc.diags.find("t.cl:8:8: error: CUTCOM/LEFT with live tool 5: machine "
                           "'linuxcnc-lathe-c' has no Y axis, and its milling is X Z C computed "
                           "by the post, where the control's cutter compensation does not "
                           "offset the path on the part"),
            std::string::npos)
      << xzc.diags;
}

// Polar interpolation on haas-st-20y (G112, Y the virtual axis, X a radius, arcs as chords:
// Fusion's Haas lathe post). The quarter and the slot at index 30: C to 0 first (the plane is
// the machine's X and Y at C0), each part point turned by 30 degrees: (10, 0) is (8.6603, 5),
// the arc's first chord end (10 cos 2.5°, 10 sin 2.5°) is at 32.5°, (8.4339, 5.373) (chords of
// 2.5° within half the tolerance, as XZC's), its end (0, 10) is (-5, 8.6603); the slot's end
// (0, -10) is (5, -8.6603). The slot crosses the centre as one straight G1; F the CL's 100 per
// minute in the plane.
TEST(MillingMotion, PolarInterpolationOnHaasSt20y) {
  std::string cl = kQuarterAndSlot;
  cl.replace(cl.find("ROTABL/0"), 8, "ROTABL/30");
  cl.replace(cl.find("FINI"), 4, "LOADTL/1\nFINI");
  Posted p = post(cl, load("haas-st-20y", {"millturn.polar_interpolation=true"}));
  EXPECT_EQ(p.errors, 0u) << p.diags;
  EXPECT_NE(p.nc.find("G0 C30.\nM14\nM15\nG0 C0.\nG112\nG17\nG0 X8.66 Y5. Z2.\n"
                      "G98 G1 X8.66 Y5. Z-1. F100.\nG1 X8.434 Y5.373 Z-1. F100.\n"),
            std::string::npos)
      << p.nc;
  EXPECT_NE(p.nc.find("G1 X-5. Y8.66 Z-1. F100.\nG1 X5. Y-8.66 Z-1. F100.\nG113\nG18\nM135\n"
                      "T0101\n"),
            std::string::npos)
      << p.nc;
  EXPECT_EQ(p.nc.find("G3"), std::string::npos) << p.nc;
  // A full circle of radius 10 about (0, 0) from (10, 0) at index 0 where the control takes
  // G2/G3 in the mode (fanuc-0i-tf-live, X set a diameter): three G3 of 120 degrees (both
  // Fusion posts split polar arcs at 120): (-5, 8.6603), (-5, -8.6603), (10, 0).
  Posted full = post(
      "LOADTL/3,MILL\nSPINDL/2000,RPM,CLW\nROTABL/0,CAXIS\nRAPID\nGOTO/10,0,-1\n"
      "FEDRAT/100,MMPM\nCIRCLE/0,0,-1,0,0,1,10\nGOTO/10,0,-1\nFINI\n",
      load("fanuc-0i-tf-live", {"millturn.polar_interpolation=true", "millturn.polar_x=diameter"}));
  EXPECT_EQ(full.errors, 0u) << full.diags;
  EXPECT_NE(full.nc.find("G3 X-10. C8.66 Z-1. I-10. J0. F100.\nG3 X-10. C-8.66 Z-1. I5. J-8.66 "
                         "F100.\nG3 X20. C0. Z-1. I5. J8.66 F100.\nG13.1\n"),
            std::string::npos)
      << full.nc;
  // Fanuc with X set a diameter: G12.1, X twice the radius, C the virtual axis (a radius), the
  // rapid a G1 at millturn.polar_rapid_feed 1500 (no G00 in the mode).
  Posted f = post(cl, load("fanuc-0i-tf-live",
                           {"millturn.polar_interpolation=true", "millturn.polar_x=diameter"}));
  EXPECT_EQ(f.errors, 0u) << f.diags;
  EXPECT_NE(f.nc.find("M74\nG0 C0.\nG12.1\nG98 G1 X17.321 C5. Z2. F1500.\n"
                      "G1 X17.321 C5. Z-1. F100.\nG3 X-10. C8.66 Z-1. I-8.66 J-5. F100.\n"
                      "G1 X10. C-8.66 Z-1. F100.\nG13.1\nM72\nT0101\n"),
            std::string::npos)
      << f.nc;
  // A ROTABL in the mode leaves it first (G113, G18): C is then at the angle of the tool's point,
  // (0, 10) is C90, so ROTABL/90 writes no C; the next motion enters at C0 again and the part
  // point (10, 0) at index 90 is (0, 10) in the plane.
  Posted idx = post(
      "LOADTL/3,MILL\nSPINDL/2000,RPM,CLW\nROTABL/0,CAXIS\nRAPID\nGOTO/10,0,2\n"
      "FEDRAT/100,MMPM\nGOTO/10,0,-1\nGOTO/0,10,-1\nROTABL/90,CAXIS\nRAPID\nGOTO/10,0,2\n"
      "GOTO/10,0,-1\nFINI\n",
      load("haas-st-20y", {"millturn.polar_interpolation=true"}));
  EXPECT_EQ(idx.errors, 0u) << idx.diags;
  EXPECT_NE(
      idx.nc.find("G1 X0. Y10. Z-1. F100.\nG113\nG18\nG0 C0.\nG112\nG17\n"
                  "G0 X0. Y10. Z2.\nG98 G1 X0. Y10. Z-1. F100.\nG113\nG18\nM135\nM155\nM30\n"),
      std::string::npos)
      << idx.nc;
  // A feed that starts the mode where C0 moves the tool off its start (FROM/10,0,-1 at index
  // 90 is C90): an error, not a move from the wrong point.
  Posted from = post(
      "LOADTL/3,MILL\nSPINDL/2000,RPM,CLW\nROTABL/90,CAXIS\nFROM/10,0,-1\nFEDRAT/100,MMPM\n"
      "GOTO/0,10,-1\nFINI\n",
      load("haas-st-20y", {"millturn.polar_interpolation=true"}));
  EXPECT_NE(from.diags.find("t.cl:6:1: error: a feed move starts polar interpolation, and the C0 "
                            "the mode starts at moves the tool off its start point"),
            std::string::npos)
      << from.diags;
  // CUTCOM in the mode is G41/G42 there (Fanuc: "Polar coordinate interpolation is applied to
  // the path after cutter compensation"); one in force where the mode starts is an error.
  const std::string comp =
      "LOADTL/3,MILL\nSPINDL/2000,RPM,CLW\nROTABL/0,CAXIS\nRAPID\nGOTO/10,0,2\n"
      "FEDRAT/100,MMPM\nCUTCOM/LEFT\nGOTO/10,0,-1\nGOTO/0,10,-1\nCUTCOM/OFF\nGOTO/0,12,-1\n"
      "FINI\n";
  Posted in_mode = post(comp, load("haas-st-20y", {"millturn.polar_interpolation=true"}));
  EXPECT_EQ(in_mode.errors, 0u) << in_mode.diags;
  EXPECT_NE(in_mode.nc.find("G112\nG17\nG0 X10. Y0. Z2.\nG41\nG98 G1 X10. Y0. Z-1. F100.\n"
                            "G1 X0. Y10. Z-1. F100.\nG40\nG1 X0. Y12. Z-1. F100.\nG113\n"),
            std::string::npos)
      << in_mode.nc;
  std::string before = comp;
  before.replace(before.find("RAPID"), 5, "CUTCOM/LEFT\nRAPID");
  Posted early = post(before, load("haas-st-20y", {"millturn.polar_interpolation=true"}));
  EXPECT_NE(early.diags.find("t.cl:6:1: error: CUTCOM/LEFT or RIGHT in force where polar "
                             "interpolation starts"),
            std::string::npos)
      << early.diags;
  // A feed along Z and across the face at once: F is not pinned for it.
  std::string ramp = kQuarterAndSlot;
  ramp.replace(ramp.find("GOTO/10,0,-1\nCIRCLE"), 12, "GOTO/9,0,-1");
  Posted r = post(ramp, load("haas-st-20y", {"millturn.polar_interpolation=true"}));
  EXPECT_NE(r.diags.find("t.cl:7:1: error: a feed move along Z and across the face at once in "
                         "polar interpolation"),
            std::string::npos)
      << r.diags;
}

}  // namespace
}  // namespace clpost

namespace clpost {
namespace {

// Peripheral milling without Y (docs/millturn.md): a radial live tool on a 16 mm diameter. A
// slot along Z at C90 (tool axis 0,1,0 at index 0: C from the axis), the groove half round at
// Z-10 (CIRCLE/ about Z) and a helix-like line from C180 Z-10 to C190 Z-11, then out along the
// tool axis.
constexpr const char* kPeripheral =
    "LOADTL/4,MILL\nSPINDL/2000,RPM,CLW\nROTABL/0,CAXIS\nRAPID\nGOTO/0,15,5,0,1,0\n"
    "FEDRAT/100,MMPM\nGOTO/0,8,5,0,1,0\nGOTO/0,8,-20,0,1,0\nGOTO/0,15,-20,0,1,0\nRAPID\n"
    "GOTO/15,0,-10,1,0,0\nGOTO/8,0,-10,1,0,0\nCIRCLE/0,0,-10,0,0,1,8\nGOTO/-8,0,-10,-1,0,0\n"
    "GOTO/-7.878462,-1.389185,-11,-0.984808,-0.173648,0\n"
    "GOTO/-14.772116,-2.604723,-11,-0.984808,-0.173648,0\nFINI\n";

// By hand. The slot: C90 from the tool axis, X the tip's diameter 16, Z alone: the lathe's G1
// (exact). The groove: chords within half the tolerance, 2 acos(1 - 0.0025 / 8) = 0.05 rad, so
// 63 of 180/63 = 2.857143 degrees, each 16 sin(90/63 degrees) = 0.398891 mm: G93 F = 100 /
// 0.398891 = 250.695 (Fanuc: 2.857143 degrees in 0.00398891 min, F716.2715). At X16 the
// control's C move is the arc itself. The helix-like line: the chord of the 16 mm circle from
// C180 to C190 (C from its tool axis, 189.99999 degrees as the CL rounds it) while Z goes -10 to
// -11; halves are 8 (1 - cos 2.5°) = 0.0076 off it, quarters 0.0019: 4 pieces, their ends on the
// line (X = 2 |point|: 15.95436 at a quarter, 16 cos 5° = 15.93912 at half; C 182.4952, 185),
// each a quarter of its 1.715996 mm: G93 F = 100 / 0.428996 = 233.1023. Out along the tool axis
// at C190: the lathe's G1.
TEST(MillingMotion, PeripheralSlotGrooveAndHelixWithoutY) {
  Posted l = post(kPeripheral, load("linuxcnc-lathe-c"));
  EXPECT_EQ(l.errors, 0u) << l.diags;
  EXPECT_NE(l.nc.find("G0 C0.\nG19\nG0 X30. Z5. C90.\nG1 X16. Z5. G94 F100.\nZ-20.\nX30.\n"
                      "G0 X30. Z-10. C0.\nG1 X16. Z-10. G94 F100.\n"
                      "G93 G1 X16. Z-10. C2.8571 F250.695\nG1 X16. Z-10. C5.7143 F250.695\n"),
            std::string::npos)
      << l.nc;
  EXPECT_NE(l.nc.find("G1 X16. Z-10. C177.1429 F250.695\nG1 X16. Z-10. C180. F250.695\n"
                      "G1 X15.95436 Z-10.25 C182.4952 F233.1023\n"
                      "G1 X15.93912 Z-10.5 C185. F233.1023\n"
                      "G1 X15.95436 Z-10.75 C187.5048 F233.1023\n"
                      "G1 X16. Z-11. C190. F233.1023\nG1 X30. Z-11. G94 F100.\nG18\nM5 $1\nM2\n"),
            std::string::npos)
      << l.nc;
  size_t groove = 0;
  for (size_t at = l.nc.find("X16. Z-10. C"); at != std::string::npos;
       at = l.nc.find("X16. Z-10. C", at + 1))
    ++groove;
  EXPECT_EQ(groove, 63u);
  // Fanuc (no plane code: the Takisawa post mills radially in G18), rollover C, the combined F.
  Posted f = post(kPeripheral, load("fanuc-0i-tf-live"));
  EXPECT_EQ(f.errors, 0u) << f.diags;
  EXPECT_NE(f.nc.find("G0 X30. Z5. C90.\nG1 X16. Z5. G98 F100.\nZ-20.\nX30.\nG0 X30. Z-10. C0.\n"
                      "G1 X16. Z-10. G98 F100.\nG1 X16. Z-10. C2.857 F716.2715\n"),
            std::string::npos)
      << f.nc;
  EXPECT_EQ(f.nc.find("G19"), std::string::npos) << f.nc;
}

// A ROTABL turns the part frame: at index 90 a radial tool along +X works at C90 (its rapid
// there is the lathe's move, as a radial drill's approach, then G19 before the milling).
TEST(MillingMotion, PeripheralWorkAtTheCIndex) {
  Posted p = post(
      "LOADTL/4,MILL\nSPINDL/2000,RPM,CLW\nROTABL/90,CAXIS\nFEDRAT/100,MMPM\nRAPID\n"
      "GOTO/15,0,5,1,0,0\nGOTO/8,0,5,1,0,0\nGOTO/8,0,-20,1,0,0\nFINI\n",
      load("linuxcnc-lathe-c"));
  EXPECT_EQ(p.errors, 0u) << p.diags;
  EXPECT_NE(p.nc.find("G0 C90.\nG0 X30. Z5.\nG19\nG1 X16. G94 F100.\nZ-20.\n"), std::string::npos)
      << p.nc;
}

// What a radial tool without Y cannot reach: a tip off the line of its axis through the centre
// line (CATIA's MillTurn3x_PATH1 at Y0.05 with the axis 1,0,0), an arc in the peripheral plane
// (about the tool axis: its points leave that line), a tilted tool axis, a tip past the centre
// line. An arc in the plane of the tool axis and Z stays at one C: lines.
TEST(MillingMotion, PeripheralWithoutYRefusesWhatNeedsY) {
  const std::string head = "LOADTL/3,MILL\nSPINDL/2000,RPM,CLW\nROTABL/0,CAXIS\nFEDRAT/150,MMPM\n";
  Posted off =
      post(head + "RAPID\nGOTO/9.42906,0.05,2.27946,1,0,0\nFINI\n", load("linuxcnc-lathe-c"));
  EXPECT_EQ(off.errors, 1u) << off.diags;
  EXPECT_NE(off.diags.find("t.cl:6:1: error: milling motion with live tool 3 (loaded at line 1): "
                           "the tip (9.42906, 0.05, 2.27946) is 0.0500 mm off the line of the "
                           "tool axis (1, 0, 0) through the centre line (millturn.xzc_tolerance "
                           "0.005): a radial tool reaches it with a Y axis only, and machine "
                           "'linuxcnc-lathe-c' has none"),
            std::string::npos)
      << off.diags;
  Posted within =
      post(head + "RAPID\nGOTO/9.42906,0.004,2.27946,1,0,0\nFINI\n", load("fanuc-0i-tf-live"));
  EXPECT_EQ(within.errors, 0u) << within.diags;
  EXPECT_NE(within.nc.find("G0 X18.858 Z2.279\n"), std::string::npos) << within.nc;
  // The half turn about X (radius 1) is 23 chords (2 acos(1 - 0.0025) = 0.1414 rad each); the
  // farthest chord point, 11 x 180/23 = 86.087 degrees round, is sin 86.087° = 0.9977 off.
  Posted plane =
      post(head + "RAPID\nGOTO/4,0,3,1,0,0\nCIRCLE/4,0,2,1,0,0,1\nGOTO/4,0,1,1,0,0\nFINI\n",
           load("fanuc-0i-tf-live"));
  EXPECT_EQ(plane.errors, 1u) << plane.diags;
  EXPECT_NE(plane.diags.find("t.cl:8:1: error: milling motion with live tool 3 (loaded at line 1): "
                             "the arc of line 7 about (1, 0, 0) at (4, -0.99767, 2.0682) is 0.9977 "
                             "mm off the line of the tool axis (1, 0, 0) through the centre line"),
            std::string::npos)
      << plane.diags;
  Posted tilted = post(head + "GOTO/4,0,3,0.6,0,0.8\nFINI\n", load("linuxcnc-lathe-c"));
  EXPECT_NE(tilted.diags.find("t.cl:5:1: error: milling motion with live tool 3 (loaded at line "
                              "1): the tool axis (0.6, 0, 0.8) is neither along Z (a face tool, "
                              "0,0,1 or 0,0,-1) nor radial (k 0)"),
            std::string::npos)
      << tilted.diags;
  Posted past = post(head + "RAPID\nGOTO/-2,0,3,1,0,0\nFINI\n", load("linuxcnc-lathe-c"));
  EXPECT_NE(past.diags.find("t.cl:6:1: error: milling motion with live tool 3 (loaded at line 1): "
                            "the tip (-2, 0, 3) is -2.0000 mm from the centre line along the tool "
                            "axis (1, 0, 0): a radial tool's tip at or past the centre line is "
                            "not written"),
            std::string::npos)
      << past.diags;
  // About Y through the centre line's plane: the arc from (6, 0, 0) round (5, 0, 0) to
  // (5, 0, -1), all at C0: chords in X and Z (the lathe's G1), X from 12 down to 10.
  Posted xz =
      post(head + "RAPID\nGOTO/6,0,0,1,0,0\nCIRCLE/5,0,0,0,1,0,1\nGOTO/5,0,-1,1,0,0\nFINI\n",
           load("linuxcnc-lathe-c"));
  EXPECT_EQ(xz.errors, 0u) << xz.diags;
  EXPECT_EQ(xz.nc.find("G93"), std::string::npos) << xz.nc;
  EXPECT_NE(xz.nc.find("G19\nG1 X11.98289 Z-0.13053 G94 F150.\n"), std::string::npos) << xz.nc;
  EXPECT_NE(xz.nc.find("X10. Z-1.\nG18\nM5 $1\nM2\n"), std::string::npos) << xz.nc;
}

}  // namespace
}  // namespace clpost

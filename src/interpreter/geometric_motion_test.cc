// APT geometric motion in the turning plane (geometric_motion.cc): the moves, each checked by
// hand, and the errors at their columns.
#include <gtest/gtest.h>

#include "interpreter/post.h"
#include "machine/machine_loader.h"
#include "machine/machine_test_util.h"

namespace clpost {
namespace {

struct Posted {
  std::string nc;
  std::string diags;
  size_t errors = 0;
};

Posted post(const std::string& cl) {
  Machine m;
  std::string errors;
  EXPECT_TRUE(load_machine("generic-lathe", {CLPOST_SOURCE_DIR},
                           {"block_numbers.enabled=false", "templates.program_header=[]"},
                           shipped_controls(), m, errors))
      << errors;
  PostedText r = post_text(cl, m, "t.cl", {});
  return Posted{r.program, r.diags.render_all(), r.diags.error_count()};
}

constexpr const char* kHeader = "%\nO0001\nG18 G21 G40 G90\n";

// CATIA's NC_CIRCLE1 (realcam/catia_karlo/DEMO5.txt): a quarter circle from (20.4, -30) about
// (25, -30), starting toward +Z, to the line through the centre along X = 25: it ends at
// (25, -25.4), counter-clockwise in (Z, X): G3, as the same CIRCLE/ + GOTO gives.
TEST(GeometricMotion, CatiaCircleIsTheArcCircleAndGotoGive) {
  const Posted go = post(
      "FEDRAT/0.1,MMPR\nGOTO/20.4,0,-30\nINDIRV/0,0,1\n"
      "TLON,GOFWD/(CIRCLE/25,0,-30,$\n4.6),ON,(LINE/25,0,-30,$\n25,0,-25.4)\nFINI\n");
  const Posted arc = post(
      "FEDRAT/0.1,MMPR\nGOTO/20.4,0,-30\nCIRCLE/25,0,-30,0,1,0,4.6\n"
      "GOTO/25,0,-25.4\nFINI\n");
  EXPECT_EQ(go.nc, std::string(kHeader) +
                       "G1 X40.8 Z-30. G95 F0.1\nG3 X50. Z-25.4 I4.6 K0.\n"
                       "M30\n%\n");
  EXPECT_EQ(go.nc, arc.nc);
  EXPECT_EQ(go.diags, "");
}

// The same with the radius in CL Y (CATIA lathe programs of other setups): the same program, and
// the note that says which axis is the radius.
TEST(GeometricMotion, RadiusInYGivesTheSameArc) {
  const Posted y = post(
      "FEDRAT/0.1,MMPR\nGOTO/0,20.4,-30\nINDIRV/0,0,1\n"
      "TLON,GOFWD/(CIRCLE/0,25,-30,4.6),ON,(LINE/0,25,-30,0,25,-25.4)\nFINI\n");
  EXPECT_EQ(y.nc, std::string(kHeader) +
                      "G1 X40.8 Z-30. G95 F0.1\nG3 X50. Z-25.4 I4.6 K0.\n"
                      "M30\n%\n");
  EXPECT_EQ(y.diags,
            "t.cl:2:1: note: the radius is CL Y and CL X is 0 (cl.radial_axis: auto, found here)\n"
            "  GOTO/0,20.4,-30\n"
            "  ^\n");
}

// CATIA's custom table (realcam/catia_toussaint, "FIN RAYON - G2"): a cylinder about Y and a
// plane through two points perpendicular to the XZ plane. From (2, 0) toward +X about (2, 2)
// radius 2 to the line Z = 2: the quarter to (4, 2), clockwise in (Z, X): G2.
TEST(GeometricMotion, CylinderAndPlanesAreTheLatheCircleAndLine) {
  const Posted p = post(
      "FEDRAT/0.4,MMPR\nGOTO/2,0,0\nPSIS/(PLANE/(POINT/2,0,2),PERPTO,(VECTOR/0,1,0))\n"
      "INDIRV/1,0,0\nTLON,GOFWD/(CYLNDR/2,0,2,0,1,0,2),ON,(PLANE/PERPTO,(PLANE/(POINT/2,0,2),"
      "PERPTO,(VECTOR/0,1,0)),(POINT/2,0,2),(POINT/4,0,2))\nFINI\n");
  EXPECT_EQ(p.nc, std::string(kHeader) + "G1 X4. Z0. G95 F0.4\nG2 X8. Z2. I0. K2.\nM30\n%\n");
  EXPECT_EQ(p.diags, "");
}

// Lines and TANTO, PAST, TO with a cutter, GOLFT:
// - along X = 10 toward -Z, TANTO the circle about (15, -20) radius 5: its foot (10, -20);
// - on that circle, the last direction -Z makes it clockwise to the line Z = -20: (20, -20), G2;
// - CUTTER/1 (radius 0.5): toward +X PAST the plane X = 25: X = 25.5;
// - GOLFT turns left of +X seen from +Y: -Z, TO the line Z = -30: Z = -29.5.
TEST(GeometricMotion, LinesTantoPastToAndTurns) {
  const Posted p = post(
      "FEDRAT/0.1,MMPR\nGOTO/10,0,0\nINDIRV/0,0,-1\n"
      "TLON,GOFWD/(LINE/10,0,0,10,0,-50),TANTO,(CIRCLE/15,0,-20,5)\n"
      "TLON,GOFWD/(CIRCLE/15,0,-20,5),ON,(LINE/15,0,-20,20,0,-20)\n"
      "CUTTER/1\nINDIRV/1,0,0\nGOFWD/(LINE/20,0,-20,30,0,-20),PAST,(PLANE/1,0,0,25)\n"
      "GOLFT/(LINE/25.5,0,-20,25.5,0,-40),TO,(LINE/0,0,-30,40,0,-30)\nFINI\n");
  EXPECT_EQ(p.nc, std::string(kHeader) +
                      "G1 X20. Z0. G95 F0.1\nZ-20.\nG2 X40. I5. K0.\nG1 X51.\nZ-29.5\nM30\n%\n");
  EXPECT_EQ(p.diags, "");
}

// Tool offsets and the n-th intersection, CUTTER/1 (radius 0.5):
// - TLLFT on the circle about (15, -20) radius 5, moving -Z at its bottom: seen from +Y the left
//   is away from the centre, so the tool runs at radius 5.5, clockwise to X = 15: (15, -25.5);
// - along X = 10 the second intersection with the circle about (12, -20) radius 5:
//   Z = -20 - sqrt(25 - 4) = -24.583;
// - TLRGT on X = 10 moving -Z: the right is +X, the tool at X = 10.5, to Z = -5.
TEST(GeometricMotion, ToolOffsetsAndIntof) {
  const Posted p = post(
      "FEDRAT/0.1,MMPR\nGOTO/9.5,0,-20\nCUTTER/1\nINDIRV/0,0,-1\n"
      "TLLFT,GOFWD/(CIRCLE/15,0,-20,5),ON,(LINE/15,0,-20,15,0,-30)\n"
      "GOTO/10,0,0\nINDIRV/0,0,-1\nGOFWD/(LINE/10,0,0,10,0,-1),ON,2,INTOF,(CIRCLE/12,0,-20,5)\n"
      "GOTO/10.5,0,0\nINDIRV/0,0,-1\nTLRGT,GOFWD/(LINE/10,0,0,10,0,-1),ON,(LINE/0,0,-5,1,0,-5)\n"
      "FINI\n");
  EXPECT_EQ(p.nc, std::string(kHeader) +
                      "G1 X19. Z-20. G95 F0.1\nG2 X30. Z-25.5 I5.5 K0.\nG1 X20. Z0.\nZ-24.583\n"
                      "X21. Z0.\nZ-5.\nM30\n%\n");
  EXPECT_EQ(p.diags, "");
}

TEST(GeometricMotion, ErrorsAtTheirColumns) {
  const Posted p = post(
      "FEDRAT/0.1,MMPR\n"
      "TLON,GOFWD/(CIRCLE/25,0,-30,4.6),ON,(LINE/25,0,-30,25,0,-25.4)\n"
      "GOTO/20,0,-30\n"
      "TLON,GOFWD/(CIRCLE/25,0,-30,4.6),ON,(LINE/25,0,-30,25,0,-25.4)\n"
      "INDIRV/0,0,1\n"
      "TLON,GOFWD/(SPHERE/25,0,-30,4.6),ON,(LINE/25,0,-30,25,0,-25.4)\n"
      "INDIRV/0,0,1\n"
      "TLON,GOFWD/(CIRCLE/25,0,-30,4.6),ON,(LINE/25,0,-30,25,0,-25.4)\n"
      "TLLFT,RAPID,GOFWD/(LINE/1,0,0,2,0,0),ON,(LINE/1,0,0,1,0,1)\n"
      "GOFWD/C1,TANTO,C2\n"
      "GOFWD/(LINE/20,0,-30,20,0,-40),AT,(LINE/0,0,-35,1,0,-35)\n"
      "PSIS/(PLANE/0,0,1,5)\n"
      "INDIRV/0,0,-1\n"
      "GOFWD/(LINE/20,0,-30,20,0,-40),ON,(LINE/0,0,35,1,0,35)\n"
      "FINI\n");
  EXPECT_EQ(p.errors, 9u);
  EXPECT_EQ(p.diags,
            "t.cl:2:6: error: GOFWD/ needs a start point: no GOTO or FROM before it\n"
            "  TLON,GOFWD/(CIRCLE/25,0,-30,4.6),ON,(LINE/25,0,-30,25,0,-25.4)\n"
            "       ^\n"
            "t.cl:4:6: error: GOFWD/ needs a direction: no INDIRV/ and no motion before it\n"
            "  TLON,GOFWD/(CIRCLE/25,0,-30,4.6),ON,(LINE/25,0,-30,25,0,-25.4)\n"
            "       ^\n"
            "t.cl:6:12: error: (SPHERE/…) is not a lathe line or arc: a lathe drive or check "
            "surface is a LINE, CIRCLE, CYLNDR or PLANE in the turning plane\n"
            "  TLON,GOFWD/(SPHERE/25,0,-30,4.6),ON,(LINE/25,0,-30,25,0,-25.4)\n"
            "             ^\n"
            "t.cl:8:12: error: the tool is not on the drive circle: 5 from its centre, radius 4.6\n"
            "  TLON,GOFWD/(CIRCLE/25,0,-30,4.6),ON,(LINE/25,0,-30,25,0,-25.4)\n"
            "             ^\n"
            "t.cl:9:7: error: 'RAPID' before GOFWD/: expected TLON, TLLFT or TLRGT\n"
            "  TLLFT,RAPID,GOFWD/(LINE/1,0,0,2,0,0),ON,(LINE/1,0,0,1,0,1)\n"
            "        ^\n"
            "t.cl:10:7: error: 'C1' names geometry defined in an APT part program: CL data gives "
            "it as a nested (WORD/…) definition\n"
            "  GOFWD/C1,TANTO,C2\n"
            "        ^\n"
            "t.cl:11:32: error: expected TO, ON, PAST or TANTO before the check surface, found "
            "'AT'\n"
            "  GOFWD/(LINE/20,0,-30,20,0,-40),AT,(LINE/0,0,-35,1,0,-35)\n"
            "                                 ^\n"
            "t.cl:12:6: error: PSIS/: the part surface is not the turning plane (normal 0, 0, 1): "
            "a lathe cuts in the plane of radius and axis\n"
            "  PSIS/(PLANE/0,0,1,5)\n"
            "       ^\n"
            "t.cl:14:35: error: the drive surface does not reach the check surface ahead of the "
            "tool (0 intersections ahead, 1 wanted)\n"
            "  GOFWD/(LINE/20,0,-30,20,0,-40),ON,(LINE/0,0,35,1,0,35)\n"
            "                                    ^\n");
}

}  // namespace
}  // namespace clpost

// CYCLE/UNDCUT: CYCLE96 on sinumerik-840d with the control's checks, the DIN 76-1 contour on a
// machine without CYCLE96, and the rows clpost does not carry.
#include "laws/din76_undercut.h"

#include <gtest/gtest.h>

#include "interpreter/post.h"
#include "interpreter/post_test_util.h"
#include "machine/machine_loader.h"
#include "reader/cl_reader.h"

namespace clpost {
namespace {

using test::load;
using test::post;
using test::Posted;

// Tool 3 loaded, feed 0.1 mm/rev, tool at X30 Z5 (diameter), then `line` (line 6).
std::string cl_with(const std::string& line, const std::string& tool = "LOADTL/3\n") {
  return "UNITS/MM\n" + tool + "FEDRAT/0.1,MMPR\nRAPID\nGOTO/15,0,5\n" + line + "\nFINI\n";
}

// The error a CL line gives on machine `m` (one error expected).
std::string error_of(const Machine& m, const std::string& cl) {
  Posted p = post(cl, m);
  EXPECT_EQ(p.errors, 1u) << p.diags;
  return p.diags;
}

TEST(Undercut, IsoCoarsePitches) {
  EXPECT_EQ(iso_coarse_pitch(3), 0.5);
  EXPECT_EQ(iso_coarse_pitch(24), 3);
  EXPECT_EQ(iso_coarse_pitch(68), 6);
  EXPECT_FALSE(iso_coarse_pitch(2.5));  // below M3
  EXPECT_FALSE(iso_coarse_pitch(17));   // not in the series
  EXPECT_FALSE(iso_coarse_pitch(72));   // above M68
}

TEST(Undercut, Din76RowsForTheNormalFormsOnly) {
  // P = 1.5 form A: the data point controllers.md confirms (depth 2.3 / 2 = 1.15, width 5.2,
  // radius 0.8).
  const Din76Row* a = din76_row('A', 1.5);
  ASSERT_NE(a, nullptr);
  EXPECT_EQ(a->diameter_step, 2.3);
  EXPECT_EQ(a->width, 5.2);
  EXPECT_EQ(a->radius, 0.8);
  const Din76Row* c = din76_row('C', 1.5);
  ASSERT_NE(c, nullptr);
  EXPECT_EQ(c->diameter_step, 0.5);
  EXPECT_EQ(c->width, 7.8);
  EXPECT_EQ(din76_row('B', 1.5), nullptr);
  EXPECT_EQ(din76_row('D', 1.5), nullptr);
  EXPECT_EQ(din76_row('A', 0.2), nullptr);  // a fine pitch below M3's: not carried
  // Every coarse pitch M3 ... M68 has both rows, and the flank leaves room for the fillet:
  // width - depth / tan 30 >= radius.
  for (double d : {3,  4,  5,  6,  8,  10, 12, 14, 16, 18, 20, 22, 24,
                   27, 30, 33, 36, 39, 42, 45, 48, 52, 56, 60, 64, 68}) {
    double p = *iso_coarse_pitch(d);
    for (char f : {'A', 'C'}) {
      const Din76Row* r = din76_row(f, p);
      ASSERT_NE(r, nullptr) << f << " " << p;
      UndercutContour k = din76_contour(d, 0, f, 1, *r);
      EXPECT_GE(k.to_fillet[1].z, r->radius) << f << " " << p;
    }
  }
}

TEST(Undercut, Cycle96OnSinumerik) {
  Posted p = post(cl_with("CYCLE/UNDCUT,DIAM,42,AT,60,FORM,A"), load("sinumerik-840d"));
  EXPECT_EQ(p.diags, "");
  // The feed in force is written before the cycle (it cuts at the feed programmed before it);
  // the cycle returns to its starting point, so the next move writes both axes.
  EXPECT_EQ(p.nc,
            "G18 G710 G40 G90 DIAMON\n"
            "T3 D3\n"
            "G0 X30 Z5\n"
            "; thread undercut M42 form A (external, normal) at Z60\n"
            "G95 F0.1\n"
            "CYCLE96(42, 60, \"A\")\n"
            "M30\n");
}

TEST(Undercut, Cycle96Checks) {
  Machine m = load("sinumerik-840d");
  EXPECT_EQ(error_of(m, cl_with("CYCLE/UNDCUT,DIAM,17,AT,-30,FORM,A")),
            "t.cl:6:19: error: CYCLE/UNDCUT: DIAM 17 is not a metric ISO coarse thread M3 ... M68 "
            "(3, 4, 5, 6, 8, 10, 12, 14, 16, 18, 20, 22, 24, 27, 30, 33, 36, 39, 42, 45, 48, 52, "
            "56, 60, 64, 68): CYCLE96 stops with an alarm\n"
            "  CYCLE/UNDCUT,DIAM,17,AT,-30,FORM,A\n"
            "                    ^\n");
  // M3 (P 0.5): 3 - 0.8 = 2.2 mm; M4 (P 0.7): 4 - 1.1 = 2.9 mm, form B too (same diameter).
  EXPECT_EQ(error_of(m, cl_with("CYCLE/UNDCUT,DIAM,3,AT,-30,FORM,A")),
            "t.cl:6:19: error: CYCLE/UNDCUT: the undercut's final diameter 2.2 (M3 pitch 0.5: DIN "
            "76-1 d - 0.8) is below 3 mm: CYCLE96 stops with an alarm\n"
            "  CYCLE/UNDCUT,DIAM,3,AT,-30,FORM,A\n"
            "                    ^\n");
  EXPECT_EQ(error_of(m, cl_with("CYCLE/UNDCUT,DIAM,4,AT,-30,FORM,B")),
            "t.cl:6:19: error: CYCLE/UNDCUT: the undercut's final diameter 2.9 (M4 pitch 0.7: DIN "
            "76-1 d - 1.1) is below 3 mm: CYCLE96 stops with an alarm\n"
            "  CYCLE/UNDCUT,DIAM,4,AT,-30,FORM,B\n"
            "                    ^\n");
  // M5 (P 0.8): 5 - 1.3 = 3.7 mm; internal forms grow the diameter: M3 form C is fine.
  EXPECT_EQ(post(cl_with("CYCLE/UNDCUT,DIAM,5,AT,-30,FORM,A"), m).errors, 0u);
  EXPECT_EQ(post(cl_with("CYCLE/UNDCUT,DIAM,3,AT,-30,FORM,C"), m).errors, 0u);
  EXPECT_EQ(error_of(m, cl_with("CYCLE/UNDCUT,DIAM,20,AT,-30,FORM,E")),
            "t.cl:6:34: error: CYCLE/UNDCUT: FORM must be A, B (external) or C, D (internal); got "
            "E\n"
            "  CYCLE/UNDCUT,DIAM,20,AT,-30,FORM,E\n"
            "                                   ^\n");
  EXPECT_EQ(error_of(m, cl_with("CYCLE/UNDCUT,DIAM,20,AT,-30,FORM,A", "")),
            "t.cl:5:1: error: CYCLE96 needs an active tool offset: no LOADTL/ before "
            "CYCLE/UNDCUT\n"
            "  CYCLE/UNDCUT,DIAM,20,AT,-30,FORM,A\n"
            "  ^\n");
  EXPECT_EQ(error_of(m, cl_with("CYCLE/UNDCUT,DIAM,20,AT,-30,FORM,A", "LOADTL/3,ADJUST,0\n")),
            "t.cl:6:1: error: CYCLE96 needs an active tool offset: the tool was loaded with offset "
            "0 (D0), which selects none\n"
            "  CYCLE/UNDCUT,DIAM,20,AT,-30,FORM,A\n"
            "  ^\n");
}

TEST(Undercut, StatementErrors) {
  Machine m = load("sinumerik-840d");
  EXPECT_EQ(error_of(m, "LOADTL/3\nCYCLE/UNDCUT,DIAM,20,AT,-30,FORM,A\nFINI\n"),
            "t.cl:2:1: error: CYCLE/UNDCUT cuts at the feed in force: no FEDRAT/ before it\n"
            "  CYCLE/UNDCUT,DIAM,20,AT,-30,FORM,A\n"
            "  ^\n");
  EXPECT_EQ(error_of(m, cl_with("CYCLE/UNDCUT,DIAM,20,FORM,A")),
            "t.cl:6:1: error: CYCLE/UNDCUT needs DIAM, AT and FORM: "
            "CYCLE/UNDCUT,DIAM,d,AT,z,FORM,A|B|C|D; missing AT\n"
            "  CYCLE/UNDCUT,DIAM,20,FORM,A\n"
            "  ^\n");
  EXPECT_EQ(error_of(m, cl_with("CYCLE/UNDCUT,DIAM,20,AT,-30,DEPTH,2")),
            "t.cl:6:29: error: CYCLE/UNDCUT: unknown word 'DEPTH'; valid words: DIAM, AT, FORM\n"
            "  CYCLE/UNDCUT,DIAM,20,AT,-30,DEPTH,2\n"
            "                              ^\n");
  EXPECT_EQ(error_of(m,
                     "UNITS/INCHES\nLOADTL/3\nFEDRAT/0.01,IPR\nCYCLE/UNDCUT,DIAM,1,AT,-1,FORM,"
                     "A\nFINI\n"),
            "t.cl:4:1: error: CYCLE/UNDCUT is for metric ISO threads (DIN 76-1, M3 ... M68): this "
            "program is in inches\n"
            "  CYCLE/UNDCUT,DIAM,1,AT,-1,FORM,A\n"
            "  ^\n");
  // Other cycles are still refused.
  EXPECT_EQ(post(cl_with("CYCLE/THREADMILLING,5\nCYCLE/OFF"), m).errors, 1u);
}

TEST(Undercut, Din76ContourFormA) {
  // M20 (P 2.5): undercut diameter 20 - 3.6 = 16.4, width 8.7, radius 1.2; the tool (Z5) is on
  // the +Z side of the shoulder at Z-30. The 30-degree flank runs 1.8 / tan 30 = 3.117691 along
  // Z: from Z-30+8.7 = -21.3 down to Z-24.418; the bottom to Z-30+1.2; the fillet (G2, centre
  // 1.2 above, I1.2 K0) to the shoulder face at X 16.4+2.4 = 18.8; up the face to 1 mm above
  // the thread (X22); back to the start.
  Posted p = post(cl_with("CYCLE/UNDCUT,DIAM,20,AT,-30,FORM,A"), load("generic-lathe"));
  EXPECT_EQ(p.diags, "");
  EXPECT_EQ(p.nc,
            "%\nO0001\nG18 G21 G40 G90\nT0303\nG0 X30. Z5.\n"
            "(thread undercut DIN 76-1 form A external, normal for M20 at Z-30: diameter 16.4, "
            "width 8.7, radius 1.2)\n"
            "X22. Z-21.3\n"
            "G1 X20. G95 F0.1\n"
            "X16.4 Z-24.418\n"
            "Z-28.8\n"
            "G2 X18.8 Z-30. I1.2 K0.\n"
            "G1 X22.\n"
            "G0 X30. Z5.\n"
            "M30\n%\n");
}

TEST(Undercut, Din76ContourFormCInTheBore) {
  // M30 (coarse P 3.5) internal: core diameter 30 - 2 x 0.54127 x 3.5 = 26.21111, undercut
  // diameter 30 + 0.5 = 30.5, width 17.7, radius 1.6; flank (15.25 - 13.105555) / tan 30 =
  // 3.714288 along Z from Z-24+17.7 = -6.3 to -10.014; fillet G3 to X 30.5-3.2 = 27.3; down the
  // face to 1 mm inside the core (X24.211).
  Posted p = post(
      "UNITS/MM\nLOADTL/9\nFEDRAT/0.1,MMPR\nRAPID\nGOTO/11,0,5\n"
      "CYCLE/UNDCUT,DIAM,30,AT,-24,FORM,C\nFINI\n",
      load("generic-lathe"));
  EXPECT_EQ(p.diags, "");
  EXPECT_EQ(p.nc,
            "%\nO0001\nG18 G21 G40 G90\nT0909\nG0 X22. Z5.\n"
            "(thread undercut DIN 76-1 form C internal, normal for M30 at Z-24: diameter 30.5, "
            "width 17.7, radius 1.6)\n"
            "X24.211 Z-6.3\n"
            "G1 X26.211 G95 F0.1\n"
            "X30.5 Z-10.014\n"
            "Z-22.4\n"
            "G3 X27.3 Z-24. I-1.6 K0.\n"
            "G1 X24.211\n"
            "G0 X22. Z5.\n"
            "M30\n%\n");
}

TEST(Undercut, ShortFormsAreRefusedWithoutCycle96) {
  Machine m = load("generic-lathe");
  EXPECT_EQ(error_of(m, cl_with("CYCLE/UNDCUT,DIAM,20,AT,-30,FORM,B")),
            "t.cl:6:34: error: CYCLE/UNDCUT: no DIN 76-1 row for form B (external, short), pitch "
            "2.5 (M20) in clpost's table: only the normal forms A and C are carried (cited in "
            "src/laws/din76_undercut.cc); use FORM,A or a machine with CYCLE96\n"
            "  CYCLE/UNDCUT,DIAM,20,AT,-30,FORM,B\n"
            "                                   ^\n");
  EXPECT_EQ(error_of(m, cl_with("CYCLE/UNDCUT,DIAM,20,AT,-30,FORM,D")),
            "t.cl:6:34: error: CYCLE/UNDCUT: no DIN 76-1 row for form D (internal, short), pitch "
            "2.5 (M20) in clpost's table: only the normal forms A and C are carried (cited in "
            "src/laws/din76_undercut.cc); use FORM,C or a machine with CYCLE96\n"
            "  CYCLE/UNDCUT,DIAM,20,AT,-30,FORM,D\n"
            "                                   ^\n");
  EXPECT_EQ(error_of(m, cl_with("CYCLE/UNDCUT,DIAM,20,AT,5,FORM,A")),
            "t.cl:6:1: error: CYCLE/UNDCUT: the tool is at the undercut's Z 5: it must be on the "
            "side of AT where the undercut lies\n"
            "  CYCLE/UNDCUT,DIAM,20,AT,5,FORM,A\n"
            "  ^\n");
}

}  // namespace
}  // namespace clpost

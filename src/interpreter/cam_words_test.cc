// The vocabulary CAM systems write around lathe work (cam_words.cc, geometric_motion.cc,
// frame.cc): exact programs and diagnostics.
#include <gtest/gtest.h>

#include "interpreter/post.h"
#include "interpreter/statement_table.h"
#include "machine/machine_loader.h"
#include "machine/machine_test_util.h"
#include "reader/cl_reader.h"
#include "support/sink.h"
#include "writer/nc_program.h"

namespace clpost {
namespace {

struct Posted {
  std::string nc;
  std::string diags;
  size_t errors = 0;
};

Machine lathe(std::vector<std::string> sets = {}, const char* name = "generic-lathe") {
  Machine m;
  std::string errors;
  if (std::string(name) == "generic-lathe") sets.push_back("block_numbers.enabled=false");
  sets.push_back("templates.program_header=[]");  // the header's own tests: cycle_time_test.cc
  EXPECT_TRUE(load_machine(name, {CLPOST_SOURCE_DIR}, sets, shipped_controls(), m, errors))
      << errors;
  return m;
}

Posted post(const std::string& cl, const Machine& m) {
  PostedText r = post_text(cl, m, "t.cl", {});
  return Posted{r.program, r.diags.render_all(), r.diags.error_count()};
}

constexpr const char* kHeader = "%\nO0001\nG18 G21 G40 G90\n";

// ---- the lathe frame (cl.radial_axis: auto) ----

TEST(RadialAxis, FoundInYWithANoteAndWrittenAsX) {
  Posted p =
      post("FEDRAT/0.1,MMPR\nRAPID\nGOTO/0,0,5\nRAPID\nGOTO/0,10,5\nGOTO/0,10,0\nFINI\n", lathe());
  EXPECT_EQ(p.nc, std::string(kHeader) + "G0 X0. Z5.\nX20.\nG1 Z0. G95 F0.1\nM30\n%\n");
  EXPECT_EQ(p.diags,
            "t.cl:5:1: note: the radius is CL Y and CL X is 0 (cl.radial_axis: auto, found here)\n"
            "  GOTO/0,10,5\n"
            "  ^\n");
}

TEST(RadialAxis, YIsTheSameProgramAsX) {
  const Posted y = post("FEDRAT/0.1,MMPR\nGOTO/0,10,5\nGOTO/0,8,-20\nFINI\n", lathe());
  const Posted x = post("FEDRAT/0.1,MMPR\nGOTO/10,0,5\nGOTO/8,0,-20\nFINI\n", lathe());
  EXPECT_EQ(y.nc, x.nc);
  EXPECT_EQ(x.diags, "");  // X, the usual frame, goes without a note
}

TEST(RadialAxis, MovingInBothIsAnErrorWhereItBecomesAmbiguous) {
  Posted p = post("RAPID\nGOTO/0,0,5\nRAPID\nGOTO/0,12,0\nRAPID\nGOTO/3,12,0\nFINI\n", lathe());
  EXPECT_EQ(p.errors, 1u);
  EXPECT_EQ(p.diags,
            "t.cl:4:1: note: the radius is CL Y and CL X is 0 (cl.radial_axis: auto, found here)\n"
            "  GOTO/0,12,0\n"
            "  ^\n"
            "t.cl:6:1: error: CL X = 3 but the radius is CL Y (found at line 4): the program moves "
            "in both, off the lathe plane (is this a milling program? set cl.radial_axis to post "
            "it anyway)\n"
            "  GOTO/3,12,0\n"
            "  ^\n");
  Posted q = post("RAPID\nGOTO/1,2,3\nFINI\n", lathe());
  EXPECT_EQ(q.diags,
            "t.cl:2:1: error: CL X = 1 and Y = 2: the point is off the lathe plane, so neither can "
            "be the radius (cl.radial_axis: auto); is this a milling program? Set cl.radial_axis "
            "to post it anyway\n"
            "  GOTO/1,2,3\n"
            "  ^\n");
}

TEST(RadialAxis, AnArcAxisDecidesIt) {
  Posted p =
      post("FEDRAT/0.1,MMPR\nGOTO/0,0,5\nCIRCLE/0,0,0,-1,0,0,5\nGOTO/0,5,0\nFINI\n", lathe());
  EXPECT_EQ(p.nc, std::string(kHeader) + "G1 X0. Z5. G95 F0.1\nG3 X10. Z0. I0. K-5.\nM30\n%\n");
  EXPECT_EQ(p.diags,
            "t.cl:3:1: note: the radius is CL Y: the arc turns about CL X (cl.radial_axis: auto, "
            "found here)\n"
            "  CIRCLE/0,0,0,-1,0,0,5\n"
            "  ^\n");
}

// ---- SYN, PPFUN, DNTCUT/CUT ----

TEST(CamWords, SynIgnoresOrRenamesWords) {
  Posted p = post(
      "SYN/'TLAXIS','$$*TLAXIS','MOVE','GOTO'\nTLAXIS/0,1,0\nRAPID\nMOVE/10,0,2\nFINI\n", lathe());
  EXPECT_EQ(p.nc, std::string(kHeader) + "G0 X20. Z2.\nM30\n%\n");
  EXPECT_EQ(p.diags,
            "t.cl:1:1: note: SYN/: TLAXIS statements are ignored from here on\n"
            "  SYN/'TLAXIS','$$*TLAXIS','MOVE','GOTO'\n"
            "  ^\n"
            "t.cl:1:1: note: SYN/: MOVE stands for GOTO from here on\n"
            "  SYN/'TLAXIS','$$*TLAXIS','MOVE','GOTO'\n"
            "  ^\n");
}

TEST(CamWords, SynReachesGotoToo) {
  Posted p = post("SYN/'GOTO','$$'\nRAPID\nGOTO/10,0,2\nFINI\n", lathe());
  EXPECT_EQ(p.nc, std::string(kHeader) + "M30\n%\n");
}

TEST(CamWords, SynNeedsPairsOfWords) {
  Posted p = post("SYN/'A'\nSYN/'A',5\nFINI\n", lathe());
  EXPECT_EQ(p.diags,
            "t.cl:1:5: error: SYN/ takes pairs of quoted words: SYN/'word','replacement'[,…]: "
            "the last word has no replacement\n"
            "  SYN/'A'\n"
            "      ^\n"
            "t.cl:2:9: error: SYN/ takes quoted words, found number 5\n"
            "  SYN/'A',5\n"
            "          ^\n");
}

// NC_THREAD_WITHOUT_TAP_HEAD in ICAM's table: a message where the cycle would be; the hole after
// it must not become a plain move.
TEST(CamWords, PpfunMessageOfAnOperationWithoutOutputIsAnError) {
  Posted p = post(
      "SPINDL/600,RPM,CLW\nRAPID\nGOTO/0,0,10\n"
      "PPFUN/3,8,'NC_THREAD_WITHOUT_TAP_HEAD_cycle_not_available'\nGOTO/0,0,0\nCYCLE/OFF\nFINI\n",
      lathe());
  EXPECT_EQ(p.errors, 1u);
  EXPECT_EQ(p.diags,
            "t.cl:4:11: error: PPFUN/3: ICAM's table reports "
            "'NC_THREAD_WITHOUT_TAP_HEAD_cycle_not_available' here: the operation has no output in "
            "the table, and the holes after it would be posted as plain moves\n"
            "  PPFUN/3,8,'NC_THREAD_WITHOUT_TAP_HEAD_cycle_not_available'\n"
            "            ^\n");
}

TEST(CamWords, PpfunIsSkippedWithANote) {
  Posted p = post("PPFUN/15,1318046,OFF\nPPFUN/15,1319003,OFF\nFINI\n", lathe());
  EXPECT_EQ(p.nc, std::string(kHeader) + "M30\n%\n");
  EXPECT_EQ(p.diags,
            "t.cl:1:1: note: PPFUN records skipped (nothing a lathe program needs)\n"
            "  PPFUN/15,1318046,OFF\n"
            "  ^\n");
}

TEST(CamWords, DntcutMovesSetThePositionOnly) {
  Posted p = post(
      "FEDRAT/0.1,MMPR\nGOTO/10,0,5\nDNTCUT\nGOTO/11,0,2\nGODLTA/1,0,0\nCUT\nGOTO/12,0,0\nFINI\n",
      lathe());
  EXPECT_EQ(p.nc, std::string(kHeader) + "G1 X20. Z5. G95 F0.1\nX24. Z0.\nM30\n%\n");
  EXPECT_EQ(p.diags, "");
}

// ---- tool data ----

TEST(CamWords, ToolDataIsReadNotWritten) {
  Posted p = post(
      "CUTTER/0.8\nTOOLNO/1,TURN,1,0,3,0.4,0,0,0.1,MMPR,500,SFM,CCLW,ON,0,NOTE\n"
      "TPRINT/SDJCL 1210 D07\nLOADTL/1,1,1\nSWITCH/3\nFINI\n",
      lathe());
  EXPECT_EQ(p.nc, std::string(kHeader) + "T0101\nM30\n%\n");
  EXPECT_EQ(p.diags, "");
}

// The tool data CATIA writes before LOADTL describe the tool it loads (ToolInfo, which the tool
// list reads); SWITCH after the change sets the quadrant of the tool in use.
TEST(CamWords, ToolDataBeforeTheChangeDescribeTheToolItLoads) {
  const Machine m = lathe();
  StringSink out;
  NcProgram prog(m, out);
  Diagnostics diags("t.cl");
  PostState s(m, prog, diags, {});
  const std::string cl =
      "PPRINT TOOL: Thread Tool.1\n"
      "TOOLNO/1,TURN,1,0,3,0.4,0,0,0.1,MMPR,500,SFM,CCLW,ON,0,NOTE\n"
      "TPRINT/SDJCL 1210 D07\nLOADTL/1,1,1\nSWITCH/9\nTURRET/7,OSETNO,8,SETOOL,0,0,0\n";
  ClReader reader(cl, diags);
  Statement st;
  std::vector<ToolInfo> after;
  while (reader.next(st)) {
    find_statement(st.major)->handler(s, st);
    after.push_back(s.tool);
  }
  ASSERT_EQ(after.size(), 6u);
  const ToolInfo& t1 = after[3];  // after LOADTL
  EXPECT_EQ(t1.number, 1);
  EXPECT_EQ(t1.offset, 1);
  EXPECT_EQ(t1.text, "SDJCL 1210 D07");  // TPRINT after PPRINT TOOL:
  EXPECT_EQ(t1.nose_radius, 0.4);
  EXPECT_EQ(t1.tip_quadrant, 3);
  EXPECT_EQ(t1.feed, "0.1 MMPR");
  EXPECT_EQ(t1.speed, "500 SFM");
  EXPECT_EQ(after[4].tip_quadrant, 9);  // SWITCH/9
  const ToolInfo& t7 = after[5];        // TURRET: nothing pending, a bare tool
  EXPECT_EQ(t7.number, 7);
  EXPECT_EQ(t7.offset, 8);
  EXPECT_EQ(t7.text, "");
  EXPECT_FALSE(t7.nose_radius.has_value());
  EXPECT_EQ(diags.error_count(), 0u);
}

TEST(CamWords, BadToolDataIsAnErrorAtItsColumn) {
  Posted p = post("SWITCH/12\nCUTTER/-1\nTOOLNO/TURN\nFINI\n", lathe());
  EXPECT_EQ(p.diags,
            "t.cl:1:8: error: SWITCH/ takes a tool-tip quadrant 0..9, got 12\n"
            "  SWITCH/12\n"
            "         ^\n"
            "t.cl:2:8: error: cutter diameter must not be negative, got -1\n"
            "  CUTTER/-1\n"
            "         ^\n"
            "t.cl:3:8: error: expected a tool number but found 'TURN'\n"
            "  TOOLNO/TURN\n"
            "         ^\n");
}

// ---- surface speed units ----

TEST(SurfaceSpeed, SfmInAMetricFileIsMetresPerMinuteByDefault) {
  Posted p = post("SPINDL/500,SFM,CCLW\nFINI\n", lathe());
  EXPECT_EQ(p.nc, std::string(kHeader) + "G50 S4000\nG96 S500 M4\nM30\n%\n");
  EXPECT_EQ(p.diags,
            "t.cl:1:1: note: SFM in a metric file: read as m/min, the file's unit "
            "(cl.surface_speed: file, as CATIA V5 writes it; `word` converts)\n"
            "  SPINDL/500,SFM,CCLW\n"
            "  ^\n");
}

TEST(SurfaceSpeed, WordConvertsFeetAndMetres) {
  Posted p = post("SPINDL/500,SFM,CCLW\nFINI\n", lathe({"cl.surface_speed=word"}));
  EXPECT_EQ(p.nc, std::string(kHeader) + "G50 S4000\nG96 S152 M4\nM30\n%\n");  // 152.4 m/min
  EXPECT_EQ(p.diags,
            "t.cl:1:1: note: 500 SFM written as 152.4 m/min (cl.surface_speed: word)\n"
            "  SPINDL/500,SFM,CCLW\n"
            "  ^\n");
  Posted q = post("UNITS/INCHES\nSPINDL/200,SMM,CLW\nFINI\n", lathe({"cl.surface_speed=word"}));
  EXPECT_EQ(q.nc, "%\nO0001\nG18 G20 G40 G90\nG50 S4000\nG96 S656 M3\nM30\n%\n");
  EXPECT_EQ(q.diags,
            "t.cl:2:1: note: 200 SMM written as 656.168 ft/min (cl.surface_speed: word)\n"
            "  SPINDL/200,SMM,CLW\n"
            "  ^\n");
}

// ---- Fusion's MOVARC ----

TEST(CamWords, MovarcIsTheCircleOfItsGoto) {
  Posted p = post(
      "FEDRAT/0.1,MMPR\nGOTO/20.4,0,-30\nMOVARC/25,0,-30,0,1,0,4.6,ANGLE,90\nGOTO/25,0,-25.4\n"
      "MOVARC/CENTER,25,0,-20,AXIS,0,-1,0,RADIUS,5.4\nGOTO/30.4,0,-20\nMOVARC/1,2\nFINI\n",
      lathe());
  EXPECT_EQ(p.diags,
            "t.cl:7:1: error: MOVARC/ takes cx,cy,cz,i,j,k,r[,ANGLE,a] or "
            "CENTER,cx,cy,cz,AXIS,i,j,k,RADIUS,r\n"
            "  MOVARC/1,2\n"
            "  ^\n");
  Posted q = post(
      "FEDRAT/0.1,MMPR\nGOTO/20.4,0,-30\nMOVARC/25,0,-30,0,1,0,4.6,ANGLE,90\nGOTO/25,0,-25.4\n"
      "MOVARC/CENTER,25,0,-20,AXIS,0,-1,0,RADIUS,5.4\nGOTO/30.4,0,-20\nFINI\n",
      lathe());
  EXPECT_EQ(q.nc, std::string(kHeader) +
                      "G1 X40.8 Z-30. G95 F0.1\nG3 X50. Z-25.4 I4.6 K0.\nG2 X60.8 Z-20. I0. "
                      "K5.4\nM30\n%\n");
  EXPECT_EQ(q.diags, "");
}

// ---- CATIA's CYCLE/LATHTHRD ----

TEST(CamWords, LaththrdIsRefusedNamingWhatIsMissing) {
  Posted p = post(
      "SPINDL/500,RPM\nCYCLE/LATHTHRD,1.5,MMPR,1.5,NOM_DIAM,20,DEPTH,0.92,NB_PATHES,5,"
      "COORD,9.08,-30,START_THRD_RAD,10,LENGTH,32\nGOTO/10,0,2\nCYCLE/OFF\n"
      "CYCLE/LATHTHRD,1.5,MMPR,1.5,DEPTH,0.92\nCYCLE/OFF\nFINI\n",
      lathe());
  EXPECT_EQ(p.errors, 2u);
  EXPECT_EQ(p.diags,
            "t.cl:2:1: error: CYCLE/LATHTHRD does not say where the thread starts along the axis "
            "(COORD is its end; LENGTH and LEAD_IN_DIST give no side and no origin): the thread "
            "cannot be planned; write it as THREAD/ON … THREAD/OFF (CATIA's ICAM tables do)\n"
            "  CYCLE/LATHTHRD,1.5,MMPR,1.5,NOM_DIAM,20,DEPTH,0.92,NB_PATHES,5,COORD,9.08,-30,"
            "START_THRD_RAD,10,LENGTH,32\n"
            "  ^\n"
            "t.cl:5:1: error: CYCLE/LATHTHRD without NB_PATHES: the thread cannot be planned\n"
            "  CYCLE/LATHTHRD,1.5,MMPR,1.5,DEPTH,0.92\n"
            "  ^\n");
}

// ---- THREAD/TURN,pitch ----

TEST(CamWords, ThreadTurnWithANumberIsThePitch) {
  const char* cl = "SPINDL/200,RPM\nTHREAD/TURN,{}\nRAPID\nGOTO/10,0,2\nGOTO/10,0,-20\nFINI\n";
  const std::string expected =
      std::string(kHeader) + "G97 S200 M3\nG0 X20. Z2.\nG33 Z-20. F2.5\nM30\n%\n";
  for (const char* pitch : {"2.5", "2.5,MMPR", "(5/2)"}) {
    std::string text(cl);
    text.replace(text.find("{}"), 2, pitch);
    Posted p = post(text, lathe());
    EXPECT_EQ(p.nc, expected) << pitch;
    EXPECT_EQ(p.diags, "") << pitch;
  }
}

// ---- the CATIA + ICAM thread (issue 15) against the same thread in plain numbers ----

struct IcamThread {
  const char* units;
  const char* pitch_expr;   // ICAM: PITCH/(1/p)
  const char* pitch_plain;  // the same value written out
  int starts;
  const char* clearance;  // GODLTA: + external, - internal
  const char* cutang;     // 180 external, 0 internal
  const char* radius;     // thread radius
  const char* start;      // radius + clearance
  const char* depth;
};

// As ICAM's CATIA table writes it (reference/cam/ICAM_MM_pptable_threading_excerpt.txt).
std::string icam_form(const IcamThread& t) {
  std::string r = std::string("UNITS/") + t.units +
                  "\nPPFUN/15,1318046,OFF\nPPFUN/15,1319003,OFF\nSYN/'TLAXIS','$$*TLAXIS'\n"
                  "PPRINT TOOL: Thread Tool.1\nTURRET/7,OSETNO,7,SETOOL,0.0,0.0,0.0\n"
                  "TLAXIS/0,1,0\nSPINDL/500,RPM,CLW\n";
  r += std::string("PITCH/") + t.pitch_expr + ",MULTRD," + std::to_string(t.starts) + "\n";
  r += std::string("DNTCUT\nGOTO/") + t.radius + ",0,2\nGODLTA/" + t.clearance + ",0,0\nCUT\n";
  r += std::string("THREAD/ON,DEPTH,") + t.depth + ",CUTS,5,CUTANG," + t.cutang +
       ",FINCUT,1,$\n\tATANGL,30,1.5,TLANGL,60,OPTION,1\n";
  r += std::string("GOTO/") + t.radius + ",0,2\nGOTO/" + t.radius + ",0,-30\nTHREAD/OFF\nFINI\n";
  return r;
}

// The same thread with plain numbers; comment lines keep THREAD/ON on line 14 as above (the NC
// names its line).
std::string plain_form(const IcamThread& t) {
  std::string r = std::string("UNITS/") + t.units +
                  "\nPPRINT TOOL: Thread Tool.1\nTURRET/7,OSETNO,7\nSPINDL/500,RPM,CLW\n";
  r += std::string("PITCH/") + t.pitch_plain + ",MULTRD," + std::to_string(t.starts) + "\n";
  r += std::string("FROM/") + t.start + ",0,2\n$$\n$$\n$$\n$$\n$$\n$$\n$$\n";
  r += std::string("THREAD/ON,DEPTH,") + t.depth + ",CUTS,5,CUTANG," + t.cutang +
       ",FINCUT,1,ATANGL,30,1.5,TLANGL,60,OPTION,1\n";
  r += std::string("GOTO/") + t.radius + ",0,2\nGOTO/" + t.radius + ",0,-30\nTHREAD/OFF\nFINI\n";
  return r;
}

TEST(IcamThread, PostsExactlyAsThePlainThread) {
  const IcamThread cases[] = {
      {"MM", "(1/2.5)", "0.4", 1, "1", "180", "10", "11", "1.534"},  // the thread
      {"MM", "(1/2)", "0.5", 2, "1", "180", "10", "11", "1.2"},      // MULTRD 2
      {"MM", "(1/1.5)", "0.6666666666666666", 1, "-1", "0", "8", "7", "0.92"},  // internal
      {"INCHES", "(1/0.1)", "10", 1, "0.04", "180", "0.5", "0.54", "0.06"},     // inch
  };
  for (const char* name : {"generic-lathe", "linuxcnc-lathe"}) {
    const Machine m = lathe({}, name);
    for (const IcamThread& t : cases) {
      const Posted icam = post(icam_form(t), m);
      const Posted plain = post(plain_form(t), m);
      EXPECT_EQ(icam.errors, 0u) << name << " " << t.pitch_expr << "\n" << icam.diags;
      EXPECT_EQ(plain.errors, 0u) << name << " " << t.pitch_expr << "\n" << plain.diags;
      EXPECT_NE(icam.nc.find("(thread line 14: "), std::string::npos) << icam.nc;
      EXPECT_EQ(icam.nc, plain.nc) << name << " " << t.pitch_expr;
    }
  }
}

}  // namespace
}  // namespace clpost

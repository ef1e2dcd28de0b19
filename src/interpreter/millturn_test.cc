// Mill-turn: milling tools, the live spindle, the C axis (millturn.cc, docs/millturn.md).
#include <gtest/gtest.h>

#include "interpreter/millturn.h"
#include "interpreter/post_test_util.h"

namespace clpost {
namespace {

using test::load;
using test::post;
using test::Posted;

// The CATIA mill-turn words of issue #25 (realcam/catia_toussaint writes them so).
constexpr const char* kCatia =
    "TDATA/MILL,   38.000000,   38.000000,   38.000000,DIAM,    1.000000\n"
    "LOADTL/3,ADJUST,1,SPINDL,15000,MILL\n"
    "SPINDL/3000.0000,RPM,CLW\n"
    "ROTABL/90.000000,CLW,CAXIS\n"
    "SPINDL/OFF\n"
    "LOADTL/1,ADJUST,9,TURN\n"
    "SPINDL/1000,RPM,CLW\n"
    "FEDRAT/0.2,MMPR\n"
    "GOTO/20,0,5\n"
    "FINI\n";

// A Haas lathe with live tools and C, as --set gives it (Haas codes: reference/millturn.md).
Machine haas_live() {
  return load("haas-st",
              {"millturn.live_tools=true", "millturn.c_axis=true", "millturn.live_max_rpm=4000",
               "templates.live_spindle_rpm=[\"{direction} P{rpm}\"]",
               "templates.live_spindle_stop=M135", "templates.c_index=[\"G0 {address}{c}\"]",
               "codes.live_spindle_cw=M133", "codes.live_spindle_ccw=M134", "codes.c_engage=M154",
               "codes.c_disengage=M155", "codes.c_clamp=M14", "codes.c_unclamp=M15"});
}

// The issue's silent bug: on a lathe without live tools the milling tool's SPINDL turned the
// main spindle, with the part, at the live tool's speed. Now its LOADTL is an error (the MILL
// word), and its SPINDL (above the lathe's 4000 rpm) is not reported again.
TEST(MillTurn, MillingToolIsAnErrorAtItsLoadtlWithoutLiveTools) {
  Posted p = post(kCatia, load("fanuc-0i-t"));
  EXPECT_EQ(p.errors, 2u) << p.diags;
  EXPECT_NE(p.diags.find("t.cl:2:32: error: tool 3 is a milling (live) tool (LOADTL's MILL word), "
                         "but machine 'fanuc-0i-t' has no live tools (millturn.live_tools: "
                         "false): its SPINDL would turn the main spindle, with the part, at the "
                         "live tool's speed\n"
                         "  LOADTL/3,ADJUST,1,SPINDL,15000,MILL\n"
                         "                                 ^\n"),
            std::string::npos)
      << p.diags;
  EXPECT_NE(p.diags.find("t.cl:4:22: error: ROTABL/ positions a C axis, and machine 'fanuc-0i-t' "
                         "has none (millturn.c_axis: false)\n"),
            std::string::npos)
      << p.diags;
  EXPECT_EQ(p.diags.find("rpm"), std::string::npos) << p.diags;
}

// Every way the CL says a tool mills, on a lathe without live tools: the error names it.
TEST(MillTurn, EveryMillWordMakesAMillingTool) {
  const Machine m = load("generic-lathe");
  const std::pair<const char*, const char*> cases[] = {
      {"TDATA/MILL,10\nLOADTL/3\n", "(TDATA/MILL at line 1)"},
      {"TLDATA/MILL,10,0,50,0,0\nLOAD/TOOL,3\n", "(TLDATA/MILL at line 1)"},
      {"TOOLNO/3,MILL,OSETNO,3\nLOADTL/3\n", "(TOOLNO/…,MILL at line 1)"},
      {"APPLY/MILL\nLOADTL/3\n", "(APPLY/MILL at line 1)"},
      {"SET/MODE,MILL\nLOADTL/3\n", "(SET/MODE,MILL at line 1)"},
      {"MODE/MILL,FACE\nLOADTL/3\n", "(MODE/MILL at line 1)"},
  };
  for (const auto& [cl, said] : cases) {
    Posted p = post(cl, m);
    EXPECT_EQ(p.errors, 1u) << cl << p.diags;
    EXPECT_NE(p.diags.find(std::string("t.cl:2:1: error: tool 3 is a milling (live) tool ") + said),
              std::string::npos)
        << cl << p.diags;
  }
  // The tool's own word wins over the mode; TURN tools and other SET/ words are as before.
  EXPECT_EQ(post("APPLY/MILL\nLOADTL/3,TURN\nFINI\n", m).errors, 0u);
  EXPECT_EQ(post("APPLY/MILL\nAPPLY/TURN\nLOADTL/3\nFINI\n", m).errors, 0u);
  Posted set = post("SET/MODE,ABSOL\nFINI\n", m);
  EXPECT_EQ(set.errors, 0u);
  EXPECT_NE(set.nc.find("(SET/MODE,ABSOL)"), std::string::npos) << set.nc;
}

// The issue's words post on linuxcnc-lathe-c: the live tool is spindle 1, C an axis of its own
// (no engage or clamp code), and the turning tool turns spindle 0. Its live tool's limit is
// 6000 rpm: the issue's 15000 needs it raised, as the issue raised limits.max_rpm.
TEST(MillTurn, TheIssuesCatiaWordsPostOnLinuxcncLatheC) {
  const std::string cl =
      std::string(kCatia).replace(std::string(kCatia).find("3000.0000"), 9, "15000.0000");
  Posted p = post(cl, load("linuxcnc-lathe-c", {"millturn.live_max_rpm=15000"}));
  EXPECT_EQ(p.errors, 0u) << p.diags;
  EXPECT_EQ(p.nc,
            "%\nG7 G18 G21 G90 G40 G80\nT3 M6 G43 H1\nM3 $1 S15000\nG0 C90.\nM5 $1\n"
            "T1 M6 G43 H9\nG97 S1000 M3\nG1 X40. Z5. G95 F0.2\nM2\n%\n");
  Posted q = post(cl, load("linuxcnc-lathe-c"));
  EXPECT_EQ(q.errors, 1u) << q.diags;
  EXPECT_NE(q.diags.find("t.cl:3:8: error: live tool speed 15000 rpm exceeds the machine's "
                         "maximum 6000 rpm (millturn.live_max_rpm)"),
            std::string::npos)
      << q.diags;
}

// The shipped live-tool machines with their builders' codes (reference/millturn.md section 2):
// Takisawa on Fanuc M76/M75 engage, M70/M72 live tool, M73/M74 clamp; Haas M154/M155, M133 P,
// M135, M14/M15.
TEST(MillTurn, TheIssuesCatiaWordsOnTheShippedLiveMachines) {
  EXPECT_EQ(post(kCatia, load("fanuc-0i-tf-live")).nc,
            "%\nO0001\nG18 G21 G40 G97\nT0301\nM76\nM70 S3000\nG0 C90.\nM73\nM72\nT0109\n"
            "M74\nM75\nG97 S1000 M3\nG1 X40. Z5. G99 F0.2\nM30\n%\n");
  EXPECT_EQ(post(kCatia, load("haas-st-20y")).nc,
            "%\nO00001\nG18 G21 G40 G97\nT0301\nM154\nM133 P3000\nG0 C90.\nM14\nM135\n"
            "T0109\nM15\nM155\nG97 S1000 M3\nG1 X40. Z5. G99 F0.2\nM30\n%\n");
}

// With live tools: the live spindle's codes, C engaged after the tool change, clamped after it
// moves; the turning tool's SPINDL unclamps and disengages C first.
TEST(MillTurn, LiveToolAndCAxisOnAHaas) {
  Posted p = post(kCatia, haas_live());
  EXPECT_EQ(p.errors, 0u) << p.diags;
  EXPECT_EQ(p.nc,
            "%\nO00001\nG18 G21 G40 G97\nT0301\nM154\nM133 P3000\nG0 C90.\nM14\nM135\nT0109\n"
            "M15\nM155\nG97 S1000 M3\nG1 X40. Z5. G99 F0.2\nM30\n%\n");
}

// The main spindle turning when a milling tool comes is stopped; it turns again as the CL left
// it when the next turning tool moves. C does not move, unclamp or clamp for the same angle.
TEST(MillTurn, MainSpindleStopsForMillingAndCMovesOnlyWhenItChanges) {
  Posted p = post(
      "SPINDL/500,RPM,CLW\nLOADTL/3,MILL\nSPINDL/2000,RPM,CCLW\nROTABL/30,CAXIS\n"
      "ROTABL/30,CAXIS\nROTABL/390,CAXIS\nLOADTL/1\nRAPID\nGOTO/20,0,5\nFINI\n",
      haas_live());
  EXPECT_EQ(p.errors, 0u) << p.diags;
  EXPECT_EQ(p.nc,
            "%\nO00001\nG18 G21 G40 G97\nG97 S500 M3\nM5\nT0303\nM154\nM134 P2000\nG0 C30.\nM14\n"
            "M135\nT0101\nM15\nM155\nG97 S500 M3\nG0 X40. Z5.\nM30\n%\n");
}

TEST(MillTurn, LiveToolLimitsAndMillingMotionAreLocatedErrors) {
  Posted p = post(
      "FEDRAT/100,MMPM\nLOADTL/3,MILL\nSPINDL/5000,RPM,CLW\nSPINDL/100,SMM\nGOTO/10,5,0,1,0,0\n"
      "GOTO/10,6,0\nROTABL/10,BAXIS\nFINI\n",
      haas_live());
  EXPECT_EQ(p.errors, 4u) << p.diags;
  EXPECT_NE(p.diags.find("t.cl:3:8: error: live tool speed 5000 rpm exceeds the machine's maximum "
                         "4000 rpm (millturn.live_max_rpm)"),
            std::string::npos)
      << p.diags;
  EXPECT_NE(p.diags.find("t.cl:4:12: error: a live tool turns at a speed in RPM: a surface speed "
                         "for milling tool 3 is not supported"),
            std::string::npos)
      << p.diags;
  // One error for the tool's motions, at the first: a radial tool's tip 5 mm off the line of its
  // axis through the centre line needs Y (milling_motion.cc).
  EXPECT_NE(p.diags.find("t.cl:5:1: error: milling motion with live tool 3 (loaded at line 2): "
                         "the tip (10, 5, 0) is 5.0000 mm off the line of the tool axis (1, 0, 0) "
                         "through the centre line (millturn.xzc_tolerance 0.005): a radial tool "
                         "reaches it with a Y axis only, and machine 'haas-st' has none "
                         "(docs/millturn.md)"),
            std::string::npos)
      << p.diags;
  EXPECT_NE(p.diags.find("t.cl:7:11: error: ROTABL/…,BAXIS: a lathe's rotary axis is C; machine "
                         "'haas-st' has no B axis"),
            std::string::npos)
      << p.diags;
}

// C from 0: the CL's direction, else the shortest way. A rollover control (0 <= C < 360)
// goes the shortest way itself, so a turn the CL gives the other way, or of 180 degrees or
// more, is written in equal steps under 180 degrees; a continuous C is the last C plus the turn.
TEST(MillTurn, CStepsTakeTheClsDirectionElseTheShortestWay) {
  const Machine roll = haas_live();
  Machine cont = roll;
  cont.c_rotation = CRotation::kContinuous;
  using V = std::vector<double>;
  EXPECT_EQ(c_steps(roll, std::nullopt, -90, false, std::nullopt), V{270});
  EXPECT_EQ(c_steps(cont, std::nullopt, -90, false, std::nullopt), V{-90});
  EXPECT_EQ(c_steps(roll, 0.0, 90, false, std::nullopt), V{90});
  EXPECT_EQ(c_steps(roll, 0.0, 270, false, std::nullopt), V{270});  // -90, the shortest
  EXPECT_EQ(c_steps(cont, 0.0, 270, false, std::nullopt), V{-90});
  EXPECT_EQ(c_steps(roll, 0.0, 90, false, -1), (V{225, 90}));  // -270 in two -135 steps
  EXPECT_EQ(c_steps(cont, 0.0, 90, false, -1), V{-270});
  EXPECT_EQ(c_steps(roll, 0.0, 180, false, std::nullopt), (V{90, 180}));
  EXPECT_EQ(c_steps(roll, 350.0, 10, false, std::nullopt), V{10});   // +20 across 0
  EXPECT_EQ(c_steps(cont, 350.0, 10, false, std::nullopt), V{370});  // a continuous angle
  EXPECT_EQ(c_steps(roll, 10.0, 370, false, 1), V{});                // there already
  EXPECT_EQ(c_steps(roll, 10.0, 360, true, 1), (V{130, 250, 10}));   // INCR: one whole turn
  EXPECT_EQ(c_steps(cont, 10.0, 30, true, -1), V{-20});
}

// CLW decreases C by default (millturn.c_clw); ROTATE/ (NX) reads as ROTABL/. At FINI C is
// unclamped and disengaged (M15, M155).
TEST(MillTurn, RotablDirectionsAndRotate) {
  Machine m = haas_live();
  Posted p = post(
      "LOADTL/3,MILL\nROTABL/0,CAXIS\nROTABL/90,CAXIS,CLW\n"
      "ROTATE/CAXIS,INCR,30,CCLW\nFINI\n",
      m);
  EXPECT_EQ(p.errors, 0u) << p.diags;
  EXPECT_EQ(p.nc,
            "%\nO00001\nG18 G21 G40 G97\nT0303\nM154\nG0 C0.\nM14\nM15\nG0 C225.\nG0 C90.\nM14\n"
            "M15\nG0 C120.\nM14\nM15\nM155\nM30\n%\n");
}

// Without a C axis and without an axis word, ROTABL stays the comment it was (CATIA with ICAM
// writes ROTABL/0,,TABLE,CLW before centre-line drilling on plain lathes).
TEST(MillTurn, RotablWithoutAxisWordOnAPlainLatheIsAComment) {
  Posted p = post("ROTABL/0,,TABLE,CLW\nFINI\n", load("generic-lathe"));
  EXPECT_EQ(p.errors, 0u);
  EXPECT_NE(p.nc.find("(ROTABL/0,,TABLE,CLW)"), std::string::npos) << p.nc;
}

TEST(MillTurn, ChannelTwoIsAWarningNamingTheMissingChannel) {
  Posted p = post("CHANNEL,2\nFINI\n", load("generic-lathe"));
  EXPECT_EQ(p.errors, 0u);
  EXPECT_EQ(p.diags,
            "t.cl:1:9: warning: the CL is the program of channel 2 of a multi-channel machine, and "
            "machine 'generic-lathe' has one channel (no channel 2): posted as a one-channel "
            "program\n"
            "  CHANNEL,2\n"
            "          ^\n");
  EXPECT_NE(p.nc.find("(CHANNEL,2)"), std::string::npos) << p.nc;
  Posted one = post("CHANNEL,1\nCHANNEL,\nFINI\n", load("generic-lathe"));
  EXPECT_EQ(one.diags, "");
  EXPECT_NE(one.nc.find("(CHANNEL,1)\n(CHANNEL,)"), std::string::npos) << one.nc;
}

TEST(MillTurn, SyncIsAWarningNamingTheMissingChannel) {
  Posted p = post("SYNC/2,1,2,1\nFINI\n", load("generic-lathe"));
  EXPECT_EQ(p.errors, 0u);
  EXPECT_NE(p.diags.find("t.cl:1:1: warning: SYNC/ synchronises this program with another "
                         "channel, and machine 'generic-lathe' has one channel (no second channel "
                         "to wait for): written as a comment"),
            std::string::npos)
      << p.diags;
  EXPECT_NE(p.nc.find("(SYNC/2,1,2,1)"), std::string::npos) << p.nc;
}

// A face hole of a live tool (docs/millturn.md): two holes of a bolt circle at radius 30 (the
// GOTO's X), C 0 and 90 (ROTABL). On linuxcnc-lathe-c G81 takes X as a diameter in G7, so X60
// (rs274 proves it: tests/rs274_test.cc); C is written by ROTABL before each hole.
constexpr const char* kFaceHoles =
    "LOADTL/3,MILL\nSPINDL/2000,RPM,CLW\nROTABL/0,CAXIS\nFROM/30,0,5\nFEDRAT/100,MMPM\n"
    "CYCLE/DRILL,8,MMPM,100,CLEAR,2\nGOTO/30,0,0\nROTABL/90,CAXIS\nGOTO/30,0,0\nCYCLE/OFF\n"
    "SPINDL/OFF\nFINI\n";

TEST(MillTurn, FaceHolesAtXWithCOnLinuxcncLatheC) {
  Posted p = post(kFaceHoles, load("linuxcnc-lathe-c"));
  EXPECT_EQ(p.errors, 0u) << p.diags;
  EXPECT_EQ(p.nc,
            "%\nG7 G18 G21 G90 G40 G80\nT3 M6 G43 H3\nM3 $1 S2000\nG0 C0.\n"
            "(hole at CL line 7: drilling at X60. C0. to Z-8.)\nG0 X60. Z5.\nG17\n"
            "G98 G94 G81 X60. Y0 Z-8. R2. F100.\nG80\nG18\nG0 C90.\n"
            "(hole at CL line 9: drilling at X60. C90. to Z-8.)\nG17\n"
            "G98 G94 G81 X60. Y0 Z-8. R2. F100.\nG80\nG18\nM5 $1\nM2\n%\n");
}

// The approach of a live tool at the C index is an XZ move (Y 0, C indexed): written as a
// lathe's rapid. Off the X axis it is milling (milling_motion.cc): X and C from the point's
// radius and angle, and C back at its index before the hole.
TEST(MillTurn, ALiveToolsXzMoveAtTheCIndexIsWritten) {
  std::string cl = kFaceHoles;
  cl.replace(cl.find("FROM/30,0,5"), 11, "RAPID\nGOTO/30,0,5");
  Posted p = post(cl, load("linuxcnc-lathe-c"));
  EXPECT_EQ(p.errors, 0u) << p.diags;
  EXPECT_NE(p.nc.find("G0 C0.\nG0 X60. Z5.\n(hole at CL line 8: drilling at X60. C0. to Z-8.)\n"
                      "G17\nG98 G94 G81 X60. Y0 Z-8. R2. F100.\n"),
            std::string::npos)
      << p.nc;
  std::string off_axis = cl;
  off_axis.replace(off_axis.find("GOTO/30,0,5"), 11, "GOTO/30,2,5");
  Posted q = post(off_axis, load("linuxcnc-lathe-c"));
  EXPECT_EQ(q.errors, 0u) << q.diags;
  // hypot(30, 2) = 30.06659 (X60.13319), atan2(2, 30) = 3.8141 degrees.
  EXPECT_NE(q.nc.find("G0 C0.\nG0 X60.13319 Z5. C3.8141\nG0 C0.\n"
                      "(hole at CL line 8: drilling at X60. C0. to Z-8.)\n"),
            std::string::npos)
      << q.nc;
}

// Haas G81 on the face at X (a diameter) with C clamped at its index (reference/millturn.md
// section 2, Fusion's haas vmt-750.cps).
TEST(MillTurn, FaceHolesOnHaasSt20y) {
  Posted p = post(kFaceHoles, load("haas-st-20y"));
  EXPECT_EQ(p.errors, 0u) << p.diags;
  EXPECT_NE(p.nc.find("M15\nG0 C90.\nM14\n(HOLE AT CL LINE 9: DRILLING AT X60. C90. TO Z-8.)\n"
                      "G98 G81 X60. Z-8. R2. F100.\nG80\n"),
            std::string::npos)
      << p.nc;
}

// The CL's own C clamp (ICAM CLAMP/ON|OFF|AUTO,CAXIS, NX-to-APT CLAMP/CAXIS,ON|OFF) on
// haas-st-20y (M14 clamp, M15 unclamp): OFF unclamps and C stays unclamped after the next index
// (C180 without M14); ON clamps; the NX form unclamps; AUTO clamps again and gives the clamping
// back to the post (C0 unclamped, indexed, clamped). Each of the 9 clamps and unclamps, and the
// unclamp at FINI, takes time.c_clamp (0.5 s); C90 (the first, from an unknown angle) is not
// timed, C180, C270 and C0 turn 90 degrees each at 18000 per minute (0.9 s in all); the tool
// change 1.5 s: 7.4 s.
TEST(MillTurn, TheClsOwnCClampOnHaas) {
  constexpr const char* kClamp =
      "LOADTL/3,MILL\nSPINDL/1000,RPM,CLW\nROTABL/90,CAXIS\nCLAMP/OFF,CAXIS\n"
      "ROTABL/180,CAXIS\nCLAMP/ON,CAXIS\nROTABL/270,CAXIS\nCLAMP/CAXIS,OFF\n"
      "CLAMP/AUTO,CAXIS\nROTABL/0,CAXIS\nSPINDL/OFF\nFINI\n";
  Posted p = post(kClamp, load("haas-st-20y"));
  EXPECT_EQ(p.errors, 0u) << p.diags;
  EXPECT_NE(p.nc.find("G0 C90.\nM14\nM15\nG0 C180.\nM14\nM15\nG0 C270.\nM14\nM15\nM14\n"
                      "M15\nG0 C0.\nM14\nM135\nM15\nM155\nM30\n"),
            std::string::npos)
      << p.nc;
  PostedText r = post_text(kClamp, load("haas-st-20y"), "t.cl");
  ASSERT_EQ(r.summary.cycle_time.tools.size(), 1u);
  EXPECT_NEAR(r.summary.cycle_time.tools[0].seconds, 10 * 0.5 + 0.9 + 1.5, 1e-6);
}

// CLAMP/…,CAXIS on a machine without C, with ICAM's axis position (not read), before C is
// engaged, or without an ON/OFF word: located errors; on linuxcnc-lathe-c, whose C has no
// clamp code, a warning and the statement as a comment.
TEST(MillTurn, CClampsThatCannotBeWritten) {
  Posted none = post("CLAMP/ON,CAXIS\nFINI\n", load("fanuc-0i-t"));
  EXPECT_NE(none.diags.find("t.cl:1:1: error: CLAMP/…,CAXIS clamps a C axis, and machine "
                            "'fanuc-0i-t' has none (millturn.c_axis: false)"),
            std::string::npos)
      << none.diags;
  Posted e = post("CLAMP/ON,CAXIS\nCLAMP/OFF,CAXIS,45\nCLAMP/CAXIS\nFINI\n", load("haas-st-20y"));
  EXPECT_NE(e.diags.find("t.cl:1:1: error: CLAMP/ON,CAXIS: C is not engaged (no milling tool "
                         "since the main spindle last turned): nothing to clamp"),
            std::string::npos)
      << e.diags;
  EXPECT_NE(e.diags.find("t.cl:2:17: error: CLAMP/…,CAXIS: '45' is not read (ICAM's "
                         "CLAMP/OFF,axis,position moves the axis in a way no source states): "
                         "position C with ROTABL/a,CAXIS"),
            std::string::npos)
      << e.diags;
  EXPECT_NE(e.diags.find("t.cl:3:1: error: expected CLAMP/ON|OFF|AUTO,CAXIS or "
                         "CLAMP/CAXIS,ON|OFF"),
            std::string::npos)
      << e.diags;
  Posted l =
      post("LOADTL/3,MILL\nROTABL/90,CAXIS\nCLAMP/ON,CAXIS\nFINI\n", load("linuxcnc-lathe-c"));
  EXPECT_EQ(l.errors, 0u) << l.diags;
  EXPECT_NE(l.diags.find("t.cl:3:1: warning: CLAMP/: machine 'linuxcnc-lathe-c' has no code "
                         "'c_clamp' (its C axis is not clamped): written as a comment"),
            std::string::npos)
      << l.diags;
  EXPECT_NE(l.nc.find("G0 C90.\n(CLAMP/ON,CAXIS)\n"), std::string::npos) << l.nc;
}

// Fusion's APT post writes CLAMP/TABLE,ALL,AUTO (reference millturn.md §1): on a lathe the
// rotary axes are C. On haas-st-20y it is CLAMP/…,CAXIS: OFF unclamps the indexed C (M15) and
// leaves C90 unclamped, AUTO clamps again (M14); on fanuc-0i-t, without C, a note and nothing
// written; a word it does not know is a located error.
TEST(MillTurn, FusionsTableClamp) {
  Posted h = post(
      "LOADTL/3,MILL\nSPINDL/1000,RPM,CLW\nROTABL/0,CAXIS\nCLAMP/TABLE,ALL,OFF\n"
      "ROTABL/90,CAXIS\nCLAMP/TABLE,ALL,AUTO\nSPINDL/OFF\nFINI\n",
      load("haas-st-20y"));
  EXPECT_EQ(h.errors, 0u) << h.diags;
  EXPECT_NE(h.nc.find("G0 C0.\nM14\nM15\nG0 C90.\nM14\nM135\n"), std::string::npos) << h.nc;
  Posted f = post("CLAMP/TABLE,ALL,AUTO\nFINI\n", load("fanuc-0i-t"));
  EXPECT_EQ(f.errors, 0u) << f.diags;
  EXPECT_NE(f.diags.find("t.cl:1:1: note: CLAMP/TABLE clamps rotary axes, and machine "
                         "'fanuc-0i-t' has none (millturn.c_axis: false): nothing to clamp"),
            std::string::npos)
      << f.diags;
  EXPECT_EQ(f.nc.find("CLAMP"), std::string::npos) << f.nc;
  Posted e = post("CLAMP/TABLE,ALL,TIGHT\nFINI\n", load("haas-st-20y"));
  EXPECT_NE(e.diags.find("t.cl:1:17: error: unknown CLAMP word 'TIGHT': expected TABLE, ALL, "
                         "ON, OFF, AUTO"),
            std::string::npos)
      << e.diags;
}

// What is not written is a located error naming what is missing, never a hole on the centre
// line: C never indexed. (Fanuc's face G83, radial holes, holes off the X axis, a feed per
// revolution and live taps are written now: hole_live_test.cc.)
TEST(MillTurn, FaceHolesThatCannotBeWrittenAreLocatedErrors) {
  std::string no_c = kFaceHoles;
  no_c.erase(no_c.find("ROTABL/0,CAXIS\n"), 15);
  Posted unindexed = post(no_c, load("linuxcnc-lathe-c"));
  EXPECT_NE(unindexed.diags.find("t.cl:6:1: error: CYCLE/DRILL hole at CL line 6 with live tool "
                                 "3: C is not indexed: a hole of a live tool needs ROTABL/…,CAXIS "
                                 "before it"),
            std::string::npos)
      << unindexed.diags;
}

}  // namespace
}  // namespace clpost

// The holes of a live tool off the centre line (hole_live.cc, docs/millturn.md): radial holes,
// face holes at C computed from X and Y, a feed per revolution of the live tool.
#include <gtest/gtest.h>

#include "interpreter/post_test_util.h"

namespace clpost {
namespace {

using test::load;
using test::post;
using test::Posted;

// Three radial holes (tool axis through the centre line), radius 40 drilled 10 deep, clearance
// 2: X bottom 30 (X60. as a diameter), R plane 42. Hole 3 is GOTO/0,40 at index 90: its own
// angle atan2(40, 0) = 90, so C180.
constexpr const char* kRadial =
    "LOADTL/4,MILL\nSPINDL/2000,RPM,CLW\nROTABL/0,CAXIS\nFROM/50,0,-10,1,0,0\n"
    "CYCLE/DRILL,10,MMPM,100,CLEAR,2\nGOTO/40,0,-10,1,0,0\nROTABL/90,CAXIS\n"
    "GOTO/40,0,-20,1,0,0\nGOTO/0,40,-30,0,1,0\nCYCLE/OFF\nSPINDL/OFF\nFINI\n";

// LinuxCNC in G19: X the bottom as a diameter, R as a radius (rs274 reads them so:
// Rs274.MillTurnRadialHoles); the tool starts at its X (radius 50: X100.).
TEST(LiveHoles, RadialHolesOnLinuxcncLatheCInG19) {
  Posted p = post(kRadial, load("linuxcnc-lathe-c"));
  EXPECT_EQ(p.errors, 0u) << p.diags;
  EXPECT_EQ(p.nc,
            "%\nG7 G18 G21 G90 G40 G80\nT4 M6 G43 H4\nM3 $1 S2000\nG0 C0.\n"
            "(hole at CL line 6: radial drilling at Z-10. C0. to X60.)\nG0 X100. Z-10.\nG19\n"
            "G98 G94 G81 X60. Y0 Z-10. R42. F100.\nG80\nG18\nG0 C90.\n"
            "(hole at CL line 8: radial drilling at Z-20. C90. to X60.)\nG0 X100. Z-20.\nG19\n"
            "G98 G94 G81 X60. Y0 Z-20. R42. F100.\nG80\nG18\nG0 C180.\n"
            "(hole at CL line 9: radial drilling at Z-30. C180. to X60.)\nG0 X100. Z-30.\nG19\n"
            "G98 G94 G81 X60. Y0 Z-30. R42. F100.\nG80\nG18\nM5 $1\nM2\n%\n");
}

// The cycle time of the radial holes, by hand on linuxcnc-lathe-c (rapids 10000 mm/min along X
// as a radius, 15000 along Z; a tool change 1.5 s): each hole rapids from radius 50 to the R
// plane at 42 (8 / 10000 min = 0.048 s), drills 12 mm at 100 mm/min (7.2 s) and rapids out to
// 50 (20 / 10000 min = 0.12 s); holes 2 and 3 first move 10 mm along Z (0.04 s each). C turns
// at time.rapid_c, 18000 degrees per minute: C0 (the first after engaging, from an unknown
// angle: not timed), C90 and C180 turn 90 degrees each (90 / 18000 min = 0.3 s).
TEST(LiveHoles, RadialHolesAreTimedAlongX) {
  PostedText r = post_text(kRadial, load("linuxcnc-lathe-c"), "t.cl");
  ASSERT_EQ(r.diags.error_count(), 0u) << r.diags.render_all();
  const double hole = 0.048 + 7.2 + 0.12;
  ASSERT_EQ(r.summary.cycle_time.tools.size(), 1u);
  EXPECT_NEAR(r.summary.cycle_time.tools[0].seconds, 1.5 + 3 * hole + 2 * 0.04 + 2 * 0.3, 1e-6);
  EXPECT_FALSE(r.summary.cycle_time.c_untimed);
}

// On haas-st-20y C is clamped (M14) after each index and unclamped (M15) before the next:
// time.c_clamp 0.5 s each. The same holes as above: the first C0 clamps once (0.5 s), C90 and
// C180 each unclamp, turn 90 degrees (0.3 s) and clamp (1 s), and FINI unclamps C to release it
// (0.5 s): 3 * hole + 2 * 0.04 + 1.5 + 0.5 + 2 * 1.3 + 0.5 = 27.284 s. Without time.rapid_c the
// turns count nothing, and the cycle time says so.
TEST(LiveHoles, CIndexAndClampsAreTimed) {
  PostedText r = post_text(kRadial, load("haas-st-20y"), "t.cl");
  ASSERT_EQ(r.diags.error_count(), 0u) << r.diags.render_all();
  const double hole = 0.048 + 7.2 + 0.12;
  ASSERT_EQ(r.summary.cycle_time.tools.size(), 1u);
  EXPECT_NEAR(r.summary.cycle_time.tools[0].seconds,
              3 * hole + 2 * 0.04 + 1.5 + 0.5 + 2 * 1.3 + 0.5, 1e-6);
  PostedText untimed = post_text(kRadial, load("haas-st-20y", {"time.rapid_c=0"}), "t.cl");
  EXPECT_NEAR(untimed.summary.cycle_time.tools[0].seconds,
              3 * hole + 2 * 0.04 + 1.5 + 0.5 + 2 * 1.0 + 0.5, 1e-6);
  EXPECT_TRUE(untimed.summary.cycle_time.c_untimed);
  EXPECT_EQ(cycle_time_lines(untimed.summary.cycle_time, LengthUnit::kMm, true).back(),
            "cycle time 0:26.7, 1 tool change; C moves not timed: no time.rapid_c");
}

// Haas G241 with R the R plane as a diameter (84 = 2 x 42), and Fanuc G87 with R relative to
// the start (42 - 50 = -8, a radius), both as Fusion's posts write them (docs/millturn.md).
TEST(LiveHoles, RadialHolesOnHaasAndFanuc) {
  Posted haas = post(kRadial, load("haas-st-20y"));
  EXPECT_EQ(haas.errors, 0u) << haas.diags;
  EXPECT_NE(haas.nc.find("M15\nG0 C90.\nM14\n(HOLE AT CL LINE 8: RADIAL DRILLING AT Z-20. C90. TO "
                         "X60.)\nG0 X100. Z-20.\nG19\nG98 G241 X60. Z-20. R84. F100.\nG80\nG18\n"),
            std::string::npos)
      << haas.nc;
  Posted fanuc = post(kRadial, load("fanuc-0i-tf-live"));
  EXPECT_EQ(fanuc.errors, 0u) << fanuc.diags;
  EXPECT_NE(fanuc.nc.find("M74\nG0 C180.\nM73\n(HOLE AT CL LINE 9: RADIAL DRILLING AT Z-30. C180. "
                          "TO X60.)\nG0 X100. Z-30.\nG98 G87 X60. Z-30. R-8. F100.\nG80\n"),
            std::string::npos)
      << fanuc.nc;
}

// Fanuc's face G83 at X (a diameter) with C, R relative to the start (2 - 5 = -3): the
// Takisawa/Fanuc post's words (docs/millturn.md), before an error naming millturn.face_holes.
TEST(LiveHoles, FaceHolesOnFanuc0iTfLive) {
  Posted p = post(
      "LOADTL/3,MILL\nSPINDL/2000,RPM,CLW\nROTABL/90,CAXIS\nFROM/30,0,5\n"
      "CYCLE/DRILL,8,MMPM,100,CLEAR,2\nGOTO/30,0,0\nCYCLE/OFF\nSPINDL/OFF\nFINI\n",
      load("fanuc-0i-tf-live"));
  EXPECT_EQ(p.errors, 0u) << p.diags;
  EXPECT_NE(p.nc.find("G0 C90.\nM73\n(HOLE AT CL LINE 6: DRILLING AT X60. C90. TO Z-8.)\n"
                      "G0 X60. Z5.\nG98 G83 X60. Z-8. R-3. F100.\nG80\n"),
            std::string::npos)
      << p.nc;
}

// A face hole off the X axis is at radius hypot(x, y) and C = index + atan2(y, x): GOTO/0,30
// at index 0 is X60. C90., GOTO/30,30 is X84.85281 (2 x 30 x sqrt 2) C45. A feed of 0.05 per
// revolution of the live tool at 2000 rpm is written as 100 per minute, with a comment.
TEST(LiveHoles, FaceHolesOffTheXAxisAndAFeedPerRevolution) {
  Posted p = post(
      "LOADTL/3,MILL\nSPINDL/2000,RPM,CLW\nROTABL/0,CAXIS\nFROM/30,0,5\n"
      "CYCLE/DRILL,8,MMPR,0.05,CLEAR,2\nGOTO/0,30,0\nGOTO/30,30,0\nCYCLE/OFF\nSPINDL/OFF\nFINI\n",
      load("linuxcnc-lathe-c"));
  EXPECT_EQ(p.errors, 0u) << p.diags;
  EXPECT_NE(p.nc.find("(feed 0.05 per revolution of the live tool x 2000 rpm = 100 per minute for "
                      "the hole at CL line 6)\nG0 C90.\n(hole at CL line 6: drilling at X60. C90. "
                      "to Z-8.)\nG0 X60. Z5.\nG17\nG98 G94 G81 X60. Y0 Z-8. R2. F100.\n"),
            std::string::npos)
      << p.nc;
  EXPECT_NE(p.nc.find("G0 C45.\n(hole at CL line 7: drilling at X84.85281 C45. to Z-8.)\n"
                      "G0 X84.85281 Z5.\nG17\nG98 G94 G81 X84.85281 Y0 Z-8. R2. F100.\n"),
            std::string::npos)
      << p.nc;
}

// On a rollover C (haas-st-20y) a hole below the X axis is at 0 <= C < 360: GOTO/0,-30 at
// index 0 is atan2(-30, 0) = -90, C270., reached the shortest way. A tool change forgets the
// last tool's axis: the next tool's GOTO/30,0,0 without i,j,k is a face hole, not a radial one.
TEST(LiveHoles, HoleBelowTheXAxisOnARolloverCAndAToolChange) {
  Posted p = post(
      "LOADTL/4,MILL\nSPINDL/2000,RPM,CLW\nROTABL/0,CAXIS\nFROM/50,0,-10,1,0,0\n"
      "CYCLE/DRILL,10,MMPM,100,CLEAR,2\nGOTO/40,0,-10,1,0,0\nCYCLE/OFF\n"
      "LOADTL/3,MILL\nSPINDL/2000,RPM,CLW\nFROM/30,0,5\nCYCLE/DRILL,8,MMPM,100,CLEAR,2\n"
      "GOTO/0,-30,0\nCYCLE/OFF\nSPINDL/OFF\nFINI\n",
      load("haas-st-20y"));
  EXPECT_EQ(p.errors, 0u) << p.diags;
  EXPECT_NE(p.nc.find("G98 G241 X60. Z-10. R84. F100.\n"), std::string::npos) << p.nc;
  EXPECT_NE(p.nc.find("M15\nG0 C270.\nM14\n(HOLE AT CL LINE 12: DRILLING AT X60. C270. TO "
                      "Z-8.)\nG0 X60. Z5.\nG98 G81 X60. Z-8. R2. F100.\n"),
            std::string::npos)
      << p.nc;
}

// Live taps (docs/millturn.md): an M10x1.5 face tap 10 deep at radius 30 (X60.) and C90, the
// live tool at 1000 rpm, and an M10x1.25 radial tap 8 deep from radius 40 (bottom radius 32:
// X64.) at Z-10 and C0, the live tool at 800 rpm. Clearance 2: R plane Z2 on the face, radius
// 42 (X84.) radial; the radial tool starts at radius 50 (X100.).
constexpr const char* kLiveTaps =
    "LOADTL/3,MILL\nSPINDL/1000,RPM,CLW\nROTABL/90,CAXIS\nFROM/30,0,5\n"
    "CYCLE/TAP,10,MMPR,1.5,CLEAR,2\nGOTO/30,0,0\nCYCLE/OFF\n"
    "LOADTL/4,MILL\nSPINDL/800,RPM,CLW\nROTABL/0,CAXIS\nFROM/50,0,-10,1,0,0\n"
    "CYCLE/TAP,8,MMPR,1.25,CLEAR,2\nGOTO/40,0,-10,1,0,0\nCYCLE/OFF\nSPINDL/OFF\nFINI\n";

// LinuxCNC: G33.1 with $1 taps synchronised with spindle 1 (the live tool), K the lead; from
// the R plane and back to it (rs274 reads them so: Rs274.MillTurnLiveTaps).
TEST(LiveTaps, G33_1OnSpindle1OnLinuxcncLatheC) {
  Posted p = post(kLiveTaps, load("linuxcnc-lathe-c"));
  EXPECT_EQ(p.errors, 0u) << p.diags;
  EXPECT_NE(p.nc.find("(hole at CL line 6: tapping at X60. C90. to Z-10.)\nG0 X60. Z5.\n"
                      "G0 X60. Z2.\nG33.1 Z-10. K1.5 $1\nG0 Z5.\n"),
            std::string::npos)
      << p.nc;
  EXPECT_NE(p.nc.find("(hole at CL line 13: radial tapping at Z-10. C0. to X64.)\n"
                      "G0 X100. Z-10.\nG0 X84.\nG33.1 X64. Z-10. K1.25 $1\nG0 X100.\n"),
            std::string::npos)
      << p.nc;
}

// Haas (Fusion's Haas lathe post): G95 on the face, G195 radial in G19 from X at the R plane,
// F per minute = the lead x the live rpm: 1.5 x 1000 = 1500, 1.25 x 800 = 1000.
TEST(LiveTaps, G95AndG195OnHaasSt20y) {
  Posted p = post(kLiveTaps, load("haas-st-20y"));
  EXPECT_EQ(p.errors, 0u) << p.diags;
  EXPECT_NE(p.nc.find("(FEED 1.5 PER REVOLUTION OF THE LIVE TOOL X 1000 RPM = 1500 PER MINUTE FOR "
                      "THE HOLE AT CL LINE 6)\n(HOLE AT CL LINE 6: TAPPING AT X60. C90. TO Z-10.)\n"
                      "G0 X60. Z5.\nG98 G95 X60. Z-10. R2. F1500.\nG80\n"),
            std::string::npos)
      << p.nc;
  EXPECT_NE(p.nc.find("G0 X100. Z-10.\nG19\nG0 X84.\nG98 G195 X64. Z-10. F1000.\nG80\n"
                      "G0 X100.\nG18\n"),
            std::string::npos)
      << p.nc;
}

// Fanuc (Fusion's Takisawa/Fanuc post): M29 S then G84 on the face, G88 radial, R relative to
// the start (2 - 5 = -3, 42 - 50 = -8), F per minute.
TEST(LiveTaps, M29G84AndG88OnFanuc0iTfLive) {
  Posted p = post(kLiveTaps, load("fanuc-0i-tf-live"));
  EXPECT_EQ(p.errors, 0u) << p.diags;
  EXPECT_NE(p.nc.find("G0 X60. Z5.\nM29 S1000\nG98 G84 X60. Z-10. R-3. F1500.\nG80\nM72\n"),
            std::string::npos)
      << p.nc;
  EXPECT_NE(p.nc.find("G0 X100. Z-10.\nM29 S800\nG98 G88 X64. Z-10. R-8. F1000.\nG80\n"),
            std::string::npos)
      << p.nc;
}

// A live tap is never written as moves (they would reverse the main spindle): without the
// machine's template (or with an empty one, which would tap nothing) it is a located error.
TEST(LiveTaps, WithoutATemplateIsALocatedError) {
  Posted none = post(kLiveTaps, load("haas-st-20y", {"templates.hole_live_tap="}));
  EXPECT_NE(none.diags.find("t.cl:6:1: error: CYCLE/TAP hole at CL line 6 with live tool 3: "
                            "machine 'haas-st-20y' has no template 'hole_live_tap': a live "
                            "tool's tap is synchronised with the live spindle by the control's "
                            "own cycle, never written as moves"),
            std::string::npos)
      << none.diags;
}

// Left-hand taps (the live tool CCLW): Haas G186 on the face and G196 radial (Fusion's Haas
// lathe post for a left-hand tap); LinuxCNC the same G33.1 after M4 $1; the Takisawa/Fanuc
// post's left-hand form is not explained, so fanuc-0i-tf-live has no template and refuses it.
TEST(LiveTaps, LeftHandTaps) {
  std::string left = kLiveTaps;
  left.replace(left.find("SPINDL/1000,RPM,CLW"), 19, "SPINDL/1000,RPM,CCLW");
  left.replace(left.find("SPINDL/800,RPM,CLW"), 18, "SPINDL/800,RPM,CCLW");
  Posted haas = post(left, load("haas-st-20y"));
  EXPECT_EQ(haas.errors, 0u) << haas.diags;
  EXPECT_NE(haas.nc.find("M134 P1000\n"), std::string::npos) << haas.nc;
  EXPECT_NE(haas.nc.find("G0 X60. Z5.\nG98 G186 X60. Z-10. R2. F1500.\nG80\n"), std::string::npos)
      << haas.nc;
  EXPECT_NE(haas.nc.find("G19\nG0 X84.\nG98 G196 X64. Z-10. F1000.\nG80\n"), std::string::npos)
      << haas.nc;
  Posted lcnc = post(left, load("linuxcnc-lathe-c"));
  EXPECT_EQ(lcnc.errors, 0u) << lcnc.diags;
  EXPECT_NE(lcnc.nc.find("M4 $1 S1000\n"), std::string::npos) << lcnc.nc;
  EXPECT_NE(lcnc.nc.find("G0 X60. Z2.\nG33.1 Z-10. K1.5 $1\n"), std::string::npos) << lcnc.nc;
  Posted fanuc = post(left, load("fanuc-0i-tf-live"));
  EXPECT_NE(fanuc.diags.find("t.cl:6:1: error: CYCLE/TAP hole at CL line 6 with live tool 3: "
                             "machine 'fanuc-0i-tf-live' has no template 'hole_live_tap_left'"),
            std::string::npos)
      << fanuc.diags;
}

// What stays a located error: a tool axis across Z that misses the centre line, one neither
// along nor across Z, a feed per revolution without the live tool's rpm.
TEST(LiveHoles, HolesThatCannotBeWrittenAreLocatedErrors) {
  const auto one = [](std::string goto_line) {
    std::string cl = kRadial;
    cl.replace(cl.find("GOTO/40,0,-10,1,0,0"), 19, goto_line);
    return post(cl, load("linuxcnc-lathe-c"));
  };
  const std::string head = "t.cl:6:1: error: CYCLE/DRILL hole at CL line 6 with live tool 4: ";
  Posted off = one("GOTO/40,5,-10,1,0,0");
  EXPECT_NE(off.diags.find(head + "the tool axis does not pass through the centre line: a radial "
                                  "hole is drilled toward it"),
            std::string::npos)
      << off.diags;
  Posted slant = one("GOTO/40,0,-10,1,0,1");
  EXPECT_NE(slant.diags.find(head + "the tool axis of GOTO/40,0,-10,1,0,1 is neither along Z (a "
                                    "face hole) nor across it (a radial hole)"),
            std::string::npos)
      << slant.diags;
  Posted centre = one("GOTO/0,0,-10,1,0,0");
  EXPECT_NE(
      centre.diags.find(head + "a radial hole (the tool axis across Z) at the centre line has "
                               "no top to drill from"),
      std::string::npos)
      << centre.diags;
  std::string no_rpm = kRadial;
  no_rpm.replace(no_rpm.find("MMPM,100"), 8, "MMPR,0.05");
  no_rpm.erase(no_rpm.find("SPINDL/2000,RPM,CLW\n"), 20);
  Posted per_rev = post(no_rpm, load("linuxcnc-lathe-c"));
  EXPECT_NE(per_rev.diags.find("t.cl:5:1: error: CYCLE/DRILL hole at CL line 5 with live tool 4: a "
                               "feed per revolution of the live tool needs its speed (SPINDL/n,RPM "
                               "before it) to be written per minute"),
            std::string::npos)
      << per_rev.diags;
}

}  // namespace
}  // namespace clpost

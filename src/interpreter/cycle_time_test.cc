// The estimated cycle time against times worked out by hand.
#include "interpreter/cycle_time.h"

#include <gtest/gtest.h>

#include <limits>

#include <cmath>
#include <numbers>

#include "interpreter/post_test_util.h"
#include "machine/machine_test_util.h"

namespace clpost {
namespace {

using test::load;

// Rapids 6000 mm/min along X (radius), 12000 along Z; a tool change takes 2 s.
const std::vector<std::string> kRates = {"time.rapid_x=6000", "time.rapid_z=12000",
                                         "time.tool_change=2"};

constexpr const char* kPart =
    "UNITS/MM\nFROM/50,0,50\nLOADTL/1\nSPINDL/1000,RPM,CLW\nFEDRAT/0.2,MMPR\n"
    "RAPID\nGOTO/20,0,5\n"                                       // line 7
    "GOTO/20,0,-20\n"                                            // line 8: turn
    "SPINDL/SMM,100,CLW,MAXRPM,2000\nGOTO/0,0,-20\n"             // line 10: face under CSS
    "SPINDL/500,RPM,CLW\nRAPID\nGOTO/12,0,2\n"                   // line 13
    "THREAD/TURN,MMPR,1.5\nRAPID\nGOTO/10,0,2\nGOTO/10,0,-20\n"  // lines 14-17: one pass
    "RAPID\nGOTO/0,0,10\nDELAY/2\n"                              // lines 19-20
    "CYCLE/DRILL,DEPTH,10,MMPR,0.1,CLEAR,2\nGOTO/0,0,0\nCYCLE/OFF\nFINI\n";

TEST(CycleTime, EveryKindOfMoveByHand) {
  PostedText r = post_text(kPart, load("generic-lathe", kRates), "t.cl");
  ASSERT_EQ(r.diags.error_count(), 0u) << r.diags.render_all();
  using std::numbers::pi;
  // Tool change: 2 s.
  const double change = 2;
  // Line 7, rapid from FROM (X50 Z50) to X20 Z5: X 30 / 6000 min = 0.3 s, Z 45 / 12000 min =
  // 0.225 s; both axes move at once: 0.3 s.
  const double rapid1 = 0.3;
  // Line 8, 25 mm at 0.2 mm/rev x 1000 rpm = 200 mm/min: 0.125 min = 7.5 s.
  const double turn = 7.5;
  // Line 10, face from radius 20 to 0 at 0.2 mm/rev, 100 m/min: rpm = 100000 / (2 pi r), up to
  // the clamp 2000 rpm below rc = 100000 / (2 pi 2000) = 25 / pi = 7.9577 mm. Above rc the time
  // is the integral of 2 pi r dr / (0.2 x 100000) = pi (20^2 - rc^2) / 20000 min (3.1731 s);
  // below it rc / (0.2 x 2000) min (1.1937 s).
  const double rc = 25 / pi;
  const double face = 60 * (pi * (400 - rc * rc) / 20000 + rc / 400);
  EXPECT_NEAR(face, 4.36674, 1e-5);
  // Line 13, rapid X0 Z-20 -> X12 Z2: X 12 / 6000 min = 0.12 s, Z 22 / 12000 min = 0.11 s.
  const double rapid2 = 0.12;
  // Lines 16-17: the thread's approach X12 -> X10 (2 / 6000 min = 0.02 s) and its pass, 22 mm
  // at lead 1.5 x 500 rpm = 750 mm/min: 1.76 s.
  const double thread = 0.02 + 1.76;
  // Line 19, rapid X10 Z-20 -> X0 Z10: X 0.1 s, Z 30 / 12000 min = 0.15 s; line 20, dwell 2 s.
  const double rapid3 = 0.15, dwell = 2;
  // The hole: rapid Z10 -> R plane Z2 (0.04 s), drill 12 mm at 0.1 mm/rev x 500 rpm = 50 mm/min
  // (14.4 s), rapid out Z-10 -> Z10 (20 / 12000 min = 0.1 s).
  const double hole = 0.04 + 14.4 + 0.1;
  const double total = change + rapid1 + turn + face + rapid2 + thread + rapid3 + dwell + hole;
  const CycleTime& t = r.summary.cycle_time;
  ASSERT_EQ(t.tools.size(), 1u);
  EXPECT_EQ(t.tools[0].tool, 1);
  EXPECT_NEAR(t.tools[0].seconds, total, 1e-6);
  EXPECT_NEAR(t.total(), 32.75674, 1e-5);
  EXPECT_FALSE(t.rapids_untimed);
  // The extremes it reaches (X as a radius): X0 .. X20, Z-20 .. Z10 (FROM is not a move).
  EXPECT_EQ(t.tools[0].x_min, 0);
  EXPECT_EQ(t.tools[0].x_max, 20);
  EXPECT_EQ(t.tools[0].z_min, -20);
  EXPECT_EQ(t.tools[0].z_max, 10);
  EXPECT_EQ(cycle_time_lines(t, LengthUnit::kMm, true),
            (std::vector<std::string>{"T1 offset 1: 0:32.8, X0.000 to X40.000, Z-20.000 to "
                                      "Z10.000 mm",
                                      "cycle time 0:32.8, 1 tool change"}));
}

TEST(CycleTime, PerToolAndUntimedRapids) {
  // Two tools, no rapid rates: T1 feeds 10 mm at 100 mm/min (6 s), T2 dwells 1.5 s.
  PostedText r = post_text(
      "FEDRAT/100,MMPM\nLOADTL/1\nGOTO/10,0,0\nGOTO/10,0,-10\nLOADTL/2,ADJUST,12\nRAPID\n"
      "GOTO/30,0,5\nSPINDL/600,RPM,CLW\nDELAY/1.5\nFINI\n",
      load("generic-lathe", {"time.rapid_x=0", "time.rapid_z=0", "time.tool_change=0"}), "t.cl");
  const CycleTime& t = r.summary.cycle_time;
  ASSERT_EQ(t.tools.size(), 2u);
  EXPECT_NEAR(t.tools[0].seconds, 6, 1e-9);
  EXPECT_NEAR(t.tools[1].seconds, 1.5, 1e-9);
  EXPECT_EQ(t.tools[1].offset, 12);
  EXPECT_TRUE(t.rapids_untimed);
  EXPECT_EQ(cycle_time_lines(t, LengthUnit::kMm, true).back(),
            "cycle time 0:07.5, 2 tool changes; rapids not timed: no time.rapid_x/rapid_z");
}

// The clock keeps the feed in force as a length per minute between FEDRAT and SPINDL: every change
// of feed, feed mode or speed is taken at the next move.
TEST(CycleTime, FeedAndSpeedChangesBetweenMoves) {
  PostedText r = post_text(
      "UNITS/MM\nFROM/0,0,0\nLOADTL/1\n"
      "FEDRAT/100,MMPM\nGOTO/0,0,-10\n"      // 10 mm at 100 mm/min: 6 s
      "FEDRAT/200,MMPM\nGOTO/0,0,-30\n"      // 20 mm at 200 mm/min: 6 s
      "FEDRAT/0.1,MMPR\nGOTO/0,0,-40\n"      // per revolution, no speed yet: not timed
      "SPINDL/500,RPM,CLW\nGOTO/0,0,-50\n"   // 10 mm at 0.1 x 500 = 50 mm/min: 12 s
      "FEDRAT/0.2,MMPR\nGOTO/0,0,-60\n"      // 10 mm at 0.2 x 500 = 100 mm/min: 6 s
      "SPINDL/1000,RPM,CLW\nGOTO/0,0,-70\n"  // 10 mm at 0.2 x 1000 = 200 mm/min: 3 s
      "FEDRAT/300,MMPM\nGOTO/3,0,-66\n"      // 5 mm (3, 4) at 300 mm/min: 1 s
      "FINI\n",
      load("generic-lathe", kRates), "t.cl");
  ASSERT_EQ(r.diags.error_count(), 0u) << r.diags.render_all();
  const CycleTime& t = r.summary.cycle_time;
  ASSERT_EQ(t.tools.size(), 1u);
  // The tool change 2 s, then 6 + 6 + 0 + 12 + 6 + 3 + 1 s.
  EXPECT_NEAR(t.tools[0].seconds, 36, 1e-9);
  EXPECT_EQ(t.tools[0].x_min, 0);
  EXPECT_EQ(t.tools[0].x_max, 3);
  EXPECT_EQ(t.tools[0].z_min, -70);
  EXPECT_EQ(t.tools[0].z_max, -10);
}

// A machine with a program_header writes it after its program start (generic-lathe's three
// lines), the template once per line, as comment text (no parentheses inside).
TEST(CycleTime, ProgramHeader) {
  std::vector<std::string> sets = kRates;
  sets.push_back("templates.program_header=[\"(HDR {text})\"]");
  PostedText r =
      post_text("FEDRAT/100,MMPM\nLOADTL/1\nFROM/10,0,5\nGOTO/10,0,-10\nPPRINT (done)\nFINI\n",
                load("generic-lathe", sets), "dir/t.cl");
  // 15 mm at 100 mm/min: 9 s, and the tool change 2 s.
  EXPECT_EQ(r.program,
            "%\nO0001\nG18 G21 G40 G90\n"
            "(HDR machine generic-lathe, program t)\n"
            "(HDR T1 offset 1, first at CL line 2, 0:11.0)\n"
            "(HDR cycle time 0:11.0, 1 tool change)\n"
            "T0101\nG1 X20. Z-10. G94 F100.\n(done)\nM30\n%\n");
}

// A machine whose program_start writes nothing (`program_start: []`): the header is the
// program's first lines.
TEST(CycleTime, ProgramHeaderWithAnEmptyProgramStart) {
  std::vector<std::string> sets = kRates;
  sets.push_back("templates.program_header=[\"(HDR {text})\"]");
  sets.push_back("templates.program_start=[]");
  PostedText r = post_text("FEDRAT/100,MMPM\nFROM/10,0,5\nGOTO/10,0,-10\nFINI\n",
                           load("generic-lathe", sets), "t.cl");
  ASSERT_EQ(r.diags.error_count(), 0u) << r.diags.render_all();
  // 15 mm at 100 mm/min: 9 s; no tool.
  EXPECT_EQ(r.program,
            "(HDR machine generic-lathe, program t)\n"
            "(HDR cycle time 0:09.0, 0 tool changes)\n"
            "G1 X20. Z-10. G94 F100.\nM30\n%\n");
}

// A machine with a program_header and no program_start at all: load_machine refuses it (a
// required template), but a post applied on its own (the machine_yaml_fuzzer's way) reaches the
// post, which stops at the missing template, the header at the top of what was written. The
// fuzzer found that the header's place was looked up in the start's lines with at(), which
// threw out_of_range (ca2105a).
TEST(CycleTime, ProgramHeaderWithoutProgramStart) {
  Machine m;
  std::string errors;
  ASSERT_TRUE(apply_machine_yaml("bare.yaml",
                                 "codes: {linear: G1, feed_per_min: G94}\n"
                                 "formats: {default: {decimals: 3}}\n"
                                 "time: {rapid_x: 6000, rapid_z: 12000, tool_change: 2}\n"
                                 "templates:\n"
                                 "  program_header: [\"(HDR {text})\"]\n"
                                 "  program_end: [M30]\n",
                                 true, m, errors))
      << errors;
  m.name = "bare";
  PostedText r = post_text("FEDRAT/100,MMPM\nFROM/10,0,5\nGOTO/10,0,-10\nFINI\n", m, "t.cl");
  EXPECT_EQ(r.diags.render_all(),
            "t.cl: error: machine 'bare' has no template 'program_start' "
            "(templates.program_start in its machine or post file)\n");
  EXPECT_EQ(r.program,
            "(HDR machine bare, program t)\n"
            "(HDR cycle time 0:09.0, 0 tool changes)\n"
            "G1 X20. Z-10. G94 F100.\nM30\n");
}

// Two tools, the first used twice (one line, its times summed), each described by the CL
// (TPRINT, ICAM's PPRINT TOOL:). By hand, at 100 mm/min and 2 s a tool change:
//   T1 line 4: 2 s + 15 mm (Z5 to Z-10) 9 s; again at line 10: 2 s + 6 mm 3.6 s  -> 16.6 s
//   T2 line 8: 2 s + 10 mm 6 s                                                    ->  8.0 s
//   total 24.6 s, three tool changes (clpost check --set ... says the same: 0:24.6).
constexpr const char* kTwoTools =
    "PARTNO SHAFT 7\nFEDRAT/100,MMPM\nTPRINT/OD TURN (R0.8) 50%\nLOADTL/1\nFROM/10,0,5\n"
    "GOTO/10,0,-10\nPPRINT TOOL: GROOVE 3MM\nLOADTL/2\nGOTO/10,0,-20\nLOADTL/1\n"
    "GOTO/10,0,-26\nFINI\n";

// A machine as shipped (its header and block numbers), with the rates above.
Machine shipped(const std::string& name) {
  Machine m;
  std::string errors;
  EXPECT_TRUE(load_machine(name, {CLPOST_SOURCE_DIR}, kRates, shipped_controls(), m, errors))
      << errors;
  return m;
}

TEST(CycleTime, HeaderOnFanucInItsCommentStyle) {
  PostedText r = post_text(kTwoTools, shipped("fanuc-0i-t"), "shaft.cl");
  ASSERT_EQ(r.diags.error_count(), 0u) << r.diags.render_all();
  // Upper case, the parentheses of "(R0.8)" dropped (a Fanuc comment cannot hold them) and the
  // '%' (the control's end-of-tape character, not allowed in its comments), not numbered (the
  // control's blocks need no N), after the start's N10 and before the body's N20.
  const std::string expected =
      "%\nO0001\nN10 G18 G21 G40 G97\n"
      "(MACHINE FANUC-0I-T, PROGRAM SHAFT 7)\n"
      "(T1 OFFSET 1, OD TURN R0.8 50, FIRST AT CL LINE 4, 0:16.6)\n"
      "(T2 OFFSET 2, GROOVE 3MM, FIRST AT CL LINE 8, 0:08.0)\n"
      "(CYCLE TIME 0:24.6, 3 TOOL CHANGES)\n"
      "N20 (SHAFT 7)\n";
  EXPECT_EQ(r.program.substr(0, expected.size()), expected);
  EXPECT_EQ(cycle_time_lines(r.summary.cycle_time, LengthUnit::kMm, true).back(),
            "cycle time 0:24.6, 3 tool changes");
}

TEST(CycleTime, HeaderOnSinumerikInItsCommentStyle) {
  PostedText r = post_text(kTwoTools, shipped("sinumerik-840d"), "shaft.cl");
  ASSERT_EQ(r.diags.error_count(), 0u) << r.diags.render_all();
  // `;` comments keep their case, their parentheses and '%'; unnumbered like every `;` line.
  const std::string expected =
      "N10 G18 G710 G40 G90 DIAMON\n"
      "; machine sinumerik-840d, program SHAFT 7\n"
      "; T1 offset 1, OD TURN (R0.8) 50%, first at CL line 4, 0:16.6\n"
      "; T2 offset 2, GROOVE 3MM, first at CL line 8, 0:08.0\n"
      "; cycle time 0:24.6, 3 tool changes\n"
      "; SHAFT 7\n";
  EXPECT_EQ(r.program.substr(0, expected.size()), expected);
}

TEST(CycleTime, TimeText) {
  EXPECT_EQ(time_text(0), "0:00.0");
  EXPECT_EQ(time_text(59.96), "1:00.0");
  EXPECT_EQ(time_text(3723.04), "1:02:03.0");
  // What a fuzzed CL reached through the header: an infinite time (was a cast out of range).
  EXPECT_EQ(time_text(3.6e9 - 0.1), "999999:59:59.9");
  EXPECT_EQ(time_text(std::numeric_limits<double>::infinity()), "over 1000000:00:00");
  EXPECT_EQ(time_text(std::numeric_limits<double>::quiet_NaN()), "not known");
}

}  // namespace
}  // namespace clpost

// clpost plot on whole files: the pictures hold one V per planned pass, a program's section shows
// its control's cuts, errors are clean, and the pictures in docs/img are what clpost draws now.
#include <gtest/gtest.h>

#include <fmt/format.h>

#include <filesystem>

#include "test_util.h"

namespace clpost::test {
namespace {

size_t count(const std::string& text, const std::string& what) {
  size_t n = 0;
  for (size_t at = text.find(what); at != std::string::npos; at = text.find(what, at + 1)) ++n;
  return n;
}

RunResult clpost(const std::string& args) {
  return run("cd " + quote(source_dir()) + " && " + quote(clpost_bin()) + " " + args);
}

TEST(Plot, AClFileDrawsTheBackplotAndEveryPlannedPass) {
  const std::string out = temp_dir() + "/options.svg";
  RunResult r = clpost("plot --full samples/threads/options.apt -o " + quote(out));
  ASSERT_EQ(r.exit_code, 0) << r.err;
  const std::string svg = read_file(out);
  // options.apt: 7 threads of 5, 6, 6, 4, 4, 10 and 4 passes.
  EXPECT_EQ(count(svg, "class=\"pass\""), 39u);
  EXPECT_EQ(count(svg, "Passes in cutting order"), 7u);
  EXPECT_EQ(count(svg, "<path class=\"thread\""), 39u);
  EXPECT_NE(svg.find("samples/threads/options.apt posted on generic-lathe"), std::string::npos);
}

// Without --full: the threads at lines 33 (DEPTH 0.92, CUTS 4, OPTION 3) and 54 (CUTS 4,
// STEP 0.23, OPTION 3) are planned alike (depth 0.92, the same 4 passes), so one section of 4
// passes says "x2"; and of the 39 thread moves of the --full picture, 28 are distinct (22 once,
// 4 twice, 1 three times, 1 six times): each is drawn once.
TEST(Plot, AClFileDrawsEachThreadMoveOnce) {
  RunResult r = clpost("plot samples/threads/options.apt -o -");
  ASSERT_EQ(r.exit_code, 0) << r.err;
  EXPECT_EQ(count(r.out, "class=\"pass\""), 35u);
  EXPECT_EQ(count(r.out, "Passes in cutting order"), 6u);
  EXPECT_NE(r.out.find(">thread at line 33 - pitch 1.5, depth 0.92, OPTION 3 \u00d72 (2 identical "
                       "threads)</text>"),
            std::string::npos);
  EXPECT_EQ(count(r.out, "<path class=\"thread\""), 28u);
  EXPECT_NE(r.out.find(">path simplified: 170 moves drawn as 114 (tolerance 0.4 px); 7 threads "
                       "drawn as 6 sections</text>"),
            std::string::npos);
}

TEST(Plot, AProgramsSectionShowsItsControlsCuts) {
  const std::string out = temp_dir() + "/g76.svg";
  RunResult r = clpost(
      "plot -m fanuc-0i-t samples/golden/fanuc-0i-t/threads-options.nc --cl "
      "samples/threads/options.apt --thread 2 -o " +
      quote(out));
  ASSERT_EQ(r.exit_code, 0) << r.err;
  const std::string svg = read_file(out);
  EXPECT_EQ(count(svg, "class=\"pass\""), 6u);
  // G76's fifth pass roughs to k - d = 0.92 - 0.081 = 0.839, where the plan has 0.8398 (6 cuts
  // of OPTION 1): the picture shows the control's depth.
  EXPECT_NE(svg.find(">0.839<"), std::string::npos);
  EXPECT_NE(svg.find("thread at options.apt:19 as threads-options.nc cuts it"), std::string::npos);
}

TEST(Plot, Errors) {
  RunResult r = clpost("plot samples/threads/options.apt --thread 9 -o /dev/null");
  EXPECT_EQ(r.exit_code, 1);
  EXPECT_EQ(r.err, "clpost: error: --thread 9: samples/threads/options.apt has 7 threads\n");
  r = clpost("plot -m fanuc-0i-t samples/golden/fanuc-0i-t/threads-options.nc --thread 1");
  EXPECT_EQ(r.exit_code, 1);
  EXPECT_EQ(r.err,
            "clpost: error: the sections of a program are measured against its plan: give --cl\n");
  const std::string dir = temp_dir();
  write_file(dir + "/p.nc", "G0 X10 Z5\nG1 X1.2.3\n");
  r = clpost("plot " + quote(dir + "/p.nc") + " -o " + quote(dir + "/p.svg"));
  EXPECT_EQ(r.exit_code, 1);
  EXPECT_EQ(r.err, dir + "/p.nc:2:4: error: invalid number 'X1.2.3'\n  G1 X1.2.3\n     ^\n");
  EXPECT_FALSE(file_exists(dir + "/p.svg"));
}

// --full draws every move and every section: the picture as it was before plots were
// simplified (tests/data/plot holds that picture, as docs/img had it).
TEST(Plot, FullKeepsEveryMove) {
  RunResult r =
      clpost("plot --full -m fanuc-0i-t samples/golden/fanuc-0i-t/threads-options.nc -o -");
  ASSERT_EQ(r.exit_code, 0) << r.err;
  EXPECT_EQ(r.out, read_file(source_dir() + "/tests/data/plot/fanuc-options-backplot-full.svg"));
  EXPECT_EQ(r.out.find("path simplified"), std::string::npos);
}

// N identical threads: one section, "xN" in its title, and a note.
TEST(Plot, IdenticalThreadsDrawOneSection) {
  std::string cl = "PARTNO T\nUNITS/MM\nLOADTL/7,ADJUST,7\nSPINDL/600,RPM,CLW\n";
  for (int i = 0; i < 40; ++i)
    cl +=
        "RAPID\nGOTO/15,0,5\nTHREAD/ON,DEPTH,1.534,CUTS,4,FINCUT,1,0.1,OPTION,1,MMPR,2.5,"
        "CHAMFR,2.5\nGOTO/10,0,2\nGOTO/10,0,-30\nTHREAD/OFF\n";
  cl += "RAPID\nGOTO/50,0,50\nEND\nFINI\n";
  const std::string dir = temp_dir();
  write_file(dir + "/t.cl", cl);
  RunResult r = clpost("plot " + quote(dir + "/t.cl") + " -o -");
  ASSERT_EQ(r.exit_code, 0) << r.err;
  EXPECT_EQ(count(r.out, "Passes in cutting order"), 1u);
  EXPECT_NE(r.out.find(" \u00d740 (40 identical threads)</text>"), std::string::npos);
  EXPECT_NE(r.out.find("; 40 threads drawn as 1 section</text>"), std::string::npos);
  // 5 passes, each thread move drawn once.
  EXPECT_EQ(count(r.out, "<path class=\"thread\""), 5u);
  r = clpost("plot --full " + quote(dir + "/t.cl") + " -o -");
  EXPECT_EQ(count(r.out, "Passes in cutting order"), 40u);
}

// Whatever the length, the picture stays under 2 MB: 300 000 moves of a zigzag 2 mm across and
// 0.3 mm along, drifting up (each a few px long and turning sharply: nothing merges them at
// 0.4 px, and no two are alike).
TEST(Plot, ABigProgramMakesASmallPicture) {
  std::string cl =
      "PARTNO Z\nUNITS/MM\nLOADTL/1,ADJUST,1\nSPINDL/1200,RPM,CLW\n"
      "FEDRAT/0.25,MMPR\nRAPID\nGOTO/40,0,5\n";
  for (int i = 0; i < 300000; ++i)
    cl += fmt::format("GOTO/{:.4f},0,{:.3f}\n", 30 + 2 * (i % 2) + 0.0001 * i, -0.3 * (i % 1000));
  cl += "RAPID\nGOTO/50,0,50\nEND\nFINI\n";
  const std::string dir = temp_dir();
  write_file(dir + "/z.cl", cl);
  RunResult r = clpost("plot " + quote(dir + "/z.cl") + " -o " + quote(dir + "/z.svg"));
  ASSERT_EQ(r.exit_code, 0) << r.err;
  const std::string svg = read_file(dir + "/z.svg");
  EXPECT_LE(svg.size(), 2u << 20);
  EXPECT_NE(svg.find(">path simplified: 300 001 moves drawn as "), std::string::npos);
}

// A face bolt circle (tests/data/millturn-face-holes.apt: 4 holes at radius 30, C0, 90, 180,
// 270) on linuxcnc-lathe-c: the face view's frame holds the stock circle (radius 30, the work's:
// nothing is turned) and its labels, +-30 * 1.08 * 1.04 = +-33.696, padded by 5 %: 74.1312 mm
// in 640 px, k = 8.63337 px/mm, centred at x 78 + 1094 / 2 = 625 and at y 438 + 320 = 758 (the
// frame's top: the side view's 352 px and the panel's head of 86). A hole at radius 30 is 30 k
// = 259 px from the centre: right at C0, up at C90.
TEST(Plot, FaceHolesAreMarksAtTheirCOnTheFaceView) {
  RunResult r = clpost("plot -m linuxcnc-lathe-c tests/data/millturn-face-holes.apt -o -");
  ASSERT_EQ(r.exit_code, 0) << r.err;
  // The face view under an empty side view (the live tool's moves are all C-axis work, left to
  // the face view): its centre 480 px lower than under the side view of those moves.
  EXPECT_NE(r.out.find("<circle class=\"stock\" cx=\"625\" cy=\"1238\" r=\"259\""),
            std::string::npos);
  EXPECT_NE(r.out.find("<circle class=\"hole\" cx=\"884\" cy=\"1238\" r=\"4.5\"/>\n"
                       "<circle class=\"hole\" cx=\"625\" cy=\"979\" r=\"4.5\"/>\n"
                       "<circle class=\"hole\" cx=\"366\" cy=\"1238\" r=\"4.5\"/>\n"
                       "<circle class=\"hole\" cx=\"625\" cy=\"1497\" r=\"4.5\"/>"),
            std::string::npos);
  // The three C indexes of 90 degrees at radius 30, rapids swept in 54 steps of 5 degrees:
  // 54 * 2 * 30 sin(2.5 deg) = 141.3 mm.
  EXPECT_NE(r.out.find(">54 moves: 54 rapid (141.3 mm); 4 face holes (marks: the tool diameter "
                       "is not in the program); dashed circle: radius 30, the work&apos;s "
                       "largest</text>"),
            std::string::npos);
  EXPECT_EQ(r.out.find("Peripheral work"), std::string::npos);
}

// tests/data/millturn-face-mill.apt on haas-st-20y (G17 X Y at C30): the 20 x 20 square's corners
// (10, -10), (10, 10), (-10, 10), (-10, -10) turned by 30 degrees are (13.6603, -3.6603),
// (3.6603, 13.6603), (-13.6603, 3.6603), (-3.6603, -13.6603). The frame holds +-14.1421 (the
// arc, the work's radius) * 1.1232 = +-15.8845, padded by 5 %: 34.9458 mm in 640 px, k =
// 18.3141, left at 305 and top at 918 (under the side view's note line), part (x, y) at
// (305 + (x + 17.4729) k, 1558 - (y + 17.4729) k): (875.18, 1305.03), (692.03, 987.82), ... Its
// length is the CL path's: 80 of the square, 270 degrees of the arc (66.6432) and the 24 of the
// slot, 170.6, on haas-st-20y as arcs and on linuxcnc-lathe-c as the post's XZC pieces mapped back.
TEST(Plot, FaceMillingIsDrawnInThePartFrame) {
  RunResult r = clpost("plot -m haas-st-20y tests/data/millturn-face-mill.apt -o -");
  ASSERT_EQ(r.exit_code, 0) << r.err;
  EXPECT_NE(r.out.find("<path class=\"feed\" d=\"M875.18 1305.03 L692.03 987.82 L374.82 1170.97 "
                       "L557.97 1488.18 L875.18 1305.03 "),
            std::string::npos);
  // Its G3 is not in the side view as a lathe arc (before: "1 arc (31.4 mm)" there).
  EXPECT_NE(r.out.find(">1 move: 1 rapid (34.1 mm)</text>"), std::string::npos);
  EXPECT_NE(r.out.find(">61 moves: 2 rapid (24.2 mm), 59 feed (170.6 mm); 0 face holes"),
            std::string::npos);
  r = clpost("plot -m linuxcnc-lathe-c tests/data/millturn-face-mill.apt -o -");
  ASSERT_EQ(r.exit_code, 0) << r.err;
  EXPECT_NE(r.out.find(" feed (170.6 mm); 0 face holes"), std::string::npos);
  // In G112 polar interpolation (X and Y in the plane at C0): the same square (0.02 px off: the
  // chords' ends, rounded to 3 decimals, make the largest radius 14.143), the same length, the
  // 270-degree arc as 126 chords of 2.15 degrees (within 0.0025 at radius 14.142): 126 + 4
  // sides + the slot's one line across the face (the plunges do not move in this view).
  r = clpost(
      "plot -m haas-st-20y --set millturn.polar_interpolation=true "
      "tests/data/millturn-face-mill.apt -o -");
  ASSERT_EQ(r.exit_code, 0) << r.err;
  EXPECT_NE(r.out.find("<path class=\"feed\" d=\"M875.16 1305.03 L692.03 987.84 L374.84 1170.97 "
                       "L557.97 1488.16 L875.16 1305.03 "),
            std::string::npos);
  EXPECT_NE(r.out.find(">132 moves: 1 rapid (24.2 mm), 131 feed (170.6 mm); 0 face holes"),
            std::string::npos);
}

// The side view is the lathe's: the live tool's C-axis work (T3's 151 moves in X or Z: its XZC
// pieces, the plunges and the slot through the centre at C fixed) is not drawn there as if it
// were turned, but in the face view, and the note says so; what is left is the turning tool's
// rapid from the milling's last point (radius 12, Z5) to GOTO/22,0,2: hypot(10, 3) = 10.4 mm.
// --full leaves out the same moves.
TEST(Plot, TheSideViewLeavesMillingToTheFaceView) {
  for (const char* full : {"", " --full"}) {
    RunResult r = clpost(std::string("plot -m linuxcnc-lathe-c") + full +
                         " tests/data/millturn-face-mill.apt -o -");
    ASSERT_EQ(r.exit_code, 0) << r.err;
    EXPECT_NE(r.out.find(">1 move: 1 rapid (10.4 mm)</text>"), std::string::npos) << full;
    EXPECT_NE(r.out.find(">151 moves of the C-axis work drawn in the views below, not here</text>"),
              std::string::npos)
        << full;
    EXPECT_NE(r.out.find(">300 moves: 28 rapid (30.9 mm), 272 feed (170.6 mm); 0 face holes"),
              std::string::npos)
        << full;
  }
}

// Radial holes (tests/data/millturn-radial-holes.apt: Z-10 C0, Z-20 C90, Z-30 C180) on the
// unrolled peripheral view only, at radius 42 (their R plane: nothing is turned); a turning
// program on a machine with C has neither view.
TEST(Plot, RadialHolesAreOnThePeripheralViewOnly) {
  RunResult r = clpost("plot -m haas-st-20y tests/data/millturn-radial-holes.apt -o -");
  ASSERT_EQ(r.exit_code, 0) << r.err;
  EXPECT_EQ(r.out.find("Face work"), std::string::npos);
  EXPECT_NE(r.out.find(">Peripheral work, unrolled at radius 42 mm:"), std::string::npos);
  EXPECT_EQ(count(r.out, "<circle class=\"hole\""), 3u);
  r = clpost("plot -m linuxcnc-lathe-c samples/thread-m20.apt -o -");
  ASSERT_EQ(r.exit_code, 0) << r.err;
  EXPECT_EQ(r.out.find("Face work"), std::string::npos);
  EXPECT_EQ(r.out.find("Peripheral work"), std::string::npos);
}

// Peripheral milling without Y (tests/data/millturn-peripheral-mill.apt) on linuxcnc-lathe-c:
// its X Z C moves in G19 are drawn unrolled, at radius 15 (the first feed's start, the slot's
// plunge from X30). By hand, in the view: the slot 25 mm along Z at C90, the groove's 63 chords
// 15 pi = 47.124 mm up from C0 to C180 (X stays 16: the control's C moves are the arc), the
// helix-like line's 4 pieces hypot(15 x 10 pi / 180, 1) = 2.803 mm: 74.9 mm in 68 feeds (the
// plunges along X are points in this view). There is no face view. On fanuc-0i-tf-live, which
// writes no plane code (the Takisawa post mills radially in G18), the same moves are face work.
TEST(Plot, PeripheralMillingWithoutYIsUnrolled) {
  RunResult r = clpost("plot -m linuxcnc-lathe-c tests/data/millturn-peripheral-mill.apt -o -");
  ASSERT_EQ(r.exit_code, 0) << r.err;
  EXPECT_EQ(r.out.find("Face work"), std::string::npos);
  EXPECT_NE(r.out.find(">Peripheral work, unrolled at radius 15 mm:"), std::string::npos);
  EXPECT_NE(r.out.find(" 68 feed (74.9 mm); 0 radial holes"), std::string::npos) << r.out;
  r = clpost("plot -m fanuc-0i-tf-live tests/data/millturn-peripheral-mill.apt -o -");
  ASSERT_EQ(r.exit_code, 0) << r.err;
  EXPECT_NE(r.out.find("Face work"), std::string::npos);
  EXPECT_EQ(r.out.find("Peripheral work"), std::string::npos);
}

// The README shows docs/img: they must be what clpost draws (scripts/plot-samples.sh redraws).
TEST(Plot, DocsPicturesAreCurrent) {
  namespace fs = std::filesystem;
  const std::string dir = temp_dir();
  RunResult r = run("CLPOST_BIN=" + quote(clpost_bin()) + " " + quote(source_dir()) +
                    "/scripts/plot-samples.sh " + quote(dir));
  ASSERT_EQ(r.exit_code, 0) << r.err;
  size_t compared = 0;
  for (const auto& e : fs::directory_iterator(dir)) {
    const fs::path committed = fs::path(source_dir()) / "docs/img" / e.path().filename();
    EXPECT_TRUE(fs::exists(committed)) << committed << ": run scripts/plot-samples.sh";
    EXPECT_EQ(read_file(e.path().string()), read_file(committed.string()))
        << committed << " is stale: run scripts/plot-samples.sh and look at it";
    ++compared;
  }
  EXPECT_EQ(compared, 6u);
}

}  // namespace
}  // namespace clpost::test

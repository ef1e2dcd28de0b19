// Holes on the spindle axis in whole programs: samples/part-turned.apt (centre drill with a
// dwell, peck drill, tap) on every machine verifies, and a drilling word edited or dropped fails
// verify naming the hole; LinuxCNC's own interpreter drills each hole to its planned depths.
#include <gtest/gtest.h>

#include <cstdio>
#include <filesystem>
#include <sstream>

#include "test_util.h"

namespace clpost::test {
namespace {

namespace fs = std::filesystem;

const std::string kPart = "samples/part-turned.apt";

struct Golden {
  std::string machine, file;  // file: under samples/golden/<machine>/
};

// The part's golden on every shipped machine.
std::vector<Golden> goldens() {
  std::vector<Golden> out;
  for (const std::string& name : shipped_machine_names())
    out.push_back({name, fs::path(golden_path(shipped_machine(name), kPart)).filename().string()});
  EXPECT_FALSE(out.empty()) << "no shipped machines found";
  return out;
}

// The golden with the first line holding `needle` changed by `edit`, verified against the part.
RunResult verify_edited(const Golden& g, const std::string& needle,
                        std::string (*edit)(const std::string&), std::string& path) {
  std::istringstream in(read_file(source_dir() + "/samples/golden/" + g.machine + "/" + g.file));
  std::string text, line;
  bool done = false;
  while (std::getline(in, line)) {
    const bool comment =
        line.find("hole at") != std::string::npos || line.find("HOLE AT") != std::string::npos;
    if (!done && !comment && line.find(needle) != std::string::npos) {
      line = edit(line);
      done = true;
    }
    text += line + "\n";
  }
  EXPECT_TRUE(done) << needle << " not in " << g.machine;
  path = temp_dir() + "/" + g.machine + "-" + g.file;
  write_file(path, text);
  return run("cd " + quote(source_dir()) + " && " + quote(clpost_bin()) + " verify -m " +
             g.machine + " " + quote(path) + " --cl " + kPart);
}

std::string first_error(const RunResult& r) {
  return r.err.substr(0, r.err.find('\n'));
}

TEST(Holes, EveryGoldenDrillsItsHoles) {
  for (const Golden& g : goldens()) {
    RunResult r = run("cd " + quote(source_dir()) + " && " + quote(clpost_bin()) + " verify -m " +
                      g.machine + " samples/golden/" + g.machine + "/" + g.file + " --cl " + kPart);
    EXPECT_EQ(r.exit_code, 0) << g.machine << "\n" << r.out << r.err;
    EXPECT_NE(r.out.find("holes on the centre line: 3 in the CL, 3 in the program\n"),
              std::string::npos)
        << g.machine << "\n"
        << r.out;
    EXPECT_NE(r.out.find("ok: every hole is drilled as planned"), std::string::npos) << r.out;
  }
}

// The peck hole (CL line 37) ends at Z-22: written one deeper, Z-21, on every machine — in the
// cycle's Z word (G83 Z-22., CYCLE83(…, -22, …), G74 Z-22.) or in the last feed of the moves.
TEST(Holes, AnEditedDepthWordFailsNamingTheHole) {
  for (const Golden& g : goldens()) {
    std::string p;
    RunResult r = verify_edited(
        g, "-22",
        [](const std::string& l) {
          std::string s = l;
          s.replace(s.find("-22"), 3, "-21");
          return s;
        },
        p);
    EXPECT_EQ(r.exit_code, 1) << g.machine;
    EXPECT_NE(
        first_error(r).find(": error: hole at " + kPart + ":37: bottom Z-21.0000, CL Z-22.0000"),
        std::string::npos)
        << g.machine << ": " << r.err;
    EXPECT_NE(r.out.find("FAILED: 1 of the holes not drilled as planned"), std::string::npos)
        << r.out;
  }
}

// The tap (CL line 45, to Z-16) dropped: its cycle block, or the feed into the hole.
TEST(Holes, ADroppedTapFailsNamingTheHole) {
  for (const Golden& g : goldens()) {
    std::string p;
    RunResult r = verify_edited(
        g, "-16", [](const std::string&) { return std::string(); }, p);
    EXPECT_EQ(r.exit_code, 1) << g.machine;
    EXPECT_NE(first_error(r).find("error: hole at " + kPart +
                                  ":45: the program does not feed "
                                  "into it"),
              std::string::npos)
        << g.machine << ": " << r.err;
  }
}

// Fanuc's G83 peck Q5000 (5 mm in micrometres) edited to Q4000: from the R point Z2 the pecks
// end at -2, -6, -10, -14, -18, -22: six feeds where the CL's pecks of 5 make five (-3, -8, -13,
// -18, -22).
TEST(Holes, AnEditedPeckWordFails) {
  std::string p;
  RunResult r = verify_edited(
      {"fanuc-0i-t", "part-turned.nc"}, "Q5000",
      [](const std::string& l) {
        std::string s = l;
        s.replace(s.find("Q5000"), 5, "Q4000");
        return s;
      },
      p);
  EXPECT_EQ(r.exit_code, 1);
  EXPECT_EQ(first_error(r),
            p + ":34:1: error: hole at " + kPart + ":37: 6 feeds into the hole, CL 5");
}

// LinuxCNC's interpreter on the part: the feeds along the centre line end where the plan's do.
// Centre drill: R2 -> Z-3 (depth 3 below the face Z0), dwell 0.5 s. Peck drill, R plane Z2,
// pecks of 5 counted from it: -3, -8, -13, -18 and the bottom -22 (22 deep). Tap: RIGID_TAP to
// Z-16 at 1.5 per revolution.
// A face hole of a live tool (docs/millturn.md): verify checks its X and C against the CL.
// The bolt circle on linuxcnc-lathe-c verifies; its second hole's C moved by 1 degree (C91, the
// hole 0.5236 mm = 30 x pi/180 along its circle) fails naming the hole.
TEST(Holes, AFaceHoleMovedOneDegreeInCFails) {
  const std::string cl = "tests/data/millturn-face-holes.apt", dir = temp_dir();
  const std::string ngc = dir + "/holes.ngc", moved = dir + "/moved.ngc";
  RunResult post = run("cd " + quote(source_dir()) + " && " + quote(clpost_bin()) +
                       " --verify -m linuxcnc-lathe-c -o " + quote(ngc) + " " + cl);
  ASSERT_EQ(post.exit_code, 0) << post.err;
  EXPECT_NE(post.err.find("holes (4 on the face at their X and C): 4 in the CL, 4 in the program"),
            std::string::npos)
      << post.err;
  std::string text = read_file(ngc);
  const size_t at = text.find("G0 C90.\n");
  ASSERT_NE(at, std::string::npos) << text;
  text.replace(at, 8, "G0 C91.\n");
  write_file(moved, text);
  RunResult r = run("cd " + quote(source_dir()) + " && " + quote(clpost_bin()) +
                    " verify -m linuxcnc-lathe-c " + quote(moved) + " --cl " + cl);
  EXPECT_EQ(r.exit_code, 1) << r.err << r.out;
  EXPECT_EQ(first_error(r), moved + ":19:1: error: hole at " + cl +
                                ":11: at C91.0000, CL C90.0000 (0.5236 mm along the circle of "
                                "radius 30.0000)")
      << r.err;
  fs::remove_all(dir);
}

// Radial holes of a live tool (docs/millturn.md): verify checks each one's Z, bottom X and C.
// tests/data/millturn-radial-holes.apt verifies on linuxcnc-lathe-c (G19 G81), haas-st-20y
// (G241) and fanuc-0i-tf-live (G87); the second hole's C moved by 1 degree (C91: 40 x pi/180 =
// 0.6981 mm along the circle of its top, radius 40) fails naming the hole.
TEST(Holes, ARadialHoleMovedOneDegreeInCFails) {
  const std::string cl = "tests/data/millturn-radial-holes.apt", dir = temp_dir();
  for (const char* m : {"linuxcnc-lathe-c", "haas-st-20y", "fanuc-0i-tf-live"}) {
    RunResult ok = run("cd " + quote(source_dir()) + " && " + quote(clpost_bin()) +
                       " --verify -m " + m + " -o " + quote(dir + "/ok.nc") + " " + cl);
    EXPECT_EQ(ok.exit_code, 0) << m << ok.err;
    EXPECT_NE(ok.err.find("holes (0 on the face at their X and C, 3 radial at their Z and C): 3 "
                          "in the CL, 3 in the program"),
              std::string::npos)
        << m << ok.err;
  }
  const std::string ngc = dir + "/holes.ngc", moved = dir + "/moved.ngc";
  RunResult post = run("cd " + quote(source_dir()) + " && " + quote(clpost_bin()) +
                       " --verify -m linuxcnc-lathe-c -o " + quote(ngc) + " " + cl);
  ASSERT_EQ(post.exit_code, 0) << post.err;
  std::string text = read_file(ngc);
  const size_t at = text.find("G0 C90.\n");
  ASSERT_NE(at, std::string::npos) << text;
  text.replace(at, 8, "G0 C91.\n");
  write_file(moved, text);
  RunResult r = run("cd " + quote(source_dir()) + " && " + quote(clpost_bin()) +
                    " verify -m linuxcnc-lathe-c " + quote(moved) + " --cl " + cl);
  EXPECT_EQ(r.exit_code, 1) << r.err << r.out;
  EXPECT_NE(first_error(r).find(":1: error: hole at " + cl +
                                ":10: at C91.0000, CL C90.0000 (0.6981 mm along the circle of "
                                "radius 40.0000)"),
            std::string::npos)
      << r.err;
  // The hole's Z moved: Z-20 written Z-21.
  text = read_file(ngc);
  const size_t z = text.find("Y0 Z-20.");
  ASSERT_NE(z, std::string::npos) << text;
  text.replace(z, 8, "Y0 Z-21.");
  write_file(moved, text);
  RunResult rz = run("cd " + quote(source_dir()) + " && " + quote(clpost_bin()) +
                     " verify -m linuxcnc-lathe-c " + quote(moved) + " --cl " + cl);
  EXPECT_NE(first_error(rz).find("hole at " + cl + ":10: at Z-21.0000, CL Z-20.0000"),
            std::string::npos)
      << rz.err;
  fs::remove_all(dir);
}

// The same bolt circle with a first peck of 5 and pecks of 2 (the template has one peck word):
// written as moves at X60 (a diameter) after each C; verify follows the moves off the centre
// line and finds the second hole at C91 (NC line 28, its first feed).
TEST(Holes, AFaceHoleWrittenAsMovesIsCheckedAtItsC) {
  std::string cl = read_file(source_dir() + "/tests/data/millturn-face-holes.apt");
  const std::string drill = "CYCLE/DRILL,8,MMPM,100,CLEAR,2";
  ASSERT_NE(cl.find(drill), std::string::npos);
  cl.replace(cl.find(drill), drill.size(),
             "CYCLE/DEEP2,FEDTO,8.6,1STPECK,5.,SUBPECK,2.,MMPM,100.,RAPTO,2.");
  const std::string dir = temp_dir(), apt = dir + "/deep.apt", ngc = dir + "/deep.ngc";
  write_file(apt, cl);
  RunResult post = run(quote(clpost_bin()) + " --verify -m linuxcnc-lathe-c -o " + quote(ngc) +
                       " " + quote(apt));
  ASSERT_EQ(post.exit_code, 0) << post.err;
  EXPECT_NE(post.err.find("  " + apt + ":11  peck drilling to Z-8.6000  ok  moves, NC line 28"),
            std::string::npos)
      << post.err;
  std::string text = read_file(ngc);
  ASSERT_NE(text.find("G0 C90.\n(hole at CL line 11: peck drilling at X60. C90. to Z-8.6)\n"),
            std::string::npos)
      << text;
  text.replace(text.find("G0 C90.\n"), 8, "G0 C91.\n");
  write_file(ngc, text);
  RunResult r = run(quote(clpost_bin()) + " verify -m linuxcnc-lathe-c " + quote(ngc) + " --cl " +
                    quote(apt));
  EXPECT_EQ(r.exit_code, 1) << r.err;
  EXPECT_EQ(first_error(r), ngc + ":28:1: error: hole at " + apt +
                                ":11: at C91.0000, CL C90.0000 (0.5236 mm along the circle of "
                                "radius 30.0000)")
      << r.err;
  fs::remove_all(dir);
}

// A radial hole written as moves (haas-st-20y has no hole_radial_chip_break): pecks of 4 from
// the R plane at radius 42 end at radius 38, 34, 30 (X76., X68., X60.), backing off
// holes.peck_clearance 0.5 (X77.). verify follows the feeds along X at the hole's Z and finds
// the second hole at C91 (NC line 27, its first feed; 0.6981 mm at radius 40).
TEST(Holes, ARadialHoleWrittenAsMovesIsCheckedAtItsC) {
  std::string cl = read_file(source_dir() + "/tests/data/millturn-radial-holes.apt");
  const std::string drill = "CYCLE/DRILL,10,MMPM,100,CLEAR,2";
  ASSERT_NE(cl.find(drill), std::string::npos);
  cl.replace(cl.find(drill), drill.size(), "CYCLE/BRKCHP,10,MMPM,100,CLEAR,2,STEP,4");
  const std::string dir = temp_dir(), apt = dir + "/brk.apt", nc = dir + "/brk.nc";
  write_file(apt, cl);
  RunResult post =
      run(quote(clpost_bin()) + " --verify -m haas-st-20y -o " + quote(nc) + " " + quote(apt));
  ASSERT_EQ(post.exit_code, 0) << post.err;
  EXPECT_NE(post.err.find("  " + apt +
                          ":10  radial chip-breaking drilling to X30.0000 (radius)  ok  moves, NC "
                          "line 27"),
            std::string::npos)
      << post.err;
  std::string text = read_file(nc);
  ASSERT_NE(text.find("G0 C90.\nM14\n(HOLE AT CL LINE 10: RADIAL CHIP-BREAKING DRILLING AT Z-20. "
                      "C90. TO X60.)\nG0 X100. Z-20.\nX84.\nG1 X76. G98 F100.\nG0 X77.\nG1 "
                      "X68.\nG0 X69.\nG1 X60.\nG0 X100.\n"),
            std::string::npos)
      << text;
  text.replace(text.find("G0 C90.\n"), 8, "G0 C91.\n");
  write_file(nc, text);
  RunResult r =
      run(quote(clpost_bin()) + " verify -m haas-st-20y " + quote(nc) + " --cl " + quote(apt));
  EXPECT_EQ(r.exit_code, 1) << r.err;
  EXPECT_EQ(first_error(r), nc + ":27:1: error: hole at " + apt +
                                ":10: at C91.0000, CL C90.0000 (0.6981 mm along the circle of "
                                "radius 40.0000)")
      << r.err;
  fs::remove_all(dir);
}

// The setup sheet says where a live tool's hole is: radial at X (the top as a diameter), Z and
// C; JSON gives its axis and C (null on the centre line, as before).
TEST(Holes, TheSheetSaysWhereALiveToolsHolesAre) {
  const std::string cl = source_dir() + "/tests/data/millturn-radial-holes.apt";
  RunResult html = run(quote(clpost_bin()) + " sheet -m linuxcnc-lathe-c -o - " + quote(cl));
  ASSERT_EQ(html.exit_code, 0) << html.err;
  EXPECT_NE(html.out.find("<td>X80 Z-20 C90, radial</td>"), std::string::npos) << html.out;
  EXPECT_NE(html.out.find("<p>On the spindle axis and off it with a live tool (at C), lengths in "),
            std::string::npos)
      << html.out;
  RunResult json =
      run(quote(clpost_bin()) + " sheet --format json -m linuxcnc-lathe-c -o - " + quote(cl));
  ASSERT_EQ(json.exit_code, 0) << json.err;
  EXPECT_NE(json.out.find("{\"line\": 11, \"cycle\": \"drilling\", \"x\": 40, \"z\": -30, "
                          "\"axis\": \"x\", \"c\": 180, \"depth\": 10, \"r\": 42,"),
            std::string::npos)
      << json.out;
  RunResult face = run(quote(clpost_bin()) + " sheet -m linuxcnc-lathe-c -o - " +
                       quote(source_dir() + "/tests/data/millturn-face-holes.apt"));
  EXPECT_NE(face.out.find("<td>X60 C90 Z0</td>"), std::string::npos) << face.out;
}

// The sheet names what wrote each hole as its reader calls it, the cycle and its code (not the
// machine file's template key), or the moves a fallback wrote; and the drill's diameter where
// the CL gave it (CUTTER/ before the tool change it describes). On fanuc-0i-t a first peck of 3
// then 5 cannot be one G83 Q: moves.
TEST(Holes, TheSheetNamesTheCycleWrittenAndTheDrill) {
  const std::string dir = temp_dir(), cl = dir + "/t.cl";
  write_file(cl,
             "FROM/0,0,20\nCUTTER/8.5\nLOADTL/1\nSPINDL/1000,RPM,CLW\n"
             "CYCLE/DEEP,DEPTH,20,STEP,5,MMPM,100,CLEAR,2\nGOTO/0,0,0\nCYCLE/OFF\n"
             "CYCLE/DEEP2,FEDTO,20,1STPECK,3,SUBPECK,5,MMPM,100,RAPTO,2,RTRCTO,20\nGOTO/0,0,-5\n"
             "CYCLE/OFF\nFINI\n");
  RunResult html = run(quote(clpost_bin()) + " sheet -m fanuc-0i-t -o - " + quote(cl));
  ASSERT_EQ(html.exit_code, 0) << html.err;
  EXPECT_NE(html.out.find("<td>peck drilling</td><td class=\"num\">8.5</td><td>X0 Z0</td>"),
            std::string::npos)
      << html.out;
  EXPECT_NE(html.out.find("<td>100 mm/min</td><td>peck drilling (G83)</td><td></td></tr>"),
            std::string::npos)
      << html.out;
  EXPECT_NE(html.out.find("<td>100 mm/min</td><td>G0/G1 moves</td><td>hole_peck not used: "),
            std::string::npos)
      << html.out;
  EXPECT_EQ(html.out.find("<td>hole_peck</td>"), std::string::npos) << html.out;
  fs::remove_all(dir);
}

// Face and radial holes of one live tool in one program (tests/data/millturn-mixed-holes.apt:
// a peck-drilled pair on the face at C0 and C90, radial holes at C0 and C-90 (GOTO/0,-40),
// one face hole at radius 20) verify on the three live machines. On linuxcnc-lathe-c the face
// G81 and the radial G81 differ only in their plane: a radial hole's G19 written G17 makes it
// a face hole, which verify refuses.
TEST(Holes, FaceAndRadialHolesInOneProgramVerify) {
  const std::string cl = "tests/data/millturn-mixed-holes.apt", dir = temp_dir();
  for (const char* m : {"linuxcnc-lathe-c", "haas-st-20y", "fanuc-0i-tf-live"}) {
    RunResult ok = run("cd " + quote(source_dir()) + " && " + quote(clpost_bin()) +
                       " --verify -m " + m + " -o " + quote(dir + "/ok.nc") + " " + cl);
    EXPECT_EQ(ok.exit_code, 0) << m << ok.err;
    EXPECT_NE(ok.err.find("holes (3 on the face at their X and C, 2 radial at their Z and C): 5 "
                          "in the CL, 5 in the program"),
              std::string::npos)
        << m << ok.err;
  }
  const std::string ngc = dir + "/holes.ngc";
  RunResult post = run("cd " + quote(source_dir()) + " && " + quote(clpost_bin()) +
                       " -m linuxcnc-lathe-c -o " + quote(ngc) + " " + cl);
  ASSERT_EQ(post.exit_code, 0) << post.err;
  std::string text = read_file(ngc);
  const size_t g19 = text.find("G19\nG98 G94 G81 X60. Y0 Z-10. R42. F100.\n");
  ASSERT_NE(g19, std::string::npos) << text;
  text.replace(g19, 3, "G17");
  write_file(ngc, text);
  RunResult r = run("cd " + quote(source_dir()) + " && " + quote(clpost_bin()) +
                    " verify -m linuxcnc-lathe-c " + quote(ngc) + " --cl " + cl);
  EXPECT_EQ(r.exit_code, 1) << r.err;
  EXPECT_NE(
      first_error(r).find("hole at " + cl + ":16: drilled along Z, CL: a radial hole along X"),
      std::string::npos)
      << r.err;
  fs::remove_all(dir);
}

// Live taps (tests/data/millturn-live-taps.apt: two M10x1.5 face taps at 1000 rpm, C90 and
// C180, one M10x1.25 radial tap at 800 rpm) verify on the three live machines. The lead is read
// back as the control taps it (left-hand taps too): LinuxCNC's K; Haas's and Fanuc's F per minute
// over the live tool's rpm as last written (M133 P1000: F1600. is a lead of 1.6, M70 S800 ...
// F1100. 1.375).
TEST(Holes, LiveTapsVerifyAndAWrongLeadFails) {
  const std::string cl = "tests/data/millturn-live-taps.apt", dir = temp_dir();
  for (const char* m : {"linuxcnc-lathe-c", "haas-st-20y", "fanuc-0i-tf-live"}) {
    RunResult ok = run("cd " + quote(source_dir()) + " && " + quote(clpost_bin()) +
                       " --verify -m " + m + " -o " + quote(dir + "/ok.nc") + " " + cl);
    EXPECT_EQ(ok.exit_code, 0) << m << ok.err;
    EXPECT_NE(ok.err.find("holes (2 on the face at their X and C, 1 radial at their Z and C): 3 "
                          "in the CL, 3 in the program"),
              std::string::npos)
        << m << ok.err;
  }
  // Left-hand (the live tools CCLW): Haas G186/G196, LinuxCNC G33.1 after M4 $1.
  std::string left = read_file(source_dir() + "/" + cl);
  for (size_t at; (at = left.find("RPM,CLW")) != std::string::npos;)
    left.replace(at, 7, "RPM,CCLW");
  write_file(dir + "/left.apt", left);
  for (const char* m : {"linuxcnc-lathe-c", "haas-st-20y"}) {
    RunResult ok = run(quote(clpost_bin()) + " --verify -m " + m + " -o " +
                       quote(dir + "/left.nc") + " " + quote(dir + "/left.apt"));
    EXPECT_EQ(ok.exit_code, 0) << m << ok.err;
    EXPECT_NE(ok.err.find(std::string("left.apt:16  radial tapping to X32.0000 (radius)  ok  ") +
                          (m[0] == 'h' ? "G196" : "G33.1")),
              std::string::npos)
        << m << ok.err;
  }
  struct Edit {
    const char* machine;
    const char* from;
    const char* to;
    const char* error;
  };
  const Edit edits[] = {
      {"linuxcnc-lathe-c", "G33.1 Z-10. K1.5 $1", "G33.1 Z-10. K1.4 $1", ":8: lead 1.4, CL 1.5"},
      {"haas-st-20y", "G95 X60. Z-10. R2. F1500.", "G95 X60. Z-10. R2. F1600.",
       ":8: lead 1.6, CL 1.5"},
      {"fanuc-0i-tf-live", "G88 X64. Z-10. R-8. F1000.", "G88 X64. Z-10. R-8. F1100.",
       ":16: lead 1.375, CL 1.25"},
      // The live tool's speed never written: the lead of F per minute is not known.
      {"haas-st-20y", "M133 P1000\n", "M133\n",
       ":8: the live tool's speed is not written before the tap: its lead is not known"}};
  for (const Edit& e : edits) {
    const std::string nc = dir + "/taps.nc";
    RunResult post = run("cd " + quote(source_dir()) + " && " + quote(clpost_bin()) + " -m " +
                         e.machine + " -o " + quote(nc) + " " + cl);
    ASSERT_EQ(post.exit_code, 0) << post.err;
    std::string text = read_file(nc);
    const size_t at = text.find(e.from);
    ASSERT_NE(at, std::string::npos) << e.machine << text;
    text.replace(at, std::string(e.from).size(), e.to);
    write_file(nc, text);
    RunResult r = run("cd " + quote(source_dir()) + " && " + quote(clpost_bin()) + " verify -m " +
                      e.machine + " " + quote(nc) + " --cl " + cl);
    EXPECT_EQ(r.exit_code, 1) << e.machine << r.err;
    EXPECT_NE(r.err.find("hole at " + cl + e.error), std::string::npos) << e.machine << r.err;
  }
  fs::remove_all(dir);
}

TEST(Holes, Rs274DrillsEveryHoleToItsDepths) {
  if (!rs274_available()) GTEST_SKIP() << "rs274 not installed: skipped";
  const std::string dir = temp_dir();
  const std::string ngc = dir + "/part.ngc";
  RunResult post = run(quote(clpost_bin()) + " -m linuxcnc-lathe -o " + quote(ngc) + " " +
                       quote(source_dir() + "/" + kPart));
  ASSERT_EQ(post.exit_code, 0) << post.err;
  RunResult r = run_rs274(dir, ngc);
  ASSERT_EQ(r.exit_code, 0) << r.err << r.out;
  std::vector<double> feeds;  // Z of every STRAIGHT_FEED at X0
  std::vector<std::string> events;
  std::istringstream in(r.out);
  for (std::string line; std::getline(in, line);) {
    double x = 0, y = 0, z = 0;
    size_t at;
    if ((at = line.find("STRAIGHT_FEED(")) != std::string::npos &&
        std::sscanf(line.c_str() + at + 14, "%lf, %lf, %lf", &x, &y, &z) == 3 && x == 0) {
      feeds.push_back(z);
    } else if ((at = line.find("DWELL(")) != std::string::npos) {
      events.push_back(line.substr(at));
    } else if ((at = line.find("RIGID_TAP(")) != std::string::npos) {
      events.push_back(line.substr(at));
    } else if ((at = line.find("START_SPEED_FEED_SYNC(1.5")) != std::string::npos) {
      events.push_back(line.substr(at));
    }
  }
  // The facing cut ends at X0 Z0 first.
  EXPECT_EQ(feeds, (std::vector<double>{0, -3, -3, -8, -13, -18, -22}));
  EXPECT_EQ(events, (std::vector<std::string>{"DWELL(0.5000)", "START_SPEED_FEED_SYNC(1.500000,0)",
                                              "RIGID_TAP(0.0000, 0.0000, -16.0000)"}));
}

}  // namespace
}  // namespace clpost::test

namespace clpost::test {
namespace {

namespace fs = std::filesystem;

// A drill that starts below its R plane (the tool at Z1, CLEAR,2: R at Z2) is a right program:
// written as moves on generic-lathe it goes up to R, feeds to the bottom and returns to Z1, and
// verify accepts it on every machine (it read "the tool does not come back out to Z2"). The
// program that stops short of Z1 still fails.
TEST(Holes, ADrillStartingBelowItsRPlaneVerifies) {
  const std::string dir = temp_dir();
  const std::string cl = dir + "/below-r.cl";
  write_file(cl,
             "UNITS/MM\nLOADTL/1\nSPINDL/500,RPM,CLW\nFEDRAT/0.1,MMPR\nGOTO/0,0,1\n"
             "CYCLE/DRILL,DEPTH,5,MMPR,0.05,CLEAR,2\nGOTO/0,0,0\nCYCLE/OFF\nGOTO/20,0,5\nFINI\n");
  for (const std::string& m : shipped_machine_names()) {
    const RunResult r = run(quote(clpost_bin()) + " -m " + m + " --verify -o " +
                            quote(dir + "/below-r." + m + ".nc") + " " + quote(cl));
    EXPECT_EQ(r.exit_code, 0) << m << "\n" << r.err;
  }
  std::string nc = read_file(dir + "/below-r.generic-lathe.nc");
  const size_t at = nc.find("G0 Z1.\n");
  ASSERT_NE(at, std::string::npos) << nc;
  nc.replace(at, 7, "G0 Z0.5\n");
  write_file(dir + "/edited.nc", nc);
  const RunResult r = run(quote(clpost_bin()) + " verify -m generic-lathe " +
                          quote(dir + "/edited.nc") + " --cl " + quote(cl));
  EXPECT_EQ(r.exit_code, 1);
  EXPECT_NE(r.err.find("the tool does not come back out to Z1.0000"), std::string::npos) << r.err;
  fs::remove_all(dir);
}

}  // namespace
}  // namespace clpost::test

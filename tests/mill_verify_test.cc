// verify of a live tool's milling (verify/mill_verify.h, docs/millturn.md): the program's X, Y,
// Z and C mapped back to the part against the CL's milling in the part frame turned by its C
// index (tests/data/millturn-face-mill.apt: a square, an arc and a slot through the centre at
// C index 30).
#include <gtest/gtest.h>

#include <filesystem>
#include <fstream>

#include "test_util.h"
#include "verify/mill_verify.h"

namespace clpost::test {
namespace {

namespace fs = std::filesystem;

const std::string kCl = source_dir() + "/tests/data/millturn-face-mill.apt";

// Posted with --verify on the three live machines: every CL point reached, every feed move
// (sampled at eighths as the control moves X, Y, Z and C together) on the CL path.
TEST(MillVerify, FaceMillingVerifiesOnTheLiveMachines) {
  const std::string dir = temp_dir();
  for (const char* m : {"linuxcnc-lathe-c", "fanuc-0i-tf-live", "haas-st-20y"}) {
    RunResult r = run(quote(clpost_bin()) + " -m " + m + " --verify -o " + quote(dir + "/p.nc") +
                      " " + quote(kCl));
    EXPECT_EQ(r.exit_code, 0) << m << r.err;
    EXPECT_NE((r.out + r.err)
                  .find("ok: every CL point reached in order and every feed move on "
                        "the CL path, within 0.006"),
              std::string::npos)
        << m << r.out << r.err;
  }
  fs::remove_all(dir);
}

// Milling longer than the lathe path check's window (16 384 program moves) between two lathe
// motions of the CL: 800 passes of the square (3200 lines, 115 169 XZC pieces), then the turning
// tool's GOTO/22,0,2, the one lathe motion. The milling moves are the milling check's, so the
// lathe's motion is still found in order (before: "motion at …:3214: X44.0000 Z2.0000 is not
// reached by the program in order", and no program at all).
TEST(MillVerify, MillingLongerThanThePathWindowVerifies) {
  const std::string dir = temp_dir(), cl = dir + "/long.cl";
  std::string text =
      "UNITS/MM\nLOADTL/3,MILL\nSPINDL/3000,RPM,CLW\nROTABL/30,CAXIS\nRAPID\nGOTO/10,-10,5\n"
      "FEDRAT/200,MMPM\n";
  for (int i = 0; i < 800; ++i)
    text += "GOTO/10,-10,-1\nGOTO/10,10,-1\nGOTO/-10,10,-1\nGOTO/-10,-10,-1\n";
  text +=
      "RAPID\nGOTO/10,-10,5\nSPINDL/OFF\nLOADTL/1,TURN\nSPINDL/1000,RPM,CLW\nRAPID\n"
      "GOTO/22,0,2\nFINI\n";
  std::ofstream(cl) << text;
  RunResult r = run(quote(clpost_bin()) + " -m linuxcnc-lathe-c --verify -o " +
                    quote(dir + "/p.ngc") + " " + quote(cl));
  EXPECT_EQ(r.exit_code, 0) << r.err;
  const size_t at = r.err.find(" program moves in X, Y, Z and C");
  ASSERT_NE(at, std::string::npos) << r.err;
  const size_t from = r.err.rfind(' ', at - 1) + 1;
  EXPECT_EQ(r.err.substr(from, at - from), "115169") << r.err;  // the window is 16 384
  EXPECT_NE(r.err.find("motions: 1 CL end points, every one reached in order"), std::string::npos)
      << r.err;
  EXPECT_TRUE(fs::exists(dir + "/p.ngc"));
  fs::remove_all(dir);
}

// The program `nc` with `from` replaced by `to` once, verified against the CL.
RunResult verify_edited(const std::string& machine, const std::string& from, const std::string& to,
                        const std::string& cl = kCl) {
  const std::string dir = temp_dir(), nc = dir + "/p.nc";
  RunResult p = run(quote(clpost_bin()) + " -m " + machine + " -o " + quote(nc) + " " + quote(cl));
  EXPECT_EQ(p.exit_code, 0) << p.err;
  std::string text = read_file(nc);
  const size_t at = text.find(from);
  EXPECT_NE(at, std::string::npos) << text;
  if (at != std::string::npos) text.replace(at, from.size(), to);
  std::ofstream(nc, std::ios::binary) << text;
  RunResult r =
      run(quote(clpost_bin()) + " verify -m " + machine + " " + quote(nc) + " --cl " + quote(cl));
  fs::remove_all(dir);
  return r;
}

// The corner (10, 10) at index 30 is radius 14.1421 at C75: written at C76 it is 1 degree off,
// 14.1421 x pi / 180 = 0.2468 mm along its circle.
TEST(MillVerify, ACMovedOneDegreeFails) {
  RunResult r =
      verify_edited("linuxcnc-lathe-c", "G1 X28.28427 Z-1. C75. ", "G1 X28.28427 Z-1. C76. ");
  EXPECT_NE(r.exit_code, 0);
  EXPECT_NE(r.err.find(":48:1: error: milling at " + kCl +
                       ":13: at C76.0000, CL C75.0000 (0.2468 mm along the circle of radius "
                       "14.1421)"),
            std::string::npos)
      << r.err;
  // Fanuc (C 0-360, F of the combined move): the same corner, X28.284 (3 decimals) a radius of
  // 14.1420.
  RunResult f = verify_edited("fanuc-0i-tf-live", "X28.284 Z-1. C75. ", "X28.284 Z-1. C76. ");
  EXPECT_NE(f.exit_code, 0);
  EXPECT_NE(f.err.find("at C76.0000, CL C75.0000 (0.2468 mm along the circle of radius 14.1420)"),
            std::string::npos)
      << f.err;
}

// haas-st-20y: Y 0.1 off at the corner (10, 10) (X20. Y10. at C30) is 0.1 mm from the path.
TEST(MillVerify, AYOffFailsOnHaasSt20y) {
  RunResult r = verify_edited("haas-st-20y", "G1 X20. Y10. Z-1. F200.", "G1 X20. Y10.1 Z-1. F200.");
  EXPECT_NE(r.exit_code, 0);
  EXPECT_NE(r.err.find("error: milling at " + kCl +
                       ":13: at X10.0000 (radius) Y10.1000 Z-1.0000 C30.0000, 0.1000 mm from the "
                       "CL path at (3.6603, 13.6603, -1.0000) (the part at C0)"),
            std::string::npos)
      << r.err;
}

// haas-st-20y writes the CL's arc (CIRCLE/ and its GOTO at line 18, radius 14.1421 about the
// centre, 270 degrees counter-clockwise from (10, -10) to (-10, -10) at C30) as G3 X-20. Y-10.
// I-10. J10. in G17 (the posted program verifies: FaceMillingVerifiesOnTheLiveMachines). verify
// follows an arc along its length, so an arc with its ends right but its way wrong fails at its
// line:
//  - G2: the short way round, 90 degrees clockwise; its first point, 5 degrees on at -50
//    degrees, is 2 x 14.1421 x sin 2.5 = 1.2337 mm from the CL's start at -45 degrees;
//  - the centre at (0, -5), as far from both ends (radius 11.1803): its first point at -21.605
//    degrees is at radius 13.8263, 0.3158 inside the CL's circle (0.3140 from its chords);
//  - the centre at (1, 0): radius 13.4536 from the start, 14.8661 to the end, 1.4124 apart.
TEST(MillVerify, AnArcIsFollowedAlongItsLength) {
  const std::pair<const char*, const char*> cases[] = {
      {"G2 X-20. Y-10. Z-1. I-10. J10.",
       "the arc (G2 about X0.0000 (radius) Y0.0000 Z-1.0000) passes at X9.0904 (radius) Y-10.8335 "
       "Z-1.0000 C30.0000, 1.2337 mm from the CL path at (13.6603, -3.6603, -1.0000) (the part "
       "at C0)"},
      {"G3 X-20. Y-10. Z-1. I-10. J5.",
       "the arc (G3 about X0.0000 (radius) Y-5.0000 Z-1.0000) passes at X10.3949 (radius) "
       "Y-9.1166 Z-1.0000 C30.0000, 0.3140 mm from the CL path at (13.8679, -2.7619, -1.0000) "
       "(the part at C0)"},
      {"G3 X-20. Y-10. Z-1. I-9. J10.",
       "the arc (G3 about X1.0000 (radius) Y0.0000 Z-1.0000): its end is 1.4124 mm off the "
       "circle through its start"}};
  for (const auto& [edited, why] : cases) {
    RunResult r = verify_edited("haas-st-20y", "G3 X-20. Y-10. Z-1. I-10. J10.", edited);
    EXPECT_EQ(r.exit_code, 1) << edited;
    EXPECT_NE(r.err.find(":21:1: error: milling at " + kCl + ":18: " + why), std::string::npos)
        << edited << r.err;
  }
}

}  // namespace
}  // namespace clpost::test

namespace clpost::test {
namespace {

// MillStream (clpost --verify, verify --cl) compares as the moves come, in whichever order the
// CL's pieces and the program's moves arrive: the same report and the same one error as
// verify_milling over the whole of both. A rapid to (10, 0, 5), then a feed down to Z-1 at C
// index 0; the program's feed ends at Z-1.5: 0.5 mm past the CL's end, said at its line.
TEST(MillVerify, TheStreamSaysWhatTheWholeSays) {
  const Machine m = shipped_machine("linuxcnc-lathe-c");
  VerifyOptions vo;
  vo.plan_name = "t.cl";
  const std::vector<MillSegment> cl = {{1, {0, 0, 5}, {10, 0, 5}, 0, true},
                                       {2, {10, 0, 5}, {10, 0, -1}, 0, false}};
  std::vector<SimMillMove> nc = {{7, "G0 X20. Z5. C0.", true, false, 10, 0, 5, 0},
                                 {8, "G1 Z-1.5", false, false, 10, 0, -1.5, 0}};
  Diagnostics whole("t.nc");
  const MillReport w = verify_milling(cl, nc, 2, m, vo, whole);
  EXPECT_EQ(w.problems, 1u);
  ASSERT_EQ(whole.kept().size(), 1u);
  EXPECT_EQ(whole.kept()[0].loc.line, 8u);
  EXPECT_EQ(whole.kept()[0].message,
            "milling at t.cl:2: at X10.0000 (radius) Y0.0000 Z-1.5000 C0.0000, 0.5000 mm from "
            "the CL path at (10.0000, 0.0000, -1.0000) (the part at C0)");
  for (const bool moves_first : {true, false}) {
    MillStream s(m, vo);
    if (moves_first)
      for (const SimMillMove& mv : nc) s.program_move(mv);
    for (const MillSegment& g : cl) s.cl_segment(g);
    s.cl_ended();
    if (!moves_first)
      for (const SimMillMove& mv : nc) s.program_move(mv);
    Diagnostics d("t.nc");
    const MillReport r = s.finish(2, d);
    EXPECT_EQ(r.text, w.text) << moves_first;
    ASSERT_EQ(d.kept().size(), 1u);
    EXPECT_EQ(d.kept()[0].message, whole.kept()[0].message);
    EXPECT_EQ(d.kept()[0].line_text, "G1 Z-1.5");
  }
  // Ending at Z-1 it is right, either way.
  nc[1].z = -1;
  Diagnostics ok("t.nc");
  EXPECT_EQ(verify_milling(cl, nc, 2, m, vo, ok).problems, 0u);
  EXPECT_EQ(ok.error_count(), 0u);
}

// Polar interpolation on haas-st-20y (millturn.polar_interpolation=true: G112, X and Y in the
// face plane at C0): the sample verifies, and the square's corner (-10, 10) at index 30, which
// is (-13.6603, 3.6603) in the plane, written (-13.66, 3.76) fails: off by (0.0003, 0.0997) from
// the corner, 0.0863 mm across the side it ends (along (-0.8660, -0.5): 0.0997 x 0.8660 -
// 0.0003 x 0.5), the nearest point of the side 0.0501 back from the corner, (-13.6169, 3.6853).
TEST(MillVerify, PolarInterpolationVerifiesAndAYOffFails) {
  const std::string dir = temp_dir(), nc = dir + "/p.nc";
  const std::string set = " --set millturn.polar_interpolation=true";
  RunResult p = run(quote(clpost_bin()) + " -m haas-st-20y" + set + " --verify -o " + quote(nc) +
                    " " + quote(kCl));
  EXPECT_EQ(p.exit_code, 0) << p.err;
  EXPECT_NE(p.err.find("ok: every CL point reached in order and every feed move on the CL path"),
            std::string::npos)
      << p.err;
  std::string text = read_file(nc);
  const std::string from = "G1 X-13.66 Y3.66 Z-1. F200.";
  const size_t at = text.find(from);
  ASSERT_NE(at, std::string::npos) << text;
  text.replace(at, from.size(), "G1 X-13.66 Y3.76 Z-1. F200.");
  std::ofstream(nc, std::ios::binary) << text;
  RunResult r = run(quote(clpost_bin()) + " verify -m haas-st-20y" + set + " " + quote(nc) +
                    " --cl " + quote(kCl));
  EXPECT_NE(r.exit_code, 0);
  EXPECT_NE(r.err.find("error: milling at " + kCl +
                       ":14: at X-13.6600 (radius) Y3.7600 Z-1.0000 C0.0000, 0.0863 mm from the "
                       "CL path at (-13.6169, 3.6853, -1.0000) (the part at C0)"),
            std::string::npos)
      << r.err;
  fs::remove_all(dir);
}

}  // namespace
}  // namespace clpost::test

namespace clpost::test {
namespace {

// Peripheral milling without Y (tests/data/millturn-peripheral-mill.apt: a radial tool's slot
// along Z at C90, a groove half round the 16 mm diameter, a helix-like line from C180 Z-10 to
// C190 Z-11): the program's X (the tip's radius) and C map back to the CL's tip points. It
// verifies on both machines without Y; a C one degree off fails at its line.
TEST(MillVerify, PeripheralMillingVerifiesAndACOffFails) {
  const std::string cl = source_dir() + "/tests/data/millturn-peripheral-mill.apt";
  const std::string dir = temp_dir();
  for (const char* m : {"linuxcnc-lathe-c", "fanuc-0i-tf-live"}) {
    RunResult r = run(quote(clpost_bin()) + " -m " + m + " --verify -o " + quote(dir + "/p.nc") +
                      " " + quote(cl));
    EXPECT_EQ(r.exit_code, 0) << m << r.err;
    EXPECT_NE((r.out + r.err)
                  .find("milling: 10 CL motions, 76 program moves in X, Y, Z and C\nok: every CL "
                        "point reached in order and every feed move on the CL path, within 0.006"),
              std::string::npos)
        << m << r.out << r.err;
  }
  fs::remove_all(dir);
  // The helix-like line's middle (the tip at radius 8 cos 5° = 7.9696, C185, Z-10.5) written at
  // C186: (-7.9259, -0.8331, -10.5) in the part, whose nearest point on the CL's line from
  // (-8, 0, -10) to (-7.878462, -1.389185, -11) is at 0.5659 of it, 0.0811 mm away.
  RunResult h =
      verify_edited("linuxcnc-lathe-c", "X15.93912 Z-10.5 C185. ", "X15.93912 Z-10.5 C186. ", cl);
  EXPECT_NE(h.exit_code, 0);
  EXPECT_NE(h.err.find("error: milling at " + cl +
                       ":22: at X7.9696 (radius) Y0.0000 Z-10.5000 C186.0000, 0.0811 mm from the "
                       "CL path at (-7.9312, -0.7861, -10.5659) (the part at C0)"),
            std::string::npos)
      << h.err;
  // The slot's plunge on Fanuc ending at C91 (the slot is at C90): the tip at radius 8 is
  // 8 x pi / 180 = 0.1396 mm along its circle from the CL's point, at CL line 14.
  RunResult s = verify_edited("fanuc-0i-tf-live", "G1 X16. Z5. G98", "G1 X16. Z5. C91. G98", cl);
  EXPECT_NE(s.exit_code, 0);
  EXPECT_NE(s.err.find("error: milling at " + cl +
                       ":14: at C91.0000, CL C90.0000 (0.1396 mm along the circle of radius "
                       "8.0000)"),
            std::string::npos)
      << s.err;
}

}  // namespace
}  // namespace clpost::test

// CATIA's mill-turn programs of a Swiss-type lathe (../shared/realcam/catia_toussaint, read in
// place) on haas-st-20y (docs/millturn.md): linear_3x_PATH2 posts and verifies with the speed
// limits raised to its 60 000 rpm turning and 15 000 rpm milling, and so does MillTurn3x_PATH1,
// its SYNC/ lines warnings naming the missing second channel.
#include <gtest/gtest.h>

#include <filesystem>
#include <fstream>

#include "test_util.h"

namespace clpost::test {
namespace {

namespace fs = std::filesystem;

const std::string kRaised =
    " -m haas-st-20y --set limits.max_rpm=60000 --set millturn.live_max_rpm=15000 ";

TEST(MillTurnRealcam, Linear3xPath2PostsAndVerifiesOnHaasSt20y) {
  const std::string cl = realcam_dir() + "/catia_toussaint/linear_3x_PATH2.aptsource";
  if (!fs::exists(cl)) GTEST_SKIP() << cl << " not found";
  const std::string dir = temp_dir(), nc = dir + "/p2.nc";
  RunResult r = run(quote(clpost_bin()) + kRaised + "--verify -o " + quote(nc) + " " + quote(cl));
  ASSERT_EQ(r.exit_code, 0) << r.err;
  // verify checks the milling: every CL point reached, every feed move on the CL path.
  EXPECT_NE((r.out + r.err)
                .find("ok: every CL point reached in order and every feed move on the "
                      "CL path, within 0.006"),
            std::string::npos)
      << r.out << r.err;
  const std::string out = read_file(nc);
  // The face tool 35: G17, the zig-zag across the centre line (X -2.9 .. 2.9 diameter, Y +-0.1)
  // at C0 (no ROTABL: noted).
  EXPECT_NE(out.find("M133 P15000\nG0 C0.\nM14\nG17\nG0 X0.072 Y0. Z5.5\n"), std::string::npos)
      << out;
  EXPECT_NE(out.find("G1 X-2.9 Y0.1 Z-0.017 F150.\nG1 X-2.9 Y-0.1 Z-0.02 F150.\n"),
            std::string::npos);
  // Tool 33's section ends at Y0 as written (the CL's last point Y0): no Y return, so no X
  // retract before it either; the live tool stops before tool 35 is loaded.
  EXPECT_NE(out.find("G0 X17.4 Y0. Z-2.784\n(END_OP/MILL)\nM135\nT3501\n"), std::string::npos)
      << out;
  // The radial tool 33 (tool axis -1,0,0): C180, X the depth: GOTO/-9.42906,0,-2.78441 is
  // X18.858.
  EXPECT_NE(out.find("M133 P15000\nG0 C180.\nM14\nG0 X18.858 Y0. Z-2.784\n"), std::string::npos)
      << out;
  EXPECT_NE(r.err.find("linear_3x_PATH2.aptsource:64:1: note: no ROTABL/ since C was engaged: "
                       "the milling is written with the part frame's X axis at C0"),
            std::string::npos)
      << r.err;
  fs::remove_all(dir);
}

}  // namespace
}  // namespace clpost::test

namespace clpost::test {
namespace {

// MillTurn3x_PATH1 on haas-st-20y (17 500 rpm allowed for its tool 4), the whole file in place:
// its SYNC/ lines are warnings naming the missing second channel, the only ones of their kind;
// its last operation (line 870), tool 5 with the tool axis 0,0,-1, is the face tool on the -Z
// side of the part's front face (the file's turning puts the part at Z >= 0): written in the
// CL's frame as every point of the file, G17 X Y Z at C0, CUTCOM/LEFT as G42 (seen from +Z).
// It posts and verifies; a face-op value moved by 0.01 fails verify at its line.
TEST(MillTurnRealcam, MillTurn3xPath1PostsAndVerifiesOnHaasSt20y) {
  const std::string cl = realcam_dir() + "/catia_toussaint/MillTurn3x_PATH1.aptsource";
  if (!fs::exists(cl)) GTEST_SKIP() << cl << " not found";
  const std::string raised =
      " -m haas-st-20y --set limits.max_rpm=60000 --set millturn.live_max_rpm=17500 ";
  const std::string dir = temp_dir(), nc = dir + "/p1.nc";
  RunResult r = run(quote(clpost_bin()) + raised + "--verify -o " + quote(nc) + " " + quote(cl));
  ASSERT_EQ(r.exit_code, 0) << r.err;
  EXPECT_EQ(r.err.find(": error: "), std::string::npos) << r.err;
  for (const char* line : {":291:1: ", ":292:1: "})
    EXPECT_NE(r.err.find(std::string("MillTurn3x_PATH1.aptsource") + line +
                         "warning: SYNC/ synchronises this program with another channel, and "
                         "machine 'haas-st-20y' has one channel (no second channel to wait for)"),
              std::string::npos)
        << r.err;
  EXPECT_NE((r.out + r.err)
                .find("ok: every CL point reached in order and every feed move on the "
                      "CL path, within 0.006"),
            std::string::npos)
      << r.out << r.err;
  EXPECT_NE(r.err.find("MillTurn3x_PATH1.aptsource:870:1: note: tool axis 0,0,-1: a face tool "
                       "on the -Z side, working a face that looks toward -Z"),
            std::string::npos)
      << r.err;
  const std::string out = read_file(nc);
  // Line 75: around the cylinder of radius 0.6 about X from (3.92906, 0.15, 1.77946), INDIRV +Y,
  // ON the plane z 2.37946: a quarter turn, positive about +X (G3 in G19), K0.6 from the start.
  // G19 comes at CUTCOM/LEFT (line 67), before G41: no plane change under compensation.
  // Line 84: HELICAL/ half a turn about X, X 0.00737 deeper.
  EXPECT_NE(out.find("G19\nG41\nG1 X7.858 Y0.15 Z1.779 F300.\n"
                     "G3 X7.858 Y0.75 Z2.379 J0. K0.6 F300.\n"),
            std::string::npos)
      << out;
  EXPECT_NE(out.find("G3 X7.832 Y-0.75 Z3. J-0.75 K0. F150.\n"), std::string::npos) << out;
  // Tool 5 (lines 870-881): C back to 0 from tool 4's C90, G17; GOTO/-0.1,0.05,-5.5 is
  // (diameter) Y0.05 Z-5.5; CUTCOM/LEFT seen from the tool on the -Z side is G42 from +Z; the
  // lead-in (CIRCLE/0,0.15,0,0.6) from (-0.6, 0.15), INDIRV +Y, to the line x 0: clockwise
  // seen from +Z to (0, 0.75), I0.6 J0. Line 884: HELICAL/ about (1.5, 0) from (1.5, 0.75)
  // INDIRV +X to (1.5, -0.75), Z 0.00991 -> 0.01509: G2, J-0.75.
  EXPECT_NE(out.find("M15\nG0 C0.\nM14\n"), std::string::npos) << out;
  EXPECT_NE(out.find("T0501\n"), std::string::npos) << out;
  EXPECT_NE(out.find("M133 P15000\nG17\nG0 X-0.2 Y0.05 Z-5.5\nG0 X-0.2 Y0.05 Z-0.5\n"
                     "G98 G1 X-0.2 Y0.05 Z0. F300.\nG42\nG1 X-1.2 Y0.15 Z0. F300.\n"
                     "G2 X0. Y0.75 Z0. I0.6 J0. F300.\nG1 X3. Y0.75 Z0.01 F150.\n"
                     "G2 X3. Y-0.75 Z0.015 I0. J-0.75 F150.\n"),
            std::string::npos)
      << out;
  // The program ends milling: as before a tool change, Y0 from the retract and G18, the live
  // tool stopped; then C unclamped and disengaged before M30.
  EXPECT_NE(out.find("G2 X1.2 Y0.15 Z0.5 I0. J-0.6 F500.\nG40\nG1 X0.2 Y0.05 Z0.5 F500.\n"
                     "G1 X0.2 Y0.05 Z0. F500.\nG0 X0.2 Y0.05 Z-5.\n(END_OP/MILL)\nG0 Y0.\n"
                     "G18\nM135\nM15\nM155\nM30\n"),
            std::string::npos)
      << out;
  // verify can fail on this operation: Y0.75 moved to Y0.76 at CL line 886.
  std::string bad = out;
  const std::string line = "G1 X3. Y0.75 Z0.01 F150.\n";
  ASSERT_NE(bad.find(line), std::string::npos);
  bad.replace(bad.find(line), line.size(), "G1 X3. Y0.76 Z0.01 F150.\n");
  std::ofstream(dir + "/bad.nc", std::ios::binary) << bad;
  RunResult v = run(quote(clpost_bin()) + " verify" + raised + "--cl " + quote(cl) + " " +
                    quote(dir + "/bad.nc"));
  EXPECT_NE(v.exit_code, 0);
  EXPECT_NE(v.err.find("MillTurn3x_PATH1.aptsource:886: at X1.5000 (radius) Y0.7600 Z0.0100 "
                       "C0.0000, 0.0100 mm from the CL path"),
            std::string::npos)
      << v.out << v.err;
  fs::remove_all(dir);
}

}  // namespace
}  // namespace clpost::test

namespace clpost::test {
namespace {

// MillTurn3x_PATH1 on the machines without Y (60 000 rpm for its turning, 17 500 for tool 4):
// its three peripheral operations contour a flat across the bar (tool axis 1,0,0 at x 3.9 with
// y from -0.75 to 0.75; tool 4 along 0,1,0 at x 0.05): every point is off the line of the tool
// axis through the centre line, work only a Y axis reaches. Each operation is one located error
// at its first point naming the offset (its approach rapid at y 0.05: 0.0500 mm); the face
// tool 5 on the -Z side (0,0,-1) is the fourth, for its CUTCOM/LEFT (line 875: without Y the
// control's compensation does not offset an XZC path). The turning between them posts.
TEST(MillTurnRealcam, MillTurn3xPath1WithoutYStopsAtItsYWork) {
  const std::string cl = realcam_dir() + "/catia_toussaint/MillTurn3x_PATH1.aptsource";
  if (!fs::exists(cl)) GTEST_SKIP() << cl << " not found";
  const std::string dir = temp_dir(), nc = dir + "/p1.nc";
  for (const std::string m : {"linuxcnc-lathe-c", "fanuc-0i-tf-live"}) {
    RunResult r = run(quote(clpost_bin()) + " -m " + m +
                      " --set limits.max_rpm=60000 --set millturn.live_max_rpm=17500 -o " +
                      quote(nc) + " " + quote(cl));
    EXPECT_NE(r.exit_code, 0);
    EXPECT_NE(r.err.find("MillTurn3x_PATH1.aptsource:62:1: error: milling motion with live tool 3 "
                         "(loaded at line 36): the tip (9.42906, 0.05, 2.27946) is 0.0500 mm off "
                         "the line of the tool axis (1, 0, 0) through the centre line "
                         "(millturn.xzc_tolerance 0.005): a radial tool reaches it with a Y axis "
                         "only, and machine '" +
                         m + "' has none"),
              std::string::npos)
        << r.err;
    EXPECT_NE(r.err.find("MillTurn3x_PATH1.aptsource:456:1: error: milling motion with live tool 3 "
                         "(loaded at line 430): the tip (9.42323, 0.05, 2.9) is 0.0500 mm off"),
              std::string::npos)
        << r.err;
    EXPECT_NE(r.err.find("MillTurn3x_PATH1.aptsource:664:1: error: milling motion with live tool 4 "
                         "(loaded at line 638): the tip (0.05, 9.4208, 1.6) is 0.0500 mm off the "
                         "line of the tool axis (0, 1, 0)"),
              std::string::npos)
        << r.err;
    EXPECT_NE(r.err.find("MillTurn3x_PATH1.aptsource:875:8: error: CUTCOM/LEFT with live tool 5: "
                         "machine '" +
                         m + "' has no Y axis"),
              std::string::npos)
        << r.err;
    size_t errors = 0;
    for (size_t at = r.err.find(": error: "); at != std::string::npos;
         at = r.err.find(": error: ", at + 1))
      ++errors;
    EXPECT_EQ(errors, 4u) << r.err;
    EXPECT_FALSE(fs::exists(nc));
  }
  fs::remove_all(dir);
}

}  // namespace
}  // namespace clpost::test

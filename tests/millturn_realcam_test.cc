// CATIA's mill-turn programs of a Swiss-type lathe (../shared/realcam/catia_toussaint, read in
// place) on haas-st-20y (docs/millturn.md): linear_3x_PATH2 posts and verifies with the speed
// limits raised to its 60 000 rpm turning and 15 000 rpm milling; MillTurn3x_PATH1's SYNC/ lines
// are warnings naming the missing second channel.
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

// MillTurn3x_PATH1 on haas-st-20y (17 500 rpm allowed for its tool 4): its SYNC/ lines are
// warnings naming the missing second channel; its last operation, a live tool facing +Z from
// the -Z side (tool axis 0,0,-1, line 870), is the one located error: the back face is no work
// for a one-turret lathe's main spindle. Up to that operation (its first 832 lines, in a
// temporary copy) it posts and verifies: the horizontal tool's TLON,GOFWD/(CYLNDR/…) and
// HELICAL/ are G19 G3 arcs.
TEST(MillTurnRealcam, MillTurn3xPath1PostsUpToItsBackFaceTool) {
  const std::string cl = realcam_dir() + "/catia_toussaint/MillTurn3x_PATH1.aptsource";
  if (!fs::exists(cl)) GTEST_SKIP() << cl << " not found";
  const std::string raised =
      " -m haas-st-20y --set limits.max_rpm=60000 --set millturn.live_max_rpm=17500 ";
  const std::string dir = temp_dir(), nc = dir + "/p1.nc";
  RunResult whole = run(quote(clpost_bin()) + raised + "-o " + quote(nc) + " " + quote(cl));
  EXPECT_NE(whole.exit_code, 0);
  EXPECT_NE(whole.err.find("MillTurn3x_PATH1.aptsource:291:1: warning: SYNC/ synchronises this "
                           "program with another channel, and machine 'haas-st-20y' has one "
                           "channel (no second channel to wait for)"),
            std::string::npos)
      << whole.err;
  EXPECT_NE(whole.err.find("MillTurn3x_PATH1.aptsource:870:1: error: milling motion with live "
                           "tool 5 (loaded at line 845): the tool axis (0, 0, -1) is neither the "
                           "face's (0,0,1) nor radial (k 0)"),
            std::string::npos)
      << whole.err;
  size_t errors = 0;
  for (size_t at = whole.err.find(": error: "); at != std::string::npos;
       at = whole.err.find(": error: ", at + 1))
    ++errors;
  EXPECT_EQ(errors, 1u) << whole.err;
  // The first 832 lines (up to the back-face tool's change), then FINI.
  std::string text = read_file(cl), head;
  size_t at = 0;
  for (int n = 0; n < 832 && at != std::string::npos; ++n) {
    const size_t end = text.find('\n', at);
    head += text.substr(at, end == std::string::npos ? end : end - at + 1);
    at = end == std::string::npos ? end : end + 1;
  }
  std::ofstream(dir + "/p1.apt", std::ios::binary) << head << "FINI\n";
  RunResult r =
      run(quote(clpost_bin()) + raised + "--verify -o " + quote(nc) + " " + quote(dir + "/p1.apt"));
  ASSERT_EQ(r.exit_code, 0) << r.err;
  EXPECT_NE((r.out + r.err)
                .find("ok: every CL point reached in order and every feed move on the "
                      "CL path, within 0.006"),
            std::string::npos)
      << r.out << r.err;
  // Line 75: around the cylinder of radius 0.6 about X from (3.92906, 0.15, 1.77946), INDIRV +Y,
  // ON the plane z 2.37946: a quarter turn, positive about +X (G3 in G19), K0.6 from the start.
  // Line 84: HELICAL/ half a turn about X, X 0.00737 deeper.
  const std::string out = read_file(nc);
  EXPECT_NE(out.find("G19\nG3 X7.858 Y0.75 Z2.379 J0. K0.6 F300.\n"), std::string::npos) << out;
  EXPECT_NE(out.find("G3 X7.832 Y-0.75 Z3. J-0.75 K0. F150.\n"), std::string::npos) << out;
  fs::remove_all(dir);
}

}  // namespace
}  // namespace clpost::test

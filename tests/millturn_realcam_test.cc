// CATIA's mill-turn programs of a Swiss-type lathe (../shared/realcam/catia_toussaint, read in
// place) on haas-st-20y (docs/millturn.md): linear_3x_PATH2 posts and verifies with the speed
// limits raised to its 60 000 rpm turning and 15 000 rpm milling; MillTurn3x_PATH1's SYNC/ lines
// are warnings naming the missing second channel.
#include <gtest/gtest.h>

#include <filesystem>

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

// LinuxCNC's own interpreter (rs274, Debian package linuxcnc-uspace) reads what clpost writes
// for linuxcnc-lathe: no error, and the end points of its motions, in order, are the CL's GOTO
// points (X as a radius: rs274 reports radii even in G7 diameter mode).
#include <gtest/gtest.h>

#include <cmath>
#include <cstdio>
#include <filesystem>
#include <sstream>

#include "reader/cl_reader.h"
#include "test_util.h"

namespace clpost::test {
namespace {

namespace fs = std::filesystem;

using XZ = CanonXZ;

bool have_rs274() {
  return run("command -v rs274").exit_code == 0;
}

// GOTO / GODLTA points of a CL file, read with the reader alone (not the interpreter).
std::vector<XZ> cl_points(const std::string& path) {
  std::vector<XZ> out;
  Diagnostics d(path);
  std::FILE* f = std::fopen(path.c_str(), "rb");
  ClReader reader(f, d);
  Statement st;
  double x = 0, z = 0;
  while (reader.next(st)) {
    if (st.major == "GOTO") {
      x = st.args[0].number;
      z = st.args.size() >= 3 ? st.args[2].number : z;
      out.push_back({x, z});
    } else if (st.major == "GODLTA") {
      x += st.args[0].number;
      z += st.args.size() >= 3 ? st.args[2].number : 0;
      out.push_back({x, z});
    }
  }
  std::fclose(f);
  return out;
}

TEST(Rs274, SamplesRunAndFollowTheClPoints) {
  if (!have_rs274())
    GTEST_SKIP() << "rs274 not installed (apt-get install linuxcnc-uspace): skipped";
  std::string dir = temp_dir();
  int checked = 0;
  for (const auto& e : fs::directory_iterator(source_dir() + "/samples")) {
    std::string ext = e.path().extension().string();
    if (ext != ".cls" && ext != ".ncl" && ext != ".apt" && ext != ".cl") continue;
    std::string ngc = dir + "/" + e.path().stem().string() + ".ngc";
    RunResult post = run(quote(clpost_bin()) + " -m linuxcnc-lathe -o " + quote(ngc) + " " +
                         quote(e.path().string()));
    ASSERT_EQ(post.exit_code, 0) << post.err;
    RunResult r = run("cd " + quote(dir) + " && " + rs274() + " -t " +
                      quote(source_dir() + "/tests/data/lathe.tbl") + " -g " + quote(ngc));
    EXPECT_EQ(r.exit_code, 0) << e.path() << ": rs274 says\n" << r.err << r.out;
    // Multi-pass threads add the planned passes between the GOTOs: thread_matrix_test.cc checks
    // those against the plan. Here they only have to run.
    if (read_file(e.path().string()).find("THREAD/ON") != std::string::npos) {
      ++checked;
      continue;
    }
    std::vector<XZ> got = rs274_motion_ends(r.out);
    std::vector<XZ> want = cl_points(e.path().string());
    ASSERT_EQ(got.size(), want.size()) << e.path();
    for (size_t i = 0; i < want.size(); ++i) {
      EXPECT_NEAR(got[i].x, want[i].x, 1e-4) << e.path() << " motion " << i + 1;
      EXPECT_NEAR(got[i].z, want[i].z, 1e-4) << e.path() << " motion " << i + 1;
    }
    ++checked;
  }
  EXPECT_GE(checked, 3);
  fs::remove_all(dir);
}

TEST(Rs274, CanonParserReadsWhatRs274Prints) {
  // From rs274 -g on "G7 G18 G21 G90 / G0 X20 Z5 / G2 X34 Z-22 I2 K0": radii, Z first on arcs.
  std::vector<XZ> m = rs274_motion_ends(
      "   12 N..... STRAIGHT_TRAVERSE(10.0000, 0.0000, 5.0000, 0.0000, 0.0000, 0.0000)\n"
      "   33 N..... ARC_FEED(-22.0000, 17.0000, -20.0000, 17.0000, -1, 0.0000, 0.0000, 0.0000, "
      "0.0000)\n");
  ASSERT_EQ(m.size(), 2u);
  EXPECT_DOUBLE_EQ(m[0].x, 10);
  EXPECT_DOUBLE_EQ(m[0].z, 5);
  EXPECT_DOUBLE_EQ(m[1].x, 17);
  EXPECT_DOUBLE_EQ(m[1].z, -22);
}

}  // namespace
}  // namespace clpost::test

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

// linuxcnc-lathe-c (docs/millturn.md) with an INI of two spindles and X Z C: the live tool is
// spindle 1 at the CL's 3000 rpm, C goes to 90, 45 (the shortest way) and 90 clockwise (C
// decreasing: 45 - 315 = -270, the same place as 90), the turning tool turns spindle 0 and its
// moves are the CL's points (radii) at that C.
TEST(Rs274, MillTurnLiveToolOnSpindleOneAndC) {
  if (!have_rs274())
    GTEST_SKIP() << "rs274 not installed (apt-get install linuxcnc-uspace): skipped";
  const std::string dir = temp_dir(), ngc = dir + "/c.ngc";
  RunResult post = run(quote(clpost_bin()) + " -m linuxcnc-lathe-c -o " + quote(ngc) + " " +
                       quote(source_dir() + "/samples/machines/linuxcnc-lathe-c.apt"));
  ASSERT_EQ(post.exit_code, 0) << post.err;
  RunResult r = run("cd " + quote(dir) + " && " + rs274() + " -i " +
                    quote(source_dir() + "/tests/data/millturn.ini") + " -t " +
                    quote(source_dir() + "/tests/data/lathe.tbl") + " -g " + quote(ngc));
  ASSERT_EQ(r.exit_code, 0) << r.err << r.out;
  std::vector<std::string> got;
  std::istringstream in(r.out);
  for (std::string line; std::getline(in, line);) {
    const size_t at = line.find("N..... ");
    if (at == std::string::npos) continue;
    const std::string call = line.substr(at + 7);
    if (call.starts_with("SET_SPINDLE_SPEED") || call.starts_with("START_SPINDLE") ||
        call.starts_with("STRAIGHT_"))
      got.push_back(call);
  }
  const std::vector<std::string> want = {
      "SET_SPINDLE_SPEED(1, 3000.0000)",
      "START_SPINDLE_CLOCKWISE(1)",
      "STRAIGHT_TRAVERSE(0.0000, 0.0000, 0.0000, 0.0000, 0.0000, 90.0000)",
      "STRAIGHT_TRAVERSE(0.0000, 0.0000, 0.0000, 0.0000, 0.0000, 45.0000)",
      "STRAIGHT_TRAVERSE(0.0000, 0.0000, 0.0000, 0.0000, 0.0000, -270.0000)",
      "SET_SPINDLE_SPEED(0, 1000.0000)",
      "START_SPINDLE_CLOCKWISE(0)",
      "STRAIGHT_TRAVERSE(22.0000, 0.0000, 2.0000, 0.0000, 0.0000, -270.0000)",
      "STRAIGHT_FEED(20.0000, 0.0000, 0.0000, 0.0000, 0.0000, -270.0000)",
      "STRAIGHT_FEED(20.0000, 0.0000, -15.0000, 0.0000, 0.0000, -270.0000)",
      "STRAIGHT_TRAVERSE(22.0000, 0.0000, 2.0000, 0.0000, 0.0000, -270.0000)"};
  EXPECT_EQ(got, want) << r.out;
  fs::remove_all(dir);
}

// The six numbers of a canonical STRAIGHT_FEED(x, y, z, a, b, c) line of rs274.
std::vector<double> canon_numbers(const std::string& call) {
  std::vector<double> out;
  std::istringstream in(call.substr(call.find('(') + 1));
  for (double v; in >> v;) {
    out.push_back(v);
    in.ignore(1);  // the comma
  }
  return out;
}

// A face bolt circle of a live tool on linuxcnc-lathe-c (docs/millturn.md): 4 holes at radius
// 30 (the GOTO's X), C 0, 90, 180, 270 (ROTABL). rs274 drills each at its X and C: mapped back
// to the part's face (X as a radius, C the angle: x cos C, x sin C), each bottom is the CL
// hole's point at the ROTABL in force, within 0.01 mm, 8 deep. G81 X60 in G7 is a diameter:
// rs274 reports the radius 30.
TEST(Rs274, MillTurnFaceBoltCircle) {
  if (!have_rs274())
    GTEST_SKIP() << "rs274 not installed (apt-get install linuxcnc-uspace): skipped";
  const std::string dir = temp_dir(), ngc = dir + "/holes.ngc";
  const std::string cl = source_dir() + "/tests/data/millturn-face-holes.apt";
  RunResult post =
      run(quote(clpost_bin()) + " -m linuxcnc-lathe-c -o " + quote(ngc) + " " + quote(cl));
  ASSERT_EQ(post.exit_code, 0) << post.err;
  RunResult r = run("cd " + quote(dir) + " && " + rs274() + " -i " +
                    quote(source_dir() + "/tests/data/millturn.ini") + " -t " +
                    quote(source_dir() + "/tests/data/lathe.tbl") + " -g " + quote(ngc));
  ASSERT_EQ(r.exit_code, 0) << r.err << r.out;
  struct FacePoint {
    double x, y, z;
  };
  const double deg = std::acos(-1.0) / 180;
  std::vector<FacePoint> got;
  std::istringstream out(r.out);
  for (std::string line; std::getline(out, line);) {
    const size_t at = line.find("STRAIGHT_FEED(");
    if (at == std::string::npos) continue;
    const std::vector<double> v = canon_numbers(line.substr(at));
    ASSERT_EQ(v.size(), 6u) << line;
    got.push_back({v[0] * std::cos(v[5] * deg), v[0] * std::sin(v[5] * deg), v[2]});
  }
  // The CL's holes: each GOTO in the cycle at the ROTABL in force, drilled 8 deep.
  std::vector<FacePoint> want;
  Diagnostics d(cl);
  std::FILE* f = std::fopen(cl.c_str(), "rb");
  ClReader reader(f, d);
  Statement st;
  double c = 0;
  bool in_cycle = false;
  while (reader.next(st)) {
    if (st.major == "ROTABL") c = st.args[0].number;
    if (st.major == "CYCLE") in_cycle = !st.args[0].is("OFF");
    if (st.major == "GOTO" && in_cycle)
      want.push_back({st.args[0].number * std::cos(c * deg), st.args[0].number * std::sin(c * deg),
                      st.args[2].number - 8});
  }
  std::fclose(f);
  ASSERT_EQ(want.size(), 4u);
  ASSERT_EQ(got.size(), want.size()) << r.out;
  for (size_t i = 0; i < want.size(); ++i) {
    EXPECT_NEAR(got[i].x, want[i].x, 0.01) << "hole " << i + 1;
    EXPECT_NEAR(got[i].y, want[i].y, 0.01) << "hole " << i + 1;
    EXPECT_NEAR(got[i].z, want[i].z, 0.01) << "hole " << i + 1;
  }
  // The third hole, by hand: radius 30 at C180 is the part's (-30, 0).
  EXPECT_NEAR(got[2].x, -30, 0.01);
  EXPECT_NEAR(got[2].y, 0, 0.01);
  fs::remove_all(dir);
}

// Radial holes of a live tool on linuxcnc-lathe-c (G19 G81, docs/millturn.md): rs274 drills each
// along X at its Z and C. Mapped back to the part (x = X cos C, y = X sin C), the bottoms are
// the CL's by hand: radius 40 drilled 10 deep is radius 30; hole 1 at C0 is (30, 0, -10),
// hole 2 at C90 (0, 30, -20), hole 3 (GOTO/0,40 at index 90: C 90 + 90) (-30, 0, -30). rs274
// takes the bottom X as a diameter in G7 and R as a radius: the feeds start at X 42.
TEST(Rs274, MillTurnRadialHoles) {
  if (!have_rs274())
    GTEST_SKIP() << "rs274 not installed (apt-get install linuxcnc-uspace): skipped";
  const std::string dir = temp_dir(), ngc = dir + "/radial.ngc";
  const std::string cl = source_dir() + "/tests/data/millturn-radial-holes.apt";
  RunResult post =
      run(quote(clpost_bin()) + " -m linuxcnc-lathe-c -o " + quote(ngc) + " " + quote(cl));
  ASSERT_EQ(post.exit_code, 0) << post.err;
  RunResult r = run("cd " + quote(dir) + " && " + rs274() + " -i " +
                    quote(source_dir() + "/tests/data/millturn.ini") + " -t " +
                    quote(source_dir() + "/tests/data/lathe.tbl") + " -g " + quote(ngc));
  ASSERT_EQ(r.exit_code, 0) << r.err << r.out;
  const double deg = std::acos(-1.0) / 180;
  std::vector<std::vector<double>> got;  // part x, y, z of each feed's end
  std::vector<double> feed_from;         // X (a radius) where each feed starts
  double last_x = 0;
  std::istringstream out(r.out);
  for (std::string line; std::getline(out, line);) {
    const bool feed = line.find("STRAIGHT_FEED(") != std::string::npos;
    const size_t at = line.find(feed ? "STRAIGHT_FEED(" : "STRAIGHT_TRAVERSE(");
    if (at == std::string::npos) continue;
    const std::vector<double> v = canon_numbers(line.substr(at));
    ASSERT_EQ(v.size(), 6u) << line;
    if (feed) {
      got.push_back({v[0] * std::cos(v[5] * deg), v[0] * std::sin(v[5] * deg), v[2]});
      feed_from.push_back(last_x);
    }
    last_x = v[0];
  }
  const std::vector<std::vector<double>> want = {{30, 0, -10}, {0, 30, -20}, {-30, 0, -30}};
  ASSERT_EQ(got.size(), want.size()) << r.out;
  for (size_t i = 0; i < want.size(); ++i) {
    for (size_t k = 0; k < 3; ++k) EXPECT_NEAR(got[i][k], want[i][k], 0.01) << "hole " << i + 1;
    EXPECT_NEAR(feed_from[i], 42, 0.01) << "hole " << i + 1 << ": R plane, radius 40 + 2";
  }
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

// LinuxCNC's own interpreter (rs274, Debian package linuxcnc-uspace) reads what clpost writes
// for linuxcnc-lathe: no error, and the end points of its motions, in order, are the CL's GOTO
// points (X as a radius: rs274 reports radii even in G7 diameter mode).
#include <gtest/gtest.h>

#include <algorithm>
#include <array>
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

// rs274 on a linuxcnc-lathe-c program, run in DIR with the mill-turn INI (two spindles, X Z C)
// and the lathe tool table: its canonical calls.
RunResult millturn_rs274(const std::string& dir, const std::string& ngc) {
  return run("cd " + quote(dir) + " && " + rs274() + " -i " +
             quote(source_dir() + "/tests/data/millturn.ini") + " -t " +
             quote(source_dir() + "/tests/data/lathe.tbl") + " -g " + quote(ngc));
}

// The CL file posted on linuxcnc-lathe-c to NGC.
RunResult post_millturn(const std::string& cl, const std::string& ngc) {
  return run(quote(clpost_bin()) + " -m linuxcnc-lathe-c -o " + quote(ngc) + " " + quote(cl));
}

// linuxcnc-lathe-c (docs/millturn.md) with an INI of two spindles and X Z C: the live tool is
// spindle 1 at the CL's 3000 rpm, C goes to 90, 45 (the shortest way) and 90 clockwise (C
// decreasing: 45 - 315 = -270, the same place as 90), the turning tool turns spindle 0 and its
// moves are the CL's points (radii) at that C.
TEST(Rs274, MillTurnLiveToolOnSpindleOneAndC) {
  if (!have_rs274())
    GTEST_SKIP() << "rs274 not installed (apt-get install linuxcnc-uspace): skipped";
  const std::string dir = temp_dir(), ngc = dir + "/c.ngc";
  RunResult post = post_millturn(source_dir() + "/samples/machines/linuxcnc-lathe-c.apt", ngc);
  ASSERT_EQ(post.exit_code, 0) << post.err;
  RunResult r = millturn_rs274(dir, ngc);
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
  RunResult post = post_millturn(cl, ngc);
  ASSERT_EQ(post.exit_code, 0) << post.err;
  RunResult r = millturn_rs274(dir, ngc);
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

// A program that ends milling (face milling at C 26.5651, then FINI: src/interpreter/
// milling_end_test.cc) on linuxcnc-lathe-c: rs274 runs it, and the live tool (spindle 1) stops
// after the last motion and before M2, as before a tool change, not by the program end (M2's
// own reset comes after: SET_G5X_OFFSET, then the stops of both spindles, then PROGRAM_END).
TEST(Rs274, MillTurnEndsMillingBeforeTheProgramEnd) {
  if (!have_rs274())
    GTEST_SKIP() << "rs274 not installed (apt-get install linuxcnc-uspace): skipped";
  const std::string dir = temp_dir(), cl = dir + "/face.cl", ngc = dir + "/face.ngc";
  write_file(cl,
             "LOADTL/3,MILL\nSPINDL/2000,RPM,CLW\nROTABL/0,CAXIS\nRAPID\nGOTO/10,5,2\n"
             "FEDRAT/100,MMPM\nGOTO/10,5,-1\nGOTO/20,10,-1\nRAPID\nGOTO/20,10,2\nFINI\n");
  RunResult post = post_millturn(cl, ngc);
  ASSERT_EQ(post.exit_code, 0) << post.err;
  RunResult r = millturn_rs274(dir, ngc);
  ASSERT_EQ(r.exit_code, 0) << r.err << r.out;
  const size_t last_move = r.out.rfind("STRAIGHT_TRAVERSE(22.3607, 0.0000, 2.0000");
  ASSERT_NE(last_move, std::string::npos) << r.out;
  const size_t stop = r.out.find("STOP_SPINDLE_TURNING(1)", last_move);
  const size_t reset = r.out.find("SET_G5X_OFFSET", last_move);
  const size_t end = r.out.find("PROGRAM_END()", last_move);
  ASSERT_NE(stop, std::string::npos) << r.out;
  ASSERT_NE(end, std::string::npos) << r.out;
  EXPECT_LT(stop, reset) << r.out;
  EXPECT_LT(reset, end) << r.out;
  // Nothing moves between the last motion and the program end.
  EXPECT_EQ(r.out.find("STRAIGHT_", last_move + 1), std::string::npos) << r.out;
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
  RunResult post = post_millturn(cl, ngc);
  ASSERT_EQ(post.exit_code, 0) << post.err;
  RunResult r = millturn_rs274(dir, ngc);
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

// Live taps on linuxcnc-lathe-c (tests/data/millturn-live-taps.apt): rs274 taps each with
// G33.1 synchronised with spindle 1, the live tool (START_SPEED_FEED_SYNC at the lead, then
// RIGID_TAP to the bottom). Mapped back to the part at the C of the traverse before it, the
// bottoms are the CL's by hand: radius 30 at C90, 10 deep: (0, 30, -10); at C180 (GOTO/0,30 at
// index 90) (-30, 0, -10); the radial tap from radius 40, 8 deep, at C0 and Z-10: (32, 0, -10).
// The same program tapping on spindle 0 ($0), which is stopped, is refused by rs274.
TEST(Rs274, MillTurnLiveTaps) {
  if (!have_rs274())
    GTEST_SKIP() << "rs274 not installed (apt-get install linuxcnc-uspace): skipped";
  const std::string dir = temp_dir(), ngc = dir + "/taps.ngc";
  const std::string cl = source_dir() + "/tests/data/millturn-live-taps.apt";
  RunResult post = post_millturn(cl, ngc);
  ASSERT_EQ(post.exit_code, 0) << post.err;
  const auto rs274_on = [&](const std::string& path) { return millturn_rs274(dir, path); };
  RunResult r = rs274_on(ngc);
  ASSERT_EQ(r.exit_code, 0) << r.err << r.out;
  const double deg = std::acos(-1.0) / 180;
  std::vector<std::vector<double>> got;  // part x, y, z of each tap's bottom
  std::vector<double> leads;
  double c = 0;
  std::istringstream out(r.out);
  for (std::string line; std::getline(out, line);) {
    if (size_t at = line.find("STRAIGHT_TRAVERSE("); at != std::string::npos)
      c = canon_numbers(line.substr(at))[5];
    if (size_t at = line.find("START_SPEED_FEED_SYNC("); at != std::string::npos)
      leads.push_back(canon_numbers(line.substr(at))[0]);
    if (size_t at = line.find("RIGID_TAP("); at != std::string::npos) {
      const std::vector<double> v = canon_numbers(line.substr(at));
      ASSERT_EQ(v.size(), 3u) << line;
      got.push_back({v[0] * std::cos(c * deg), v[0] * std::sin(c * deg), v[2]});
    }
  }
  const std::vector<std::vector<double>> want = {{0, 30, -10}, {-30, 0, -10}, {32, 0, -10}};
  ASSERT_EQ(got.size(), want.size()) << r.out;
  for (size_t i = 0; i < want.size(); ++i)
    for (size_t k = 0; k < 3; ++k) EXPECT_NEAR(got[i][k], want[i][k], 0.01) << "tap " << i + 1;
  EXPECT_EQ(leads, (std::vector<double>{1.5, 1.5, 1.25}));
  std::string text = read_file(ngc);
  for (size_t at; (at = text.find("K1.5 $1")) != std::string::npos;) text.replace(at, 7, "K1.5 $0");
  write_file(dir + "/main.ngc", text);
  RunResult main = rs274_on(dir + "/main.ngc");
  EXPECT_NE((main.out + main.err).find("Spindle not turning in G33.1"), std::string::npos)
      << main.out << main.err;
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

namespace clpost::test {
namespace {

// Face milling of a live tool on linuxcnc-lathe-c (docs/millturn.md): the part frame's lines
// and arc written in X, Z and C by the post (tests/data/millturn-face-mill.apt, C index 30).
// rs274 runs the program; every feed move it makes, sampled at eighths as the control moves
// (X, Z and C linear), mapped back to the part (X as the radius at angle C - 30) lies within
// 0.01 mm of the CL path, every CL point is reached, and the tool moves along the part at the
// CL's 200 mm/min (G93: rs274 turns F into a rate over the move's length).
struct PartSeg {
  double ax, ay, bx, by;  // a line a-b (the part frame)
  bool arc = false;       // or an arc about the centre 0,0 of radius hypot(a)
};

double to_seg(const PartSeg& s, double x, double y) {
  if (s.arc) return std::abs(std::hypot(x, y) - std::hypot(s.ax, s.ay));
  const double dx = s.bx - s.ax, dy = s.by - s.ay;
  const double t = std::clamp(((x - s.ax) * dx + (y - s.ay) * dy) / (dx * dx + dy * dy), 0.0, 1.0);
  return std::hypot(s.ax + dx * t - x, s.ay + dy * t - y);
}

TEST(Rs274, MillTurnFaceMillingInXzcFollowsThePartPath) {
  if (!have_rs274())
    GTEST_SKIP() << "rs274 not installed (apt-get install linuxcnc-uspace): skipped";
  const std::string dir = temp_dir(), ngc = dir + "/mill.ngc";
  const std::string cl = source_dir() + "/tests/data/millturn-face-mill.apt";
  RunResult post = post_millturn(cl, ngc);
  ASSERT_EQ(post.exit_code, 0) << post.err;
  RunResult r = millturn_rs274(dir, ngc);
  ASSERT_EQ(r.exit_code, 0) << r.err << r.out;
  // The CL's cut at Z -1 and -2 (the square, the arc, the slot through the centre line).
  const std::vector<PartSeg> path = {{10, -10, 10, 10},     {10, 10, -10, 10},
                                     {-10, 10, -10, -10},   {-10, -10, 10, -10},
                                     {10, -10, 0, 0, true}, {12, 0.002, -12, 0.002}};
  const std::vector<std::pair<double, double>> corners = {{10, -10},  {10, 10},    {-10, 10},
                                                          {-10, -10}, {12, 0.002}, {-12, 0.002}};
  const double deg = std::acos(-1.0) / 180;
  std::vector<double> at, rate_now;
  double rate = 0, worst = 0;
  size_t feeds = 0, timed = 0;
  std::vector<bool> reached(corners.size(), false);
  std::istringstream out(r.out);
  for (std::string line; std::getline(out, line);) {
    if (const size_t f = line.find("SET_FEED_RATE("); f != std::string::npos)
      rate = canon_numbers(line.substr(f))[0];
    const size_t t = line.find("STRAIGHT_TRAVERSE("), m = line.find("STRAIGHT_FEED(");
    if (t == std::string::npos && m == std::string::npos) continue;
    const std::vector<double> v = canon_numbers(line.substr(t != std::string::npos ? t : m));
    ASSERT_EQ(v.size(), 6u) << line;
    if (m != std::string::npos && !at.empty() && v[2] < -0.5) {
      ++feeds;
      for (int k = 0; k <= 8; ++k) {
        const double x = at[0] + (v[0] - at[0]) * k / 8, z = at[2] + (v[2] - at[2]) * k / 8;
        const double c = (at[5] + (v[5] - at[5]) * k / 8 - 30) * deg;
        const double px = x * std::cos(c), py = x * std::sin(c);
        double d = 1e9;
        for (const PartSeg& s : path) d = std::min(d, to_seg(s, px, py));
        EXPECT_LE(d, 0.01) << line << " at " << k << "/8: part " << px << ", " << py << ", " << z;
        worst = std::max(worst, d);
        for (size_t i = 0; i < corners.size(); ++i)
          reached[i] =
              reached[i] || std::hypot(px - corners[i].first, py - corners[i].second) < 0.01;
      }
      // The time rs274 gives the move (its length over X and Z, else C, over the rate) and the
      // part length it covers: the CL's 200 per minute, but on the flips at the centre.
      const double ca = (at[5] - 30) * deg, cb = (v[5] - 30) * deg;
      const double part = std::hypot(v[0] * std::cos(cb) - at[0] * std::cos(ca),
                                     v[0] * std::sin(cb) - at[0] * std::sin(ca));
      const double linear = std::hypot(v[0] - at[0], v[2] - at[2]);
      const double minutes = (linear > 1e-9 ? linear : std::abs(v[5] - at[5])) / rate;
      if (part > 0.05) {
        EXPECT_NEAR(part / minutes, 200, 2) << line;
        ++timed;
      }
    }
    at = v;
  }
  EXPECT_GT(feeds, 100u);
  EXPECT_GT(timed, 100u);
  EXPECT_LT(worst, 0.006);  // the machine's xzc_tolerance 0.005, and the output's rounding
  for (size_t i = 0; i < corners.size(); ++i) EXPECT_TRUE(reached[i]) << "corner " << i;
  fs::remove_all(dir);
}

// The mill-turn sample (samples/millturn/part.apt) as linuxcnc-lathe-c's reviewed program, run by
// rs274: every live-tool feed, mapped back to the part (X the radius at angle C, less the C index
// its CL frame is turned by), is where the CL puts it, within 0.01 mm. By hand from the CL:
// - T3: four face holes at radius 20, C 0/90/180/270, bottom Z-10 (pecks of 3 from R Z2);
// - T4: two radial holes at Z-25 down to radius 30 - 8 = 22, at C 45 and 225;
// - T5: the stadium at Z-2, C index 30: every point at distance 4 from the segment (11,0)-(19,0),
//   its four tangent points (11,+-4), (19,+-4) reached.
struct Canon {
  int tool = 0;
  bool feed = false;
  std::vector<double> from, to;  // x (radius), y, z, a, b, c
};

std::vector<Canon> canon_moves(const std::string& out_text) {
  std::vector<Canon> out;
  int tool = 0;
  std::vector<double> at;
  std::istringstream out_lines(out_text);
  for (std::string line; std::getline(out_lines, line);) {
    if (const size_t t = line.find("CHANGE_TOOL("); t != std::string::npos)
      tool = static_cast<int>(canon_numbers(line.substr(t))[0]);
    const size_t r = line.find("STRAIGHT_TRAVERSE("), f = line.find("STRAIGHT_FEED(");
    if (r == std::string::npos && f == std::string::npos) continue;
    const std::vector<double> v = canon_numbers(line.substr(r != std::string::npos ? r : f));
    if (!at.empty()) out.push_back({tool, f != std::string::npos, at, v});
    at = v;
  }
  return out;
}

// The part point of canonical position `v` sampled at t along from-to, in the CL frame of index
// `index` degrees.
std::pair<double, double> part_xy(const Canon& m, double t, double index) {
  const double deg = std::acos(-1.0) / 180;
  const double x = m.from[0] + (m.to[0] - m.from[0]) * t;
  const double c = (m.from[5] + (m.to[5] - m.from[5]) * t - index) * deg;
  return {x * std::cos(c), x * std::sin(c)};
}

TEST(Rs274, MillTurnPartIsWhereTheClSays) {
  if (!have_rs274())
    GTEST_SKIP() << "rs274 not installed (apt-get install linuxcnc-uspace): skipped";
  const std::string ngc = source_dir() + "/samples/golden/linuxcnc-lathe-c/millturn-part.ngc";
  const std::string dir = temp_dir();
  RunResult r = millturn_rs274(dir, ngc);
  ASSERT_EQ(r.exit_code, 0) << r.err << r.out;
  std::vector<std::pair<double, double>> face, radial;
  const std::vector<std::pair<double, double>> tangents = {{11, -4}, {19, -4}, {19, 4}, {11, 4}};
  std::vector<bool> reached(tangents.size(), false);
  size_t stadium = 0;
  for (const Canon& m : canon_moves(r.out)) {
    if (!m.feed) continue;
    if (m.tool == 3 && std::abs(m.to[2] + 10) < 1e-6) face.push_back(part_xy(m, 1, 0));
    if (m.tool == 4 && std::abs(m.to[0] - 22) < 1e-6) {
      EXPECT_NEAR(m.to[2], -25, 1e-6);
      radial.push_back(part_xy(m, 1, 0));
    }
    if (m.tool != 5) continue;
    ++stadium;
    for (int k = 0; k <= 8; ++k) {
      const auto [px, py] = part_xy(m, k / 8.0, 30);
      const double along = std::hypot(px - std::clamp(px, 11.0, 19.0), py);
      EXPECT_NEAR(along, 4, 0.01) << "T5 feed at " << k << "/8: part " << px << ", " << py;
      for (size_t i = 0; i < tangents.size(); ++i)
        reached[i] =
            reached[i] || std::hypot(px - tangents[i].first, py - tangents[i].second) < 0.01;
    }
  }
  const std::vector<std::pair<double, double>> face_cl = {{20, 0}, {0, 20}, {-20, 0}, {0, -20}};
  const double h = 22 / std::sqrt(2.0);
  const std::vector<std::pair<double, double>> radial_cl = {{h, h}, {-h, -h}};
  ASSERT_EQ(face.size(), face_cl.size());
  for (size_t i = 0; i < face.size(); ++i) {
    EXPECT_NEAR(face[i].first, face_cl[i].first, 0.01) << "face hole " << i;
    EXPECT_NEAR(face[i].second, face_cl[i].second, 0.01) << "face hole " << i;
  }
  ASSERT_EQ(radial.size(), radial_cl.size());
  for (size_t i = 0; i < radial.size(); ++i) {
    EXPECT_NEAR(radial[i].first, radial_cl[i].first, 0.01) << "radial hole " << i;
    EXPECT_NEAR(radial[i].second, radial_cl[i].second, 0.01) << "radial hole " << i;
  }
  EXPECT_GT(stadium, 20u);
  for (size_t i = 0; i < tangents.size(); ++i) EXPECT_TRUE(reached[i]) << "tangent point " << i;
  fs::remove_all(dir);
}

}  // namespace
}  // namespace clpost::test

namespace clpost::test {
namespace {

// Peripheral milling without Y (docs/millturn.md): a radial live tool's slot along Z at C90, its
// groove half round the 16 mm diameter and its helix-like line changing C and Z together
// (tests/data/millturn-peripheral-mill.apt), written in X, Z and C on linuxcnc-lathe-c. rs274
// runs the program; every feed move, sampled at eighths as the control moves (X, Z and C
// linear), mapped back to the part (X the radius at angle C) lies within 0.006 mm of the CL path
// (the machine's xzc_tolerance and the output's rounding), every CL point is reached, and the
// tip moves along the part at the CL's 100 mm/min.
struct Seg3 {
  double a[3], b[3];
  bool groove = false;  // or the arc of radius 8 about Z at Z-10 from C0 to C180
};

double to_seg3(const Seg3& s, const double p[3]) {
  if (s.groove) return p[1] < -1e-9 ? 1e9 : std::hypot(std::hypot(p[0], p[1]) - 8, p[2] + 10);
  double d[3], len2 = 0, t = 0;
  for (int i = 0; i < 3; ++i) d[i] = s.b[i] - s.a[i], len2 += d[i] * d[i];
  for (int i = 0; i < 3; ++i) t += (p[i] - s.a[i]) * d[i] / len2;
  t = std::clamp(t, 0.0, 1.0);
  double e = 0;
  for (int i = 0; i < 3; ++i) e += (s.a[i] + d[i] * t - p[i]) * (s.a[i] + d[i] * t - p[i]);
  return std::sqrt(e);
}

TEST(Rs274, MillTurnPeripheralMillingFollowsThePartPath) {
  if (!have_rs274())
    GTEST_SKIP() << "rs274 not installed (apt-get install linuxcnc-uspace): skipped";
  const std::string dir = temp_dir(), ngc = dir + "/periph.ngc";
  const std::string cl = source_dir() + "/tests/data/millturn-peripheral-mill.apt";
  RunResult post = post_millturn(cl, ngc);
  ASSERT_EQ(post.exit_code, 0) << post.err;
  RunResult r = millturn_rs274(dir, ngc);
  ASSERT_EQ(r.exit_code, 0) << r.err << r.out;
  const double ex = -7.878462, ey = -1.389185;  // the helix-like line's end: 8 at 190 degrees
  const std::vector<Seg3> path = {{{0, 15, 5}, {0, 8, 5}},
                                  {{0, 8, 5}, {0, 8, -20}},
                                  {{0, 8, -20}, {0, 15, -20}},
                                  {{15, 0, -10}, {8, 0, -10}},
                                  {{8, 0, -10}, {-8, 0, -10}, true},
                                  {{-8, 0, -10}, {ex, ey, -11}},
                                  {{ex, ey, -11}, {-14.772116, -2.604723, -11}}};
  const std::vector<std::array<double, 3>> corners = {{0, 8, 5},   {0, 8, -20},  {8, 0, -10},
                                                      {0, 8, -10}, {-8, 0, -10}, {ex, ey, -11}};
  std::vector<bool> reached(corners.size(), false);
  const double deg = std::acos(-1.0) / 180;
  double rate = 0, worst = 0;
  size_t feeds = 0, timed = 0;
  std::istringstream out(r.out);
  std::vector<double> at;
  for (std::string line; std::getline(out, line);) {
    if (const size_t f = line.find("SET_FEED_RATE("); f != std::string::npos)
      rate = canon_numbers(line.substr(f))[0];
    const size_t t = line.find("STRAIGHT_TRAVERSE("), m = line.find("STRAIGHT_FEED(");
    if (t == std::string::npos && m == std::string::npos) continue;
    const std::vector<double> v = canon_numbers(line.substr(t != std::string::npos ? t : m));
    ASSERT_EQ(v.size(), 6u) << line;
    if (m != std::string::npos && !at.empty()) {
      ++feeds;
      double part[2][3];
      for (int k = 0; k <= 8; ++k) {
        const double x = at[0] + (v[0] - at[0]) * k / 8, z = at[2] + (v[2] - at[2]) * k / 8;
        const double c = (at[5] + (v[5] - at[5]) * k / 8) * deg;
        const double p[3] = {x * std::cos(c), x * std::sin(c), z};
        double d = 1e9;
        for (const Seg3& s : path) d = std::min(d, to_seg3(s, p));
        EXPECT_LE(d, 0.006) << line << " at " << k << "/8: part " << p[0] << ", " << p[1] << ", "
                            << p[2];
        worst = std::max(worst, d);
        for (size_t i = 0; i < corners.size(); ++i)
          reached[i] = reached[i] || std::hypot(p[0] - corners[i][0], p[1] - corners[i][1],
                                                p[2] - corners[i][2]) < 0.006;
        if (k == 0 || k == 8) std::copy(p, p + 3, part[k / 8]);
      }
      // rs274's time for the move: its length over X and Z, else C (G93: the rate it derives).
      const double linear = std::hypot(v[0] - at[0], v[2] - at[2]);
      const double minutes = (linear > 1e-9 ? linear : std::abs(v[5] - at[5])) / rate;
      const double along =
          std::hypot(part[1][0] - part[0][0], part[1][1] - part[0][1], part[1][2] - part[0][2]);
      EXPECT_NEAR(along / minutes, 100, 1) << line;
      ++timed;
    }
    at = v;
  }
  // The slot's plunge, cut and retract, the groove's plunge and its 63 chords of 180/63
  // degrees (sagitta 8 (1 - cos(90/63 degrees)) = 0.00249, within half the tolerance), the
  // helix-like line's 4 pieces (2 would be 0.0095 off it), the retract.
  EXPECT_EQ(feeds, 3u + 1u + 63u + 4u + 1u);
  EXPECT_EQ(timed, feeds);
  EXPECT_LT(worst, 0.006);
  for (size_t i = 0; i < corners.size(); ++i) EXPECT_TRUE(reached[i]) << "CL point " << i;
  fs::remove_all(dir);
}

}  // namespace
}  // namespace clpost::test

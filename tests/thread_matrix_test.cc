// Issue-3 conformance: a matrix of thread CL files (every OPTION x CUTS/STEP, with and without
// FINCUT, each pull-out kind, MULTRD, taper, face, internal, inch) is posted on linuxcnc-lathe and
// run through LinuxCNC's own interpreter. Every synchronized move rs274 reports must start and
// end where the plan (`clpost plan --format json`) says: pass from -> to, then the pull-out
// delta, within 0.001 mm.
#include <gtest/gtest.h>

#include <algorithm>
#include <cmath>
#include <cstdio>
#include <filesystem>
#include <numbers>
#include <regex>
#include <sstream>

#include "test_util.h"

namespace clpost::test {
namespace {

namespace fs = std::filesystem;

struct XZ {
  double x = 0, z = 0;
};

struct Case {
  const char* name;
  bool inch;
  XZ p0, p1, p2;
  const char* params;           // after THREAD/ON,
  const char* p3;               // third GOTO ("x,z") or nullptr
  bool linear_pullout = false;  // chamfer angle outside 30..60: emulation cuts it with G1
};

// M20x2.5 external turn from Z2 to Z-30 unless said otherwise (CL X is a radius).
const Case kCases[] = {
    {"opt0_cuts", false, {15, 5}, {10, 2}, {10, -30}, "DEPTH,1.534,CUTS,5,MMPR,2.5", nullptr},
    {"opt0_step", false, {15, 5}, {10, 2}, {10, -30}, "DEPTH,1.534,STEP,0.5,MMPR,2.5", nullptr},
    {"opt1_cuts_fincut",
     false,
     {15, 5},
     {10, 2},
     {10, -30},
     "DEPTH,1.534,CUTS,5,FINCUT,1,0.1,OPTION,1,MMPR,2.5",
     nullptr},
    {"opt1_step",
     false,
     {15, 5},
     {10, 2},
     {10, -30},
     "DEPTH,1.534,STEP,0.6,OPTION,1,MMPR,2.5",
     nullptr},
    {"opt2_cuts_spring",
     false,
     {15, 5},
     {10, 2},
     {10, -30},
     "DEPTH,1.534,CUTS,6,FINCUT,2,OPTION,2,MMPR,2.5",
     nullptr},
    {"opt2_step",
     false,
     {15, 5},
     {10, 2},
     {10, -30},
     "DEPTH,1.534,STEP,0.5,OPTION,2,MMPR,2.5",
     nullptr},
    {"opt3_cuts",
     false,
     {15, 5},
     {10, 2},
     {10, -30},
     "DEPTH,1.534,CUTS,4,OPTION,3,MMPR,2.5",
     nullptr},
    {"opt3_step_fincut",
     false,
     {15, 5},
     {10, 2},
     {10, -30},
     "DEPTH,1.534,STEP,0.4,FINCUT,1,0.134,OPTION,3,MMPR,2.5",
     nullptr},
    {"opt4_cuts",
     false,
     {15, 5},
     {10, 2},
     {10, -30},
     "DEPTH,1.534,CUTS,4,OPTION,4,MMPR,2.5",
     nullptr},
    {"opt4_step",
     false,
     {15, 5},
     {10, 2},
     {10, -30},
     "DEPTH,1.534,STEP,0.5,OPTION,4,MMPR,2.5",
     nullptr},
    {"couplets", false, {15, 5}, {10, 2}, {10, -30}, "CUTS,2,0.5,3,0.178,MMPR,2.5", nullptr},
    {"chamfr_45",
     false,
     {15, 5},
     {10, 2},
     {10, -30},
     "DEPTH,1.534,CUTS,5,CHAMFR,2.5,MMPR,2.5",
     nullptr},
    {"chamfr_negative",
     false,
     {15, 5},
     {10, 2},
     {10, -30},
     "DEPTH,1.534,CUTS,5,CHAMFR,-3,60,MMPR,2.5",
     nullptr},
    {"chamfr_linear",
     false,
     {15, 5},
     {10, 2},
     {10, -30},
     "DEPTH,1.534,CUTS,5,CHAMFR,2,20,MMPR,2.5",
     nullptr,
     true},
    {"atangl",
     false,
     {15, 5},
     {10, 2},
     {10, -30},
     "DEPTH,1.534,CUTS,5,ATANGL,30,2,MMPR,2.5",
     nullptr},
    {"third_goto", false, {15, 5}, {10, 2}, {10, -30}, "DEPTH,1.534,CUTS,5,MMPR,2.5", "12.5,-32.5"},
    {"return_h",
     false,
     {15, 5},
     {10, 2},
     {10, -30},
     "DEPTH,1.534,CUTS,5,RETURN,3,MMPR,2.5",
     nullptr},
    {"return_p0",
     false,
     {15, 5},
     {10, 2},
     {10, -30},
     "DEPTH,1.534,CUTS,5,RETURN,MMPR,2.5",
     nullptr},
    {"multrd2",
     false,
     {15, 5},
     {10, 6},
     {10, -30},
     "DEPTH,1.534,CUTS,4,OPTION,1,MMPR,2.5,MULTRD,2",
     nullptr},
    {"multrd3",
     false,
     {15, 10},
     {10, 9},
     {10, -30},
     "DEPTH,0.92,CUTS,3,MMPR,1.5,MULTRD,3",
     nullptr},
    {"taper", false, {16, 5}, {9, 2}, {10, -30}, "DEPTH,1.227,CUTS,5,OPTION,1,MMPR,2", nullptr},
    {"face", false, {30, 5}, {25, 0}, {8, 0}, "DEPTH,0.92,CUTS,4,MMPR,1.5", nullptr},
    {"internal",
     false,
     {5, 5},
     {8.5, 2},
     {8.5, -25},
     "DEPTH,1.083,CUTS,5,OPTION,1,MMPR,2",
     nullptr},
    {"internal_chamfr",
     false,
     {5, 5},
     {8.5, 2},
     {8.5, -25},
     "DEPTH,1.083,CUTS,5,CHAMFR,1.5,MMPR,2",
     nullptr},
    {"inch_tpi",
     true,
     {0.6, 0.2},
     {0.375, 0.1},
     {0.375, -1},
     "DEPTH,0.0384,CUTS,4,FINCUT,1,0.004,OPTION,1,TPI,16",
     nullptr},
    {"inch_cutang",
     true,
     {0.6, 0.2},
     {0.375, 0.1},
     {0.375, -1},
     "DEPTH,0.0384,CUTS,4,CUTANG,210,TPI,16",
     nullptr},
    // Cut as G76 on linuxcnc-lathe: H2, the exit taper E L2, an angled infeed as Q, a thread
    // cut toward +Z, an internal constant-depth thread.
    {"g76_spring",
     false,
     {15, 5},
     {10, 2},
     {10, -30},
     "DEPTH,1.534,CUTS,5,FINCUT,2,OPTION,1,MMPR,2.5",
     nullptr},
    {"g76_exit_taper",
     false,
     {15, 5},
     {10, 2},
     {10, -30},
     "DEPTH,1.534,CUTS,5,OPTION,1,CHAMFR,1.534,MMPR,2.5",
     nullptr},
    {"g76_cutang",
     false,
     {15, 5},
     {10, 2},
     {10, -30},
     "DEPTH,1.534,CUTS,4,OPTION,3,CUTANG,210,MMPR,2.5",
     nullptr},
    {"g76_toward_plus",
     false,
     {15, -35},
     {10, -30},
     {10, 2},
     "DEPTH,1.534,CUTS,5,OPTION,1,MMPR,2.5",
     nullptr},
    {"g76_internal_opt3",
     false,
     {5, 5},
     {8.5, 2},
     {8.5, -25},
     "DEPTH,1.083,STEP,0.3,OPTION,3,MMPR,2",
     nullptr},
};

bool have_rs274() {
  return run("command -v rs274").exit_code == 0;
}

std::string cl_text(const Case& c) {
  std::ostringstream s;
  s << (c.inch ? "UNITS/INCHES\n" : "UNITS/MM\n") << "LOADTL/1\nSPINDL/" << (c.inch ? 300 : 500)
    << ",RPM,CLW\n"
    << (c.inch ? "FEDRAT/0.008,IPR\n" : "FEDRAT/0.2,MMPR\n") << "RAPID\nGOTO/" << c.p0.x << ",0,"
    << c.p0.z << "\nRAPID\nTHREAD/ON," << c.params << "\nGOTO/" << c.p1.x << ",0," << c.p1.z
    << "\nGOTO/" << c.p2.x << ",0," << c.p2.z << "\n";
  if (c.p3) {
    std::string p3 = c.p3;
    s << "GOTO/" << p3.substr(0, p3.find(',')) << ",0," << p3.substr(p3.find(',') + 1) << "\n";
  }
  s << "THREAD/OFF\nRAPID\nGOTO/" << c.p0.x << ",0," << c.p0.z << "\nFINI\n";
  return s.str();
}

struct Seg {
  XZ from, to;
};

// Planned synchronized segments: each pass's cut, then its threaded pull-out.
// The {"x": .., "z": ..} points of `text`, in order.
std::vector<XZ> points_in(const std::string& text) {
  std::vector<XZ> out;
  std::regex point_re(R"re(\{"x": ([-0-9.e]+), "z": ([-0-9.e]+)\})re");
  for (auto it = std::sregex_iterator(text.begin(), text.end(), point_re);
       it != std::sregex_iterator(); ++it)
    out.push_back({std::stod((*it)[1]), std::stod((*it)[2])});
  return out;
}

// The JSON array that follows `key` in `text` ("" when there is none).
std::string array_after(const std::string& text, const std::string& key) {
  const size_t at = text.find("\"" + key + "\": [");
  if (at == std::string::npos) return "";
  return text.substr(at, text.find(']', at) - at);
}

// Every planned synchronized move of one thread's JSON: each pass from -> to (a chain's pass:
// every segment of its path), then its threaded pull-out.
std::vector<Seg> planned(const std::string& json, bool linear) {
  std::vector<Seg> out;
  std::regex pullout_re(R"re("pullout": \{"x": ([-0-9.e]+), "z": ([-0-9.e]+)\})re");
  std::smatch m;
  bool have_pullout = std::regex_search(json, m, pullout_re);
  XZ d = have_pullout ? XZ{std::stod(m[1]), std::stod(m[2])} : XZ{};
  std::regex pass_re(
      R"re("from": \{"x": ([-0-9.e]+), "z": ([-0-9.e]+)\}, "to": \{"x": ([-0-9.e]+), "z": ([-0-9.e]+)\}([^\n]*))re");
  for (auto it = std::sregex_iterator(json.begin(), json.end(), pass_re);
       it != std::sregex_iterator(); ++it) {
    const std::smatch& p = *it;
    XZ from{std::stod(p[1]), std::stod(p[2])}, to{std::stod(p[3]), std::stod(p[4])};
    const std::vector<XZ> path = points_in(array_after(p[5].str(), "path"));
    if (path.size() >= 2) {
      for (size_t j = 1; j < path.size(); ++j) out.push_back({path[j - 1], path[j]});
    } else {
      out.push_back({from, to});
    }
    if (have_pullout && !linear) out.push_back({to, {to.x + d.x, to.z + d.z}});
  }
  return out;
}

// Synchronized moves in rs274 canonical output.
std::vector<Seg> synced(const std::string& canon) {
  std::vector<Seg> out;
  for (const CanonSegment& s : rs274_synced_moves(canon))
    out.push_back({{s.from.x, s.from.z}, {s.to.x, s.to.z}});
  return out;
}

// The cases linuxcnc-lathe writes as one G76 block (its law gives exactly the planned passes);
// the others fall back to the emulation, each with a comment saying why. The reasons, by case:
// OPTION 0 laws, alternating flanks (OPTION 2, 4), couplets, every pull-out whose rise is not the
// thread depth or that is not threaded, several starts, taper, face.
// opt1_cuts_fincut and inch_tpi have a finish allowance that G76 happens to cut: the last
// rough depth times sqrt((c + 1)/c) is not below DEPTH, so the control goes to K next.
const char* const kG76Cases[] = {
    "opt1_cuts_fincut", "opt1_step",      "opt3_cuts",  "internal",        "inch_tpi",
    "g76_spring",       "g76_exit_taper", "g76_cutang", "g76_toward_plus", "g76_internal_opt3"};

bool expects_g76(const Case& c) {
  for (const char* n : kG76Cases)
    if (std::string(n) == c.name) return true;
  return false;
}

// G76 blocks and fallback comments in a LinuxCNC program.
int count_lines_starting(const std::string& text, const std::string& prefix) {
  int n = 0;
  std::istringstream in(text);
  std::string line;
  while (std::getline(in, line))
    if (line.compare(0, prefix.size(), prefix) == 0) ++n;
  return n;
}

class ThreadMatrix : public ::testing::TestWithParam<Case> {};

TEST_P(ThreadMatrix, Rs274CutsThePlan) {
  if (!have_rs274())
    GTEST_SKIP() << "rs274 not installed (apt-get install linuxcnc-uspace): skipped";
  const Case& c = GetParam();
  std::string dir = temp_dir();
  std::string cl = dir + "/" + c.name + ".cl", ngc = dir + "/" + c.name + ".ngc";
  write_file(cl, cl_text(c));
  RunResult plan = run(quote(clpost_bin()) + " plan --format json -m linuxcnc-lathe " + quote(cl));
  ASSERT_EQ(plan.exit_code, 0) << plan.err;
  RunResult post =
      run(quote(clpost_bin()) + " -m linuxcnc-lathe -o " + quote(ngc) + " " + quote(cl));
  ASSERT_EQ(post.exit_code, 0) << post.err;
  RunResult r = run("cd " + quote(dir) + " && " + rs274() + " -t " +
                    quote(source_dir() + "/tests/data/lathe.tbl") + " -g " + quote(ngc));
  ASSERT_EQ(r.exit_code, 0) << "rs274: " << r.err << "\n" << read_file(ngc);
  // G76 where its law gives the plan, else the emulation with the reason: either way rs274 must
  // cut exactly the planned passes (below).
  const std::string nc = read_file(ngc);
  EXPECT_EQ(count_lines_starting(nc, "G76 "), expects_g76(c) ? 1 : 0) << nc;
  EXPECT_EQ(count_lines_starting(nc, "(G76 not used: "), expects_g76(c) ? 0 : 1) << nc;
  std::vector<Seg> want = planned(plan.out, c.linear_pullout);
  std::vector<Seg> got = synced(r.out);
  ASSERT_GT(want.size(), 0u);
  ASSERT_EQ(got.size(), want.size()) << plan.out << "\n" << read_file(ngc);
  // 0.001 mm. rs274 prints 4 decimals: in an inch program its own print rounding (half of
  // 0.0001 in) is added, since the printout cannot resolve 0.001 mm.
  double tol = c.inch ? 0.001 / 25.4 + 0.00005 : 0.001;
  for (size_t i = 0; i < want.size(); ++i) {
    EXPECT_NEAR(got[i].from.x, want[i].from.x, tol) << c.name << " segment " << i + 1;
    EXPECT_NEAR(got[i].from.z, want[i].from.z, tol) << c.name << " segment " << i + 1;
    EXPECT_NEAR(got[i].to.x, want[i].to.x, tol) << c.name << " segment " << i + 1;
    EXPECT_NEAR(got[i].to.z, want[i].to.z, tol) << c.name << " segment " << i + 1;
  }
  fs::remove_all(dir);
}

// The planned synchronized segments of every thread in a `clpost plan --format json` printout,
// in order: each thread's passes with its pull-out, which emulation feeds with G1 (not
// synchronized) when its angle to the thread line is outside 30..60 degrees.
std::vector<Seg> planned_all(const std::string& json) {
  std::vector<Seg> out;
  std::vector<size_t> at;
  for (size_t p = json.find("\"line\": "); p != std::string::npos;
       p = json.find("\"line\": ", p + 1))
    at.push_back(p);
  at.push_back(json.size());
  std::regex p1_re(
      R"re("p1": \{"x": ([-0-9.e]+), "z": ([-0-9.e]+)\},\s*"p2": \{"x": ([-0-9.e]+), "z": ([-0-9.e]+)\})re");
  std::regex pullout_re(R"re("pullout": \{"x": ([-0-9.e]+), "z": ([-0-9.e]+)\})re");
  for (size_t i = 0; i + 1 < at.size(); ++i) {
    const std::string one = json.substr(at[i], at[i + 1] - at[i]);
    std::smatch m, q;
    bool linear = false;
    if (std::regex_search(one, q, pullout_re) && std::regex_search(one, m, p1_re)) {
      // The pull-out's angle with the thread line (a chain's: its last segment).
      double tx = std::stod(m[4]) - std::stod(m[2]), tr = std::stod(m[3]) - std::stod(m[1]);
      const std::vector<XZ> contour = points_in(array_after(one, "points"));
      if (contour.size() >= 2) {
        tx = contour.back().z - contour[contour.size() - 2].z;
        tr = contour.back().x - contour[contour.size() - 2].x;
      }
      const double dx = std::stod(q[1]), dz = std::stod(q[2]);
      const double c = std::fabs(tx * dz + tr * dx) / std::hypot(tx, tr) / std::hypot(dx, dz);
      const double angle = std::acos(std::min(1.0, c)) * 180 / std::numbers::pi;
      linear = angle < 30 - 1e-6 || angle > 60 + 1e-6;
    }
    std::vector<Seg> segs = planned(one, linear);
    out.insert(out.end(), segs.begin(), segs.end());
  }
  return out;
}

// The shared thread samples and linuxcnc-lathe's own sample, posted on linuxcnc-lathe: every
// thread written as G76 (and every fallback) cuts in rs274 exactly the planned passes.
TEST(ThreadSamples, Rs274CutsThePlanOfEveryThread) {
  if (!have_rs274())
    GTEST_SKIP() << "rs274 not installed (apt-get install linuxcnc-uspace): skipped";
  std::vector<std::string> files;
  for (const auto& e : fs::directory_iterator(source_dir() + "/samples/threads"))
    if (e.path().extension() == ".apt") files.push_back(e.path().string());
  files.push_back(source_dir() + "/samples/machines/linuxcnc-lathe.apt");
  files.push_back(source_dir() + "/samples/thread-m20.apt");
  std::sort(files.begin(), files.end());
  std::string dir = temp_dir();
  int g76 = 0;
  for (const std::string& f : files) {
    std::string ngc = dir + "/" + fs::path(f).stem().string() + ".ngc";
    RunResult plan = run(quote(clpost_bin()) + " plan --format json -m linuxcnc-lathe " + quote(f));
    ASSERT_EQ(plan.exit_code, 0) << plan.err;
    RunResult post =
        run(quote(clpost_bin()) + " -m linuxcnc-lathe -o " + quote(ngc) + " " + quote(f));
    ASSERT_EQ(post.exit_code, 0) << post.err;
    RunResult r = run("cd " + quote(dir) + " && " + rs274() + " -t " +
                      quote(source_dir() + "/tests/data/lathe.tbl") + " -g " + quote(ngc));
    ASSERT_EQ(r.exit_code, 0) << f << ": rs274: " << r.err << "\n" << read_file(ngc);
    const std::string nc = read_file(ngc);
    g76 += count_lines_starting(nc, "G76 ");
    std::vector<Seg> want = planned_all(plan.out);
    std::vector<Seg> got = synced(r.out);
    ASSERT_EQ(got.size(), want.size()) << f << "\n" << nc;
    const double tol =
        plan.out.find("\"units\": \"in\"") != std::string::npos ? 0.001 / 25.4 + 0.00005 : 0.001;
    for (size_t i = 0; i < want.size(); ++i) {
      EXPECT_NEAR(got[i].from.x, want[i].from.x, tol) << f << " segment " << i + 1;
      EXPECT_NEAR(got[i].from.z, want[i].from.z, tol) << f << " segment " << i + 1;
      EXPECT_NEAR(got[i].to.x, want[i].to.x, tol) << f << " segment " << i + 1;
      EXPECT_NEAR(got[i].to.z, want[i].to.z, tol) << f << " segment " << i + 1;
    }
  }
  // finish 3, inch 1, internal 1, options 4, pullouts 2, linuxcnc-lathe 5 (see the goldens).
  EXPECT_EQ(g76, 16);
  fs::remove_all(dir);
}

INSTANTIATE_TEST_SUITE_P(Threads, ThreadMatrix, ::testing::ValuesIn(kCases),
                         [](const ::testing::TestParamInfo<Case>& i) {
                           return std::string(i.param.name);
                         });

}  // namespace
}  // namespace clpost::test

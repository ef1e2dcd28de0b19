// Every text CL file in ../shared/realcam (CATIA V5 with ICAM and custom tables, NX, Makino, an
// APT360 part program) is read without a single reader error: what the reader cannot read in a
// statement travels with it as its problem (the interpreter decides), and the statements are
// the ones an independent count finds.
#include <gtest/gtest.h>

#include <cstdio>
#include <filesystem>
#include <map>
#include <string>

#include "reader/cl_reader.h"
#include "reader/cl_reader_test_util.h"

namespace clpost {
namespace {

namespace fs = std::filesystem;

const fs::path kRealCam = CLPOST_SOURCE_DIR "/../shared/realcam";

struct FileResult {
  size_t statements = 0;
  size_t errors = 0;
  std::string diags;
  std::map<std::string, size_t> problems;  // "line:col message" of each statement's problem
};

FileResult read_file(const fs::path& path) {
  FileResult r;
  r.statements = reader_test::read_whole_file(
      path,
      [&r](const Statement& s) {
        if (!s.has_problem()) return;
        ++r.problems[std::string(s.major) + " " + std::to_string(s.problem.loc.line) + ":" +
                     std::to_string(s.problem.loc.col) + " " + s.problem.message];
      },
      r.errors, r.diags);
  return r;
}

TEST(RealCam, AllTextFilesReadWithoutReaderErrors) {
  if (!fs::is_directory(kRealCam)) GTEST_SKIP() << kRealCam << " not found";
  std::map<std::string, FileResult> results;
  for (const fs::directory_entry& e : fs::recursive_directory_iterator(kRealCam)) {
    if (!e.is_regular_file() || e.path().filename() == "README.md") continue;
    results[fs::relative(e.path(), kRealCam).string()] = read_file(e.path());
  }
  // 14 text files and APT360's binary cl.tap (ClReader hands it to the CLDATA reader).
  EXPECT_EQ(results.size(), 15u);
  for (const auto& [name, r] : results) {
    EXPECT_EQ(r.errors, 0u) << name << "\n" << r.diags;
    EXPECT_GT(r.statements, 0u) << name;
  }

  // Counted independently: lines that start (after blanks) with a letter and do not continue a
  // line (statement or `$$` comment: CATIA wraps both) ending in a single `$`:
  //   awk '{sub(/\r$/,""); if (!c && /^[ \t]*[A-Za-z]/) n++; t=$0; sub(/[ \t]+$/,"",t);
  //        c = (t ~ /[^$]\$$/ || t == "$")} END {print n}' FILE
  const std::map<std::string, size_t> counts = {
      {"catia_karlo/DEMO1.txt", 31},
      {"catia_karlo/DEMO2.txt", 18},
      {"catia_karlo/DEMO4.txt", 65},
      {"catia_karlo/DEMO5.txt", 28},
      {"catia_toussaint/MillTurn3x_PATH1.aptsource", 485},
      {"catia_toussaint/TURNING_PATH1_TRANSV.aptsource", 55},
      {"catia_toussaint/linear_3x_PATH2.aptsource", 285},
      {"catia_liubaishuo/CVZ1234567.aptsource", 228},
      {"catia_liubaishuo/peening.aptsource", 143},
      {"nx_clsf_steptools/coremill.cls", 4492},
      {"nx_clsf_steptools/simple_block.cls", 205},
      {"makino_steptools/Plane_1.cldata", 323},
      {"makino_steptools/Plane_2.cldata", 162},
      {"apt360_binary/window.apt", 40},
  };
  for (const auto& [name, n] : counts) EXPECT_EQ(results[name].statements, n) << name;

  // The lathe programs: DEMO5's arcs as APT geometry read whole; what is left as a problem is
  // free text (TPRINT is a text statement, so CATIA's tool names are not among them).
  EXPECT_TRUE(results["catia_karlo/DEMO1.txt"].problems.empty());
  EXPECT_TRUE(results["catia_karlo/DEMO5.txt"].problems.empty());
  const std::map<std::string, size_t> turning = {
      {"CATMAT 33:33 missing ',' before 'CANAL1'", 1},
      {"OPDATA 50:44 missing ',' before 'de'", 1},
      {"OPDATA 92:44 missing ',' before 'de'", 1},
      {"OP_NAME 47:13 missing ',' before 'RAYON'", 1},
      {"OP_NAME 89:13 missing ',' before 'RAYON'", 1},
      {"PART_OPE 18:16 missing ',' before 'd'usinage.1'", 1},
  };
  EXPECT_EQ(results["catia_toussaint/TURNING_PATH1_TRANSV.aptsource"].problems, turning);
}

}  // namespace
}  // namespace clpost

// clpost plot on whole files: the pictures hold one V per planned pass, a program's section shows
// its control's cuts, errors are clean, and the pictures in docs/img are what clpost draws now.
#include <gtest/gtest.h>

#include <filesystem>

#include "test_util.h"

namespace clpost::test {
namespace {

size_t count(const std::string& text, const std::string& what) {
  size_t n = 0;
  for (size_t at = text.find(what); at != std::string::npos; at = text.find(what, at + 1)) ++n;
  return n;
}

RunResult clpost(const std::string& args) {
  return run("cd " + quote(source_dir()) + " && " + quote(clpost_bin()) + " " + args);
}

TEST(Plot, AClFileDrawsTheBackplotAndEveryPlannedPass) {
  const std::string out = temp_dir() + "/options.svg";
  RunResult r = clpost("plot samples/threads/options.apt -o " + quote(out));
  ASSERT_EQ(r.exit_code, 0) << r.err;
  const std::string svg = read_file(out);
  // options.apt: 7 threads of 5, 6, 6, 4, 4, 10 and 4 passes.
  EXPECT_EQ(count(svg, "class=\"pass\""), 39u);
  EXPECT_EQ(count(svg, "Passes in cutting order"), 7u);
  EXPECT_EQ(count(svg, "<path class=\"thread\""), 39u);
  EXPECT_NE(svg.find("samples/threads/options.apt posted on generic-lathe"), std::string::npos);
}

TEST(Plot, AProgramsSectionShowsItsControlsCuts) {
  const std::string out = temp_dir() + "/g76.svg";
  RunResult r = clpost(
      "plot -m fanuc-0i-t samples/golden/fanuc-0i-t/threads-options.nc --cl "
      "samples/threads/options.apt --thread 2 -o " +
      quote(out));
  ASSERT_EQ(r.exit_code, 0) << r.err;
  const std::string svg = read_file(out);
  EXPECT_EQ(count(svg, "class=\"pass\""), 6u);
  // G76's fifth pass roughs to k - d = 0.92 - 0.081 = 0.839, where the plan has 0.8398 (6 cuts
  // of OPTION 1): the picture shows the control's depth.
  EXPECT_NE(svg.find(">0.839<"), std::string::npos);
  EXPECT_NE(svg.find("thread at options.apt:19 as threads-options.nc cuts it"), std::string::npos);
}

TEST(Plot, Errors) {
  RunResult r = clpost("plot samples/threads/options.apt --thread 9 -o /dev/null");
  EXPECT_EQ(r.exit_code, 1);
  EXPECT_EQ(r.err, "clpost: error: --thread 9: samples/threads/options.apt has 7 threads\n");
  r = clpost("plot -m fanuc-0i-t samples/golden/fanuc-0i-t/threads-options.nc --thread 1");
  EXPECT_EQ(r.exit_code, 1);
  EXPECT_EQ(r.err,
            "clpost: error: the sections of a program are measured against its plan: give --cl\n");
  const std::string dir = temp_dir();
  write_file(dir + "/p.nc", "G0 X10 Z5\nG1 X1.2.3\n");
  r = clpost("plot " + quote(dir + "/p.nc") + " -o " + quote(dir + "/p.svg"));
  EXPECT_EQ(r.exit_code, 1);
  EXPECT_EQ(r.err, dir + "/p.nc:2:4: error: invalid number 'X1.2.3'\n  G1 X1.2.3\n     ^\n");
  EXPECT_FALSE(file_exists(dir + "/p.svg"));
}

// The README shows docs/img: they must be what clpost draws (scripts/plot-samples.sh redraws).
TEST(Plot, DocsPicturesAreCurrent) {
  namespace fs = std::filesystem;
  const std::string dir = temp_dir();
  RunResult r = run("CLPOST_BIN=" + quote(clpost_bin()) + " " + quote(source_dir()) +
                    "/scripts/plot-samples.sh " + quote(dir));
  ASSERT_EQ(r.exit_code, 0) << r.err;
  size_t compared = 0;
  for (const auto& e : fs::directory_iterator(dir)) {
    const fs::path committed = fs::path(source_dir()) / "docs/img" / e.path().filename();
    EXPECT_TRUE(fs::exists(committed)) << committed << ": run scripts/plot-samples.sh";
    EXPECT_EQ(read_file(e.path().string()), read_file(committed.string()))
        << committed << " is stale: run scripts/plot-samples.sh and look at it";
    ++compared;
  }
  EXPECT_EQ(compared, 5u);
}

}  // namespace
}  // namespace clpost::test

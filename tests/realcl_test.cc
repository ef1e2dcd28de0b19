// Real CL files written by CAM systems (../shared/realcl, not part of this repository): every one
// is read to the end without a crash or hang; the lathe programs post cleanly; the milling ones
// fail with located diagnostics, never a silently empty program.
#include <gtest/gtest.h>

#include <filesystem>
#include <regex>

#include "test_util.h"

namespace clpost::test {
namespace {

namespace fs = std::filesystem;

std::vector<std::string> realcl_files() {
  std::vector<std::string> out;
  if (!fs::exists(realcl_dir())) return out;
  for (const auto& e : fs::recursive_directory_iterator(realcl_dir()))
    if (e.is_regular_file() && e.path().filename() != "README.md") out.push_back(e.path().string());
  std::sort(out.begin(), out.end());
  return out;
}

TEST(RealCl, EveryFileIsReadWithoutCrashAndDiagnosed) {
  std::vector<std::string> files = realcl_files();
  if (files.empty()) GTEST_SKIP() << "../shared/realcl not found: skipped";
  EXPECT_EQ(files.size(), 66u);
  std::regex located("^.+:[0-9]+(:[0-9]+)?: error: .+");
  for (const std::string& f : files) {
    RunResult r = run(quote(clpost_bin()) + " check " + quote(f));
    ASSERT_TRUE(r.exit_code == 0 || r.exit_code == 1) << f << " exit " << r.exit_code << "\n"
                                                      << r.err;
    if (r.exit_code == 1) {
      // The first error is located: file:line:col: error: ...
      std::string first_error;
      size_t p = r.err.find(": error: ");
      ASSERT_NE(p, std::string::npos) << f << "\n" << r.err;
      size_t start = r.err.rfind('\n', p);
      first_error =
          r.err.substr(start == std::string::npos ? 0 : start + 1,
                       r.err.find('\n', p) - (start == std::string::npos ? 0 : start + 1));
      EXPECT_TRUE(std::regex_match(first_error, located)) << first_error;
    }
  }
}

TEST(RealCl, LatheProgramsPostCleanly) {
  if (realcl_files().empty()) GTEST_SKIP() << "../shared/realcl not found: skipped";
  for (const char* name :
       {"nist_proe/V20_basic_turning_cycle.ncl", "nist_proe/V20_cl_data_unified-iso.ncl"}) {
    std::string f = realcl_dir() + "/" + name;
    RunResult r = run(quote(clpost_bin()) + " -m linuxcnc-lathe " + quote(f));
    EXPECT_EQ(r.exit_code, 0) << f << "\n" << r.err;
    EXPECT_EQ(r.err.find("error:"), std::string::npos) << r.err;
    EXPECT_NE(r.out.find("M2"), std::string::npos);
  }
}

}  // namespace
}  // namespace clpost::test

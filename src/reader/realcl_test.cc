// Every real CL file in ../shared/realcl (written by SolidWorks CAM, Siemens NX, Creo, Pro/E) must
// read without a single reader error.
#include <gtest/gtest.h>

#include <cstdio>
#include <filesystem>
#include <map>
#include <string>
#include <vector>

#include "reader/cl_reader.h"
#include "reader/cl_reader_test_util.h"

namespace clpost {
namespace {

namespace fs = std::filesystem;

const fs::path kRealCl = CLPOST_SOURCE_DIR "/../shared/realcl";

struct FileResult {
  size_t statements = 0;
  size_t errors = 0;
  std::string diags;
  std::vector<size_t> op_args;  // the number of arguments of each OP statement
};

FileResult read_file(const fs::path& path) {
  FileResult r;
  r.statements = reader_test::read_whole_file(
      path,
      [&r](const Statement& s) {
        if (s.major == "OP") r.op_args.push_back(s.args.size());
      },
      r.errors, r.diags);
  return r;
}

TEST(RealCl, AllFilesReadWithoutErrors) {
  if (!fs::is_directory(kRealCl)) GTEST_SKIP() << kRealCl << " not found";
  std::map<std::string, FileResult> results;
  for (const fs::directory_entry& e : fs::recursive_directory_iterator(kRealCl)) {
    if (!e.is_regular_file() || e.path().filename() == "README.md") continue;
    results[fs::relative(e.path(), kRealCl).string()] = read_file(e.path());
  }
  EXPECT_EQ(results.size(), 66u);
  for (const auto& [name, r] : results) {
    EXPECT_EQ(r.errors, 0u) << name << "\n" << r.diags;
    EXPECT_GT(r.statements, 0u) << name;
  }

  // Statement counts found independently of the reader. In these files every statement starts
  // in column 1 with a letter, and no continuation line or comment line does, so
  //   grep -c '^[A-Za-z]' FILE
  // counts the statements, less the NX listing lines in APT_Project2.txt: 4 header lines
  // (Information/Date/Current work part/Node name) and the trailer "Tool Path Listing has ...".
  EXPECT_EQ(results["nist_proe/V20_cl_data_unified-iso.ncl"].statements, 24u);
  EXPECT_EQ(results["creo_creopost/schruppen_1.ncl.1"].statements, 7067u);
  EXPECT_EQ(results["nx_clsf_mech491/APT_Project2.txt"].statements, 11279u - 5u);
  EXPECT_EQ(results["solidworks_cam/boss.apt"].statements, 12427u);

  // OP / THREAD , TURN, DEPTH, 0.061343, TPI, 10.000000, CUTS, 3, FINCUT, 3,$
  //  CUTANG, 180.000000
  // then OP / THREAD, NOMORE.
  EXPECT_EQ(results["nist_proe/V20_cl_data_unified-iso.ncl"].op_args, (std::vector<size_t>{12, 2}));

  const FileResult& nx = results["nx_clsf_mech491/APT_Project2.txt"];
  EXPECT_NE(nx.diags.find("APT_Project2.txt:2: note: skipped NX information listing header "
                          "(6 lines)\n"),
            std::string::npos)
      << nx.diags;
}

}  // namespace
}  // namespace clpost

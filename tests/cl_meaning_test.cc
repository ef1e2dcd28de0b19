// What the CL means (docs/cl-meaning.md) on every shipped machine, through the clpost binary:
// each program posts and passes --verify, or is refused with a located error.
#include <gtest/gtest.h>

#include <filesystem>

#include "test_util.h"

namespace clpost::test {
namespace {

namespace fs = std::filesystem;

constexpr const char* kHead = "UNITS/MM\nLOADTL/1\nSPINDL/500,RPM,CLW\nFEDRAT/0.2,MMPR\n";

// `cl` posted with --verify on machine `m` in `dir`: its result, the program in `nc`.
RunResult post_verify(const std::string& dir, const std::string& cl, const std::string& m,
                      std::string* nc = nullptr) {
  const std::string in = dir + "/t.cl", out = dir + "/t." + m + ".nc";
  write_file(in, cl);
  const RunResult r =
      run(quote(clpost_bin()) + " -m " + m + " --verify -o " + quote(out) + " " + quote(in));
  if (nc != nullptr) *nc = file_exists(out) ? read_file(out) : "";
  return r;
}

// Inch output with the control's least input increment reads back right: verify passes on every
// machine, for a program in inch from the start and one that switches.
TEST(ClMeaningMachines, InchProgramsVerifyOnEveryMachine) {
  const std::string dir = temp_dir();
  const std::string cls[] = {
      "UNITS/INCHES\nLOADTL/1\nSPINDL/500,RPM,CLW\nFEDRAT/0.008,IPR\nGOTO/1.23456,0,0.1\n"
      "GOTO/1.23456,0,-0.54321\nCIRCLE/0.1234,0,-0.54321,0,1,0,1.11116\nGOTO/0.1234,0,-1.65437\n"
      "GOTO/2,0,0.5\nFINI\n",
      std::string(kHead) + "GOTO/10,0,5\nUNITS/INCHES\nGOTO/1.23456,0,-0.54321\nFINI\n"};
  for (const std::string& cl : cls)
    for (const std::string& m : shipped_machine_names()) {
      const RunResult r = post_verify(dir, cl, m);
      EXPECT_EQ(r.exit_code, 0) << m << "\n" << cl << r.err;
    }
  fs::remove_all(dir);
}

}  // namespace
}  // namespace clpost::test

// The command line as a user meets it: exit codes, diagnostics, and files written or not.
#include <gtest/gtest.h>

#include <filesystem>

#include "test_util.h"

namespace clpost::test {
namespace {

namespace fs = std::filesystem;

std::string bin() {
  return quote(clpost_bin());
}

// Six good statements, then a bad number on line 7 (column 15).
constexpr const char* kBadLine7 =
    "PARTNO BAD\n"
    "UNITS/MM\n"
    "LOADTL/1\n"
    "SPINDL/1000,RPM,CLW\n"
    "FEDRAT/0.2,MMPR\n"
    "GOTO/10,0,2\n"
    "GOTO/10,0,-1.2.3\n"
    "FINI\n";

TEST(Cli, SyntaxErrorOnLine7ExitsOneAndWritesNothing) {
  std::string dir = temp_dir();
  write_file(dir + "/bad.cl", kBadLine7);
  RunResult r = run(bin() + " -o " + quote(dir + "/bad.nc") + " " + quote(dir + "/bad.cl"));
  EXPECT_EQ(r.exit_code, 1);
  // Column 11: G-O-T-O-/-1-0-,-0-, are columns 1..10, the number starts at 11.
  EXPECT_EQ(r.err, dir +
                       "/bad.cl:7:11: error: invalid number '-1.2.3'\n"
                       "  GOTO/10,0,-1.2.3\n"
                       "            ^\n");
  EXPECT_FALSE(file_exists(dir + "/bad.nc"));
  // Nothing else left behind either (no temporary files).
  EXPECT_EQ(std::distance(fs::directory_iterator(dir), fs::directory_iterator()), 1);
  fs::remove_all(dir);
}

// Every shipped machine writes a header, its body spooled beside the output file until the end:
// the spool has no name, so a good post leaves the program and nothing else (and a failed one
// nothing at all: SyntaxErrorOnLine7ExitsOneAndWritesNothing).
TEST(Cli, TheHeaderSpoolLeavesNoFileBehind) {
  std::string dir = temp_dir();
  write_file(dir + "/good.cl", "PARTNO GOOD\nUNITS/MM\nLOADTL/1\nRAPID\nGOTO/10,0,2\nFINI\n");
  RunResult r = run(bin() + " -o " + quote(dir + "/good.nc") + " " + quote(dir + "/good.cl"));
  EXPECT_EQ(r.exit_code, 0) << r.err;
  EXPECT_NE(read_file(dir + "/good.nc").find("(machine generic-lathe, program GOOD)\n"),
            std::string::npos);
  EXPECT_EQ(std::distance(fs::directory_iterator(dir), fs::directory_iterator()), 2);
  // The same program on standard output (its spool in the system's temporary directory).
  RunResult out = run(bin() + " " + quote(dir + "/good.cl"));
  EXPECT_EQ(out.out, read_file(dir + "/good.nc"));
  fs::remove_all(dir);
}

TEST(Cli, AFailedPostNeverReplacesAGoodProgram) {
  std::string dir = temp_dir();
  write_file(dir + "/bad.cl", kBadLine7);
  write_file(dir + "/part.nc", "good program\n");
  RunResult r = run(bin() + " -o " + quote(dir + "/part.nc") + " " + quote(dir + "/bad.cl"));
  EXPECT_EQ(r.exit_code, 1);
  EXPECT_EQ(read_file(dir + "/part.nc"), "good program\n");
  fs::remove_all(dir);
}

TEST(Cli, ErrorsGoToStderrAndNothingToStdout) {
  std::string dir = temp_dir();
  write_file(dir + "/bad.cl", kBadLine7);
  RunResult r = run(bin() + " " + quote(dir + "/bad.cl"));
  EXPECT_EQ(r.exit_code, 1);
  EXPECT_EQ(r.out, "");  // no partial program on standard output
  fs::remove_all(dir);
}

TEST(Cli, StdinAndStdout) {
  RunResult file = run(bin() + " " + quote(source_dir() + "/samples/pin-apt.apt"));
  RunResult piped = run(bin() + " -", source_dir() + "/samples/pin-apt.apt");
  EXPECT_EQ(file.exit_code, 0);
  EXPECT_EQ(piped.exit_code, 0) << piped.err;
  EXPECT_EQ(piped.out, file.out);
  EXPECT_EQ(piped.out, read_file(source_dir() + "/samples/golden/generic-lathe/pin-apt.nc"));
}

TEST(Cli, MachinesListsTheShippedOnes) {
  RunResult r = run(bin() + " machines");
  EXPECT_EQ(r.exit_code, 0);
  EXPECT_NE(r.out.find("generic-lathe      .nc   emulation                                Generic "
                       "2-axis ISO lathe"),
            std::string::npos)
      << r.out;
  EXPECT_NE(r.out.find("linuxcnc-lathe     .ngc  "), std::string::npos) << r.out;
}

TEST(Cli, VersionAndHelp) {
  RunResult v = run(bin() + " --version");
  EXPECT_EQ(v.exit_code, 0);
  EXPECT_EQ(v.out, "clpost 0.1.0\n");
  RunResult h = run(bin() + " --help");
  EXPECT_EQ(h.exit_code, 0);
  EXPECT_NE(h.out.find("clpost -m linuxcnc-lathe -o part.ngc part.cl"), std::string::npos);
  EXPECT_NE(h.out.find("Exit status: 0 ok, 1 errors in the input, 2 usage or machine-file errors."),
            std::string::npos);
}

TEST(Cli, UsageErrorsExitTwo) {
  EXPECT_EQ(run(bin() + " --no-such-option x.cl").exit_code, 2);
  RunResult none = run(bin());
  EXPECT_EQ(none.exit_code, 2);
  EXPECT_NE(none.err.find("clpost: error: no input file"), std::string::npos);
  RunResult m = run(bin() + " -m no-such-machine " + quote(source_dir() + "/samples/pin-apt.apt"));
  EXPECT_EQ(m.exit_code, 2);
  EXPECT_EQ(m.err.rfind("clpost: error: unknown machine 'no-such-machine'", 0), 0u) << m.err;
}

TEST(Cli, BrokenMachineFileExitsTwoWithItsLocation) {
  std::string dir = temp_dir();
  write_file(dir + "/m.yaml", "extends: iso-lathe\ndescription: test\nlimits: {max_rpm: fast}\n");
  fs::create_directories(dir + "/../posts");  // not there: the post is found in the data dirs
  RunResult r = run(bin() + " -m " + quote(dir + "/m.yaml") + " " +
                    quote(source_dir() + "/samples/pin-apt.apt"));
  EXPECT_EQ(r.exit_code, 2);
  EXPECT_EQ(r.err, dir +
                       "/m.yaml:3:19: error: 'limits.max_rpm' must be a number, not 'fast'\n"
                       "  limits: {max_rpm: fast}\n"
                       "                    ^\n");
  fs::remove_all(dir);
}

TEST(Cli, SetOverridesTheMachine) {
  RunResult r = run(bin() + " --set block_numbers.enabled=false " +
                    quote(source_dir() + "/samples/pin-apt.apt"));
  EXPECT_EQ(r.exit_code, 0) << r.err;
  EXPECT_EQ(r.out.rfind("%\nO0001\nG18 G21 G40 G90\n"
                        "(machine generic-lathe, program PIN-01 turned pin, 25 mm stock)\n"
                        "(T3 offset 3, first at CL line 5, 0:15.5)\n"
                        "(cycle time 0:15.5, 1 tool change)\n"
                        "(PIN-01 turned pin, 25 mm stock)\nT0303\n",
                        0),
            0u)
      << r.out;
  RunResult bad =
      run(bin() + " --set limits.max_rmp=1 " + quote(source_dir() + "/samples/pin-apt.apt"));
  EXPECT_EQ(bad.exit_code, 2);
  EXPECT_EQ(
      bad.err,
      "--set limits.max_rmp=1: error: unknown key 'limits.max_rmp' (did you mean 'max_rpm'?)\n");
}

TEST(Cli, UnknownStatementWarnsOrFailsWithStrict) {
  std::string dir = temp_dir();
  write_file(dir + "/u.cl", "UNITS/MM\nFEDRAT/0.1,MMPR\nFROB/1,2\nGOTO/1,0,1\nFINI\n");
  RunResult r = run(bin() + " " + quote(dir + "/u.cl"));
  EXPECT_EQ(r.exit_code, 0);
  EXPECT_EQ(r.err, dir +
                       "/u.cl:3:1: warning: unknown statement 'FROB' written as a comment\n"
                       "  FROB/1,2\n"
                       "  ^\n");
  EXPECT_NE(r.out.find("(FROB/1,2)"), std::string::npos);
  RunResult s = run(bin() + " --strict " + quote(dir + "/u.cl"));
  EXPECT_EQ(s.exit_code, 1);
  EXPECT_EQ(s.err, dir +
                       "/u.cl:3:1: error: unknown statement 'FROB' (--strict)\n"
                       "  FROB/1,2\n"
                       "  ^\n");
  fs::remove_all(dir);
}

TEST(Cli, CheckValidatesWithoutWriting) {
  std::string dir = temp_dir();
  write_file(dir + "/bad.cl", kBadLine7);
  RunResult ok = run("cd " + quote(dir) + " && " + bin() + " check " +
                     quote(source_dir() + "/samples/shaft-nx.cls"));
  EXPECT_EQ(ok.exit_code, 0);
  EXPECT_EQ(ok.out, "");
  RunResult bad = run(bin() + " check " + quote(dir + "/bad.cl") + " " +
                      quote(source_dir() + "/samples/pin-apt.apt"));
  EXPECT_EQ(bad.exit_code, 1);
  EXPECT_NE(bad.err.find(dir + "/bad.cl: failed (1 errors, 0 warnings"), std::string::npos)
      << bad.err;
  EXPECT_NE(bad.err.find("samples/pin-apt.apt: ok (0 errors, 0 warnings"), std::string::npos)
      << bad.err;
  EXPECT_EQ(std::distance(fs::directory_iterator(dir), fs::directory_iterator()), 1);
  fs::remove_all(dir);
}

TEST(Cli, MissingFiniIsAWarningAndTheProgramIsClosed) {
  std::string dir = temp_dir();
  write_file(dir + "/nofini.cl", "UNITS/MM\nRAPID\nGOTO/10,0,2\n");
  RunResult r = run(bin() + " --set block_numbers.enabled=false " + quote(dir + "/nofini.cl"));
  EXPECT_EQ(r.exit_code, 0);
  EXPECT_EQ(r.err,
            dir + "/nofini.cl:3: warning: the file ends without FINI: the program end was added\n");
  EXPECT_EQ(r.out,
            "%\nO0001\nG18 G21 G40 G90\n(machine generic-lathe, program nofini)\n"
            "(cycle time 0:00.0, 0 tool changes)\nG0 X20. Z2.\nM30\n%\n");
  fs::remove_all(dir);
}

}  // namespace
}  // namespace clpost::test

// What the CL means (docs/cl-meaning.md) on every shipped machine, through the clpost binary:
// each program posts and passes --verify, or is refused with a located error; and verify, run
// with block delete off and on, finds a program that is right only with it off.
#include <gtest/gtest.h>
#include <algorithm>

#include <cstdlib>
#include <filesystem>
#include <regex>
#include <sstream>

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
// machine, for a program in inch from the start and one that switches; a machine in mm whose
// control reads a program in one unit (HEIDENHAIN DIN) refuses UNITS/INCHES at its line.
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
      const Machine machine = shipped_machine(m);
      if (machine.control && machine.control->one_unit_per_program) {
        EXPECT_EQ(r.exit_code, 1) << m << "\n" << cl << r.err;
        EXPECT_NE(
            r.err.find(":7: error: machine '" + m + "' (" + std::string(machine.control->name) +
                       ") reads the whole program in mm"),
            std::string::npos)
            << r.err;
        continue;
      }
      EXPECT_EQ(r.exit_code, 0) << m << "\n" << cl << r.err;
    }
  fs::remove_all(dir);
}

// The first arc block (G2/G3/G02/G03) of `nc` whose I and K are both zero (a full circle on the
// control), or "".
std::string arc_without_radius(const std::string& nc) {
  static const std::regex arc(R"((^|\s)G0?[23](\s|$))");
  static const std::regex i_word(R"(\bI=?(-?[0-9]*\.?[0-9]*))"),
      k_word(R"(\bK=?(-?[0-9]*\.?[0-9]*))");
  std::istringstream in(nc);
  for (std::string line; std::getline(in, line);) {
    if (!std::regex_search(line, arc)) continue;
    std::smatch i, k;
    if (std::regex_search(line, i, i_word) && std::regex_search(line, k, k_word) &&
        std::atof(i[1].str().c_str()) == 0 && std::atof(k[1].str().c_str()) == 0)
      return line;
  }
  return "";
}

// An arc that the output's resolution rounds to nothing (I0. K0.) is a straight move on every
// machine, which verify accepts; so is an arc whose end rounds onto its start (nothing written).
TEST(ClMeaningMachines, ArcsRoundedToNothingAreNoCircleOnEveryMachine) {
  const std::string dir = temp_dir();
  const std::string cls[] = {
      std::string(kHead) +
          "GOTO/10,0,0\nCIRCLE/10.0004,0,0,0,1,0,0.0004\nGOTO/10.0008,0,0\nGOTO/10,0,-5\nFINI\n",
      std::string(kHead) +
          "GOTO/10,0,0\nCIRCLE/10.000003,0,0,0,1,0,0.000003\nGOTO/10.000006,0,0\n"
          "GOTO/10,0,-5\nFINI\n",
      std::string(kHead) +
          "GOTO/10,0,0\nCIRCLE/10,0,-5,0,1,0,5\nGOTO/10.0000001,0,0\n"
          "GOTO/10,0,-5\nFINI\n"};
  for (const std::string& cl : cls)
    for (const std::string& m : shipped_machine_names()) {
      std::string nc;
      const RunResult r = post_verify(dir, cl, m, &nc);
      EXPECT_EQ(r.exit_code, 0) << m << "\n" << r.err;
      EXPECT_EQ(arc_without_radius(nc), "") << m << "\n" << nc;
    }
  fs::remove_all(dir);
}

// A feed per revolution with the spindle stopped is refused at its CL line on every machine.
TEST(ClMeaningMachines, AFeedPerRevolutionWithTheSpindleStoppedIsRefused) {
  const std::string dir = temp_dir();
  const std::string cl = std::string(kHead) + "GOTO/20,0,5\nSPINDL/OFF\nGOTO/10,0,-5\nFINI\n";
  for (const std::string& m : shipped_machine_names()) {
    const RunResult r = post_verify(dir, cl, m);
    EXPECT_EQ(r.exit_code, 1) << m;
    EXPECT_NE(r.err.find("t.cl:7:1: error: feed move per revolution with the spindle stopped "
                         "(SPINDL/OFF at line 6)"),
              std::string::npos)
        << m << "\n"
        << r.err;
  }
  fs::remove_all(dir);
}

// OPSKIP ranges (spindle, coolant, moves and an arc inside) verify on every machine with block
// delete off and on.
TEST(ClMeaningMachines, OpskipProgramsVerifyWithBlockDeleteOffAndOn) {
  const std::string dir = temp_dir();
  const std::string cl = std::string(kHead) +
                         "GOTO/20,0,5\nOPSKIP/ON\nSPINDL/800,RPM,CLW\nCOOLNT/FLOOD\nGOTO/10,0,-5\n"
                         "CIRCLE/10,0,-10,0,1,0,5\nGOTO/5,0,-10\nOPSKIP/OFF\nGOTO/10,0,-12\n"
                         "OPSKIP/ON\nGOTO/12,0,-14\nOPSKIP/OFF\nRAPID\nGOTO/30,0,5\nFINI\n";
  for (const std::string& m : shipped_machine_names()) {
    const RunResult r = post_verify(dir, cl, m);
    EXPECT_EQ(r.exit_code, 0) << m << "\n" << r.err;
  }
  fs::remove_all(dir);
}

// A program with an optional block where its CL has no OPSKIP range: the CL says to do every
// block either way, so verify refuses it, at that block, whether the program streams to
// --verify behind its header, without one, or is read whole by `clpost verify --cl`. (clpost
// writes '/' only for OPSKIP; here a program_end template asks for one.)
TEST(ClMeaningMachines, VerifyRefusesAnOptionalBlockTheClDoesNotHave) {
  const std::string dir = temp_dir();
  const std::string cl = std::string(kHead) + "GOTO/20,0,5\nGOTO/10,0,-5\nFINI\n";
  write_file(dir + "/t.cl", cl);
  const std::string sets =
      " --set block_numbers.enabled=false --set 'templates.program_end=[\"/M1\",\"M30\",\"%\"]'";
  for (const std::string header : {"", " --set 'templates.program_header=[]'"}) {
    const std::string nc = dir + "/t.nc";
    const std::string post = quote(clpost_bin()) + " -m fanuc-0i-t" + sets + header;
    const RunResult v = run(post + " --verify -o " + quote(nc) + " " + quote(dir + "/t.cl"));
    EXPECT_EQ(v.exit_code, 1) << header;
    EXPECT_FALSE(file_exists(nc)) << header;
    ASSERT_EQ(run(post + " -o " + quote(nc) + " " + quote(dir + "/t.cl")).exit_code, 0);
    const std::string program = read_file(nc);
    const size_t at = program.find("/M1\n");
    ASSERT_NE(at, std::string::npos) << program;
    const std::string line =
        std::to_string(1 + std::count(program.begin(), program.begin() + at, '\n'));
    const std::string error = nc + ":" + line +
                              ":1: error: an optional block ('/'), where the CL has no OPSKIP "
                              "range\n  /M1\n  ^\n";
    EXPECT_NE(v.err.find(error), std::string::npos) << header << "\n" << v.err;
    const RunResult w = run(quote(clpost_bin()) + " verify -m fanuc-0i-t" + sets + header + " " +
                            quote(nc) + " --cl " + quote(dir + "/t.cl"));
    EXPECT_EQ(w.exit_code, 1) << header;
    EXPECT_EQ(w.err, error) << header;
    fs::remove(nc);
  }
  fs::remove_all(dir);
}

// verify runs a program with optional blocks with block delete off and on. The program of case E
// as it was before its fix (the block after the range did not state X again) is right with block
// delete off, and wrong with it on: N60 cuts to X40. Z-10., not the CL's X20. Z-10. The error is
// at that NC line, marked.
TEST(ClMeaningMachines, VerifyFindsWhatIsWrongOnlyWithBlockDeleteOn) {
  const std::string dir = temp_dir();
  const std::string cl = std::string(kHead) +
                         "GOTO/20,0,5\nOPSKIP/ON\nGOTO/10,0,-5\nOPSKIP/OFF\nGOTO/10,0,-10\nFINI\n";
  std::string nc;
  ASSERT_EQ(post_verify(dir, cl, "fanuc-0i-t", &nc).exit_code, 0);
  const std::string right = "N60 G1 X20. Z-10. G99 F0.2\n";
  const size_t at = nc.find(right);
  ASSERT_NE(at, std::string::npos) << nc;
  nc.replace(at, right.size(), "N60 Z-10.\n");
  // The NC line of N60 (the program's header comes before it).
  const std::string n60 = std::to_string(1 + std::count(nc.begin(), nc.begin() + at, '\n'));
  write_file(dir + "/edited.nc", nc);
  const RunResult r = run(quote(clpost_bin()) + " verify -m fanuc-0i-t " +
                          quote(dir + "/edited.nc") + " --cl " + quote(dir + "/t.cl"));
  EXPECT_EQ(r.exit_code, 1);
  EXPECT_EQ(r.err, dir + "/edited.nc:" + n60 + ":1: error: motion at " + dir +
                       "/t.cl:9: X20.0000 Z-10.0000 is not reached by the program in order "
                       "(block delete on)\n");
  EXPECT_NE(r.out.find("block delete on: 1 difference"), std::string::npos) << r.out;
  fs::remove_all(dir);
}

}  // namespace
}  // namespace clpost::test

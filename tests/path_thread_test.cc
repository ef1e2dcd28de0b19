// Single-pass (THREAD/TURN…) and coupled (COUPLE/ON…OFF) threads through the whole program:
// each of these once wrote a wrong program and exited 0. Exact diagnostics, exit codes, and no
// output file where there is an error.
#include <gtest/gtest.h>

#include <filesystem>

#include "test_util.h"

namespace clpost::test {
namespace {

namespace fs = std::filesystem;

struct Posted {
  RunResult run;
  bool wrote = false;
  std::string program;
};

// Posts `cl` (written to t.cl in a fresh directory) with `args` to t.nc, then cleans up.
Posted post(const std::string& cl, const std::string& args = "") {
  const std::string dir = temp_dir();
  write_file(dir + "/t.cl", cl);
  Posted p;
  p.run = run("cd " + quote(dir) + " && " + quote(clpost_bin()) + " " + args + " -o t.nc t.cl");
  p.wrote = file_exists(dir + "/t.nc");
  if (p.wrote) p.program = read_file(dir + "/t.nc");
  fs::remove_all(dir);
  return p;
}

TEST(PathThread, SingleThreadWithoutLengthIsAnError) {
  // Was: `G33 F1.5`, a thread block with no axis word, exit 0.
  Posted p = post(
      "UNITS/MM\nSPINDL/800,RPM,CLW\nRAPID\nGOTO/12,0,5\nTHREAD/TURN,MMPR,1.5\nRAPID\nGOTO/10,0,2\n"
      "GOTO/10,0,2\nRAPID\nGOTO/15,0,5\nFINI\n");
  EXPECT_EQ(p.run.exit_code, 1);
  EXPECT_FALSE(p.wrote);
  EXPECT_EQ(p.run.err,
            "t.cl:8:1: error: the thread end (X 10, Z 2) is the thread start: the thread has no "
            "length\n"
            "  GOTO/10,0,2\n"
            "  ^\n"
            "t.cl:5:1: note: the thread starts here\n"
            "  THREAD/TURN,MMPR,1.5\n"
            "  ^\n");
}

TEST(PathThread, RepeatedGotoInsideCoupleWritesNoMotionlessBlock) {
  // Was: `N50 F3.` between the two synchronized moves, exit 0.
  Posted p = post(
      "UNITS/MM\nSPINDL/800,RPM,CLW\nRAPID\nGOTO/10,0,2\nCOUPLE/ON,MMPR,3\nGOTO/10,0,-20\n"
      "GOTO/10,0,-20\nGOTO/11.5,0,-21.5\nCOUPLE/OFF\nRAPID\nGOTO/15,0,5\nFINI\n");
  EXPECT_EQ(p.run.exit_code, 0);
  EXPECT_EQ(p.run.err,
            "t.cl:7:1: warning: this GOTO (X 10, Z -20) does not move the tool: no synchronized "
            "move\n"
            "  GOTO/10,0,-20\n"
            "  ^\n");
  EXPECT_EQ(p.program,
            "%\nO0001\nN10 G18 G21 G40 G90\n(machine generic-lathe, program t)\n"
            "(cycle time 0:00.7, 0 tool changes)\nN20 G97 S800 M3\nN30 G0 X20. Z2.\n"
            "N40 G33 Z-20. F3.\nN50 X23. Z-21.5 F3.\nN60 G0 X30. Z5.\nN70 M30\n%\n");
}

// A single-pass thread and a COUPLE that begins where it ends, with no move between: the program
// writes consecutive G33 blocks, which the control cuts as one continuous thread; verify splits
// that cut where the couple begins and finds each thread cut as planned. Found by the round-trip
// fuzzer (it reported the couple as not cut).
TEST(PathThread, ACoupleRightAfterASinglePassThreadVerifies) {
  Posted p = post(
      "UNITS/MM\nSPINDL/600,RPM,CLW\nRAPID\nGOTO/12,0,5\nPITCH/1.5,MMPR\nTHREAD/TURN\n"
      "RAPID\nGOTO/9.2,0,2\nGOTO/9.2,0,-20\nCOUPLE/ON\nGOTO/9.1,0,-20\nGOTO/10.6,0,-21.5\nCOUPLE/"
      "OFF\n"
      "RAPID\nGOTO/15,0,5\nFINI\n",
      "--verify");
  EXPECT_EQ(p.run.exit_code, 0) << p.run.err;
  EXPECT_NE(p.program.find("N50 G33 Z-20. F1.5\nN60 X18.2 F1.5\nN70 X21.2 Z-21.5 F1.5\n"),
            std::string::npos)
      << p.program;
  // NC line 9: after the program start's three lines and the header's two.
  EXPECT_NE(p.run.err.find("  t.cl:6       1 passes  ok     G33, NC line 9\n"
                           "  t.cl:10      1 passes  ok     G33, NC line 9\n"),
            std::string::npos)
      << p.run.err;
}

TEST(PathThread, FaceCoupleIsHeldToTheXFeedLimit) {
  // A face thread from radius 20 to 5 at Z1, lead 2 at 1000 rpm: X moves 2 x 1000 = 2000 per
  // minute. Was: checked as a turn thread (X moving nothing), exit 0; THREAD/FACE was refused.
  const std::string cl =
      "UNITS/MM\nSPINDL/1000,RPM,CLW\nRAPID\nGOTO/20,0,1\nCOUPLE/ON,MMPR,2\nGOTO/5,0,1\n"
      "GOTO/4,0,0\nCOUPLE/OFF\nRAPID\nGOTO/25,0,5\nFINI\n";
  Posted bad = post(cl, "--set limits.max_feed_x=1500");
  EXPECT_EQ(bad.run.exit_code, 1);
  EXPECT_FALSE(bad.wrote);
  EXPECT_EQ(bad.run.err,
            "t.cl:6:1: error: thread feed too fast for machine 'generic-lathe': the X axis moves "
            "2000 per minute (lead 2 x 1000 rpm), above its limit 1500 (limits.max_feed_x)\n"
            "  GOTO/5,0,1\n"
            "  ^\n");
  // The pull-out (1 along X and Z: X's share is the whole lead) is within 2000.
  Posted ok = post(cl, "--set limits.max_feed_x=2000");
  EXPECT_EQ(ok.run.exit_code, 0) << ok.run.err;
  EXPECT_TRUE(ok.wrote);
  // And the same face as a single-pass thread is held to the same limit.
  Posted single = post(
      "UNITS/MM\nSPINDL/1000,RPM,CLW\nRAPID\nGOTO/20,0,1\nTHREAD/FACE,MMPR,2\nRAPID\nGOTO/20,0,1\n"
      "GOTO/5,0,1\nRAPID\nGOTO/25,0,5\nFINI\n",
      "--set limits.max_feed_x=1500");
  EXPECT_EQ(single.run.exit_code, 1);
  EXPECT_EQ(single.run.err,
            "t.cl:5:1: error: thread feed too fast for machine 'generic-lathe': the X axis moves "
            "2000 per minute (lead 2 x 1000 rpm), above its limit 1500 (limits.max_feed_x)\n"
            "  THREAD/FACE,MMPR,2\n"
            "  ^\n");
}

TEST(PathThread, PlanOfACoupleEndsWhereItsPathEnds) {
  // Was: "ends at (X 0, Z 0)" for every COUPLE thread.
  const std::string dir = temp_dir();
  write_file(dir + "/t.cl",
             "UNITS/MM\nSPINDL/800,RPM,CLW\nRAPID\nGOTO/10,0,2\nCOUPLE/ON,MMPR,3\n"
             "GOTO/10,0,-20\nGOTO/11.5,0,-21.5\nCOUPLE/OFF\nFINI\n");
  RunResult r = run("cd " + quote(dir) + " && " + quote(clpost_bin()) + " plan t.cl");
  fs::remove_all(dir);
  EXPECT_EQ(r.exit_code, 0) << r.err;
  EXPECT_NE(r.out.find("  ends at (X 11.5, Z -21.5)\n"), std::string::npos) << r.out;
  EXPECT_EQ(r.out.find("(X 0, Z 0)"), std::string::npos) << r.out;
}

}  // namespace
}  // namespace clpost::test

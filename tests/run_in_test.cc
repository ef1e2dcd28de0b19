// Run-in and run-out (docs/threading.md section 15) through the whole program: what the plan
// says, the warning when no length of a thread has the right lead, and threading.run_in `auto`
// in the cycles' words. The numbers are Fanuc's law, worked out by hand in each test.
#include <gtest/gtest.h>

#include <filesystem>

#include "test_util.h"

namespace clpost::test {
namespace {

namespace fs = std::filesystem;

// An M20x2 (lead 2) external thread from Z 2 to Z -30 at 1500 rpm, 4 cuts of `option`.
std::string thread_cl(int option) {
  return "UNITS/MM\nPITCH/2,MMPR\nSPINDL/RPM,1500,CLW\nRAPID\nGOTO/12,0,5\n"
         "THREAD/ON,DEPTH,1.2,CUTS,4,OPTION," +
         std::to_string(option) + "\nGOTO/10,0,2\nGOTO/10,0,-30\nTHREAD/OFF\nFINI\n";
}

// Runs clpost `args` on `cl` (written to t.cl in a fresh directory).
RunResult clpost(const std::string& cl, const std::string& args) {
  const std::string dir = temp_dir();
  write_file(dir + "/t.cl", cl);
  RunResult r = run("cd " + quote(dir) + " && " + quote(clpost_bin()) + " " + args + " t.cl");
  fs::remove_all(dir);
  return r;
}

bool has(const std::string& text, const std::string& part) {
  return text.find(part) != std::string::npos;
}

// V = 1500 x 2 / 60 = 50 mm/s; δ2 = T1·V = 0.033 x 50 = 1.65; δ1 = T1·V·(a − 1 − ln a) =
// 1.65 x (0.01 − 1 + 4.605170) = 1.65 x 3.615170 = 5.965031 (5.97). OPTION 0 has no flank
// shift: every pass runs Z 2 to -30, so the lead is right from 2 - 5.965031 = -3.965031 to
// -30 + 1.65 = -28.35.
TEST(RunIn, ThePlanGivesRunInAndRunOut) {
  RunResult json = clpost(thread_cl(0), "plan --format json");
  ASSERT_EQ(json.exit_code, 0) << json.err;
  EXPECT_TRUE(
      has(json.out,
          "      \"rpm\": 1500,\n"
          "      \"run_in\": 5.965031,\n"
          "      \"run_out\": 1.65,\n"
          "      \"run_in_added\": false,\n"
          "      \"lead_right\": {\"axis\": \"z\", \"from\": -3.965031, \"to\": -28.35},\n"))
      << json.out;
  RunResult text = clpost(thread_cl(0), "plan");
  ASSERT_EQ(text.exit_code, 0) << text.err;
  EXPECT_TRUE(has(text.out,
                  "  run-in 5.965031, run-out 1.65 at 1500 rpm; lead right from Z -3.965031 to "
                  "Z -28.35\n"))
      << text.out;
  EXPECT_EQ(json.err, "");  // 32 mm is long enough: no warning
}

// T1 0.066: both double, 11.930062 and 3.3; right from 2 - 11.930062 = -9.930062 to -26.7.
TEST(RunIn, DoublingTheTimeConstantDoublesBoth) {
  RunResult r = clpost(thread_cl(0), "plan --set threading.servo_time_constant=0.066");
  ASSERT_EQ(r.exit_code, 0) << r.err;
  EXPECT_TRUE(has(r.out,
                  "  run-in 11.930062, run-out 3.3 at 1500 rpm; lead right from Z -9.930062 to "
                  "Z -26.7\n"))
      << r.out;
}

// A 5 mm single-pass thread at 2000 rpm and a 3 mm lead: V = 100 mm/s, δ2 = 3.3, δ1 = 3.3 x
// 3.615170 = 11.930062; together 15.230062 > 5. Below 5 / (0.033 x 3 / 60 x 4.615170) = 656.6
// rpm they leave some of it: 656 rpm.
TEST(RunIn, WarnsAtTheThreadWhenNoLengthHasTheRightLead) {
  const std::string cl =
      "UNITS/MM\nSPINDL/RPM,2000,CLW\nRAPID\nGOTO/12,0,5\nTHREAD/TURN,MMPR,3\nRAPID\n"
      "GOTO/10,0,2\nGOTO/10,0,-3\nRAPID\nGOTO/12,0,5\nFINI\n";
  RunResult r = clpost(cl, "-o t.nc");
  EXPECT_EQ(r.exit_code, 0);
  EXPECT_EQ(r.err,
            "t.cl:5:1: warning: run-in 11.930062 and run-out 3.3 at 2000 rpm, lead 3, cover the "
            "whole synchronized cut (5 long): no length of this thread has the right lead; 656 "
            "rpm or less leaves one\n"
            "  THREAD/TURN,MMPR,3\n"
            "  ^\n");
  // At 600 rpm: δ1 3.579018, δ2 0.99, 4.569018 < 5: no warning.
  std::string slow = cl;
  slow.replace(slow.find("2000"), 4, "600");
  EXPECT_EQ(clpost(slow, "-o t.nc").err, "");
}

// OPTION 3 (flank infeed, IANG 30) on sinumerik-840d. With `auto` the CL's start Z 2 stays SPL
// and the cut begins APP = δ1 = 5.965031 (5.965 at cycle99_depth's 4 decimals) before it; by
// default APP is 0 as before. VRT = 2 sqrt(3) / 2 = 1.7321, the default return height.
TEST(RunIn, AutoWritesTheRunInAsCycle99App) {
  RunResult r = clpost(thread_cl(3), "-m sinumerik-840d --set threading.run_in=auto --verify -o -");
  ASSERT_EQ(r.exit_code, 0) << r.err;
  EXPECT_TRUE(has(r.out,
                  "CYCLE99(2, 20, -30, 20, 5.965, 0, 1.2, 0, 30, 0, 4, 0, 2, 300101, 0, 1.7321, "
                  "0, 0, 0, 0, 0, 0, 1, \"\", \"\", \"\", 0)\n"))
      << r.out;
  RunResult d = clpost(thread_cl(3), "-m sinumerik-840d -o -");
  EXPECT_TRUE(has(d.out,
                  "CYCLE99(2, 20, -30, 20, 0, 0, 1.2, 0, 30, 0, 4, 0, 2, 300101, 0, 1.7321, 0, 0, "
                  "0, 0, 0, 0, 1, \"\", \"\", \"\", 0)\n"))
      << d.out;
}

// G31 on heidenhain-pilot: `auto` keeps the contour's start at the CL's Z 2 with B = δ1 5.965
// before it, and ends the contour δ2 = 1.65 before Z -30 (Z -28.35) with the run-out P1.65 after
// it: the control cuts the same passes, which verify checks.
TEST(RunIn, AutoWritesRunInAndRunOutAsG31BAndP) {
  RunResult r =
      clpost(thread_cl(3), "-m heidenhain-pilot --set threading.run_in=auto --verify -o -");
  ASSERT_EQ(r.exit_code, 0) << r.err;
  EXPECT_TRUE(has(r.out,
                  "G31 F2. U1.2 IC4 V1 H1 A30. D1 Q0 C0. BD0 B5.965 P1.65 K0.\n"
                  "N 60 G0 X20. Z2.\n"
                  "N 70 G1 X20. Z-28.35\n"
                  "N 80 G80\n"))
      << r.out;
}

// A number is a run-in taken from the start of the CL's thread: the contour starts B = 2 after
// Z 2, at Z 0, so the cut still starts at Z 2 (before, G31 fell back to its G33 loop).
TEST(RunIn, ANumberIsTakenFromTheCLsThreadOnG31) {
  RunResult r = clpost(thread_cl(3), "-m heidenhain-pilot --set threading.run_in=2 --verify -o -");
  ASSERT_EQ(r.exit_code, 0) << r.err;
  EXPECT_TRUE(has(r.out,
                  "G31 F2. U1.2 IC4 V1 H1 A30. D1 Q0 C0. BD0 B2. P0. K0.\n"
                  "N 60 G0 X20. Z0.\n"
                  "N 70 G1 X20. Z-30.\n"))
      << r.out;
}

// Without a cycle word (generic-lathe's emulation) `auto` starts every pass δ1 before the CL's
// start: pass 1 (OPTION 0, depth 1.2 x 1 x 8 / 20 = 0.48) cuts from Z 2 + 5.965031 = 7.965031.
TEST(RunIn, AutoStartsEveryPassBeforeTheThreadOnEveryMachine) {
  RunResult plan = clpost(thread_cl(0), "plan --set threading.run_in=auto");
  ASSERT_EQ(plan.exit_code, 0) << plan.err;
  EXPECT_TRUE(has(plan.out, "(X 9.52, Z 7.965031) -> (X 9.52, Z -30)")) << plan.out;
  EXPECT_TRUE(has(plan.out,
                  "  run-in 5.965031 (before the thread start), run-out 1.65 at 1500 rpm; lead "
                  "right from Z 2 to Z -28.35\n"))
      << plan.out;
  RunResult nc = clpost(thread_cl(0), "--set threading.run_in=auto --verify -o -");
  ASSERT_EQ(nc.exit_code, 0) << nc.err;
  EXPECT_TRUE(has(nc.out, "Z7.965")) << nc.out;
}

// LinuxCNC's G76 has no run-in word: with `auto` the drive line starts where the cuts do, Z 2 +
// 5.965031 = 7.96503 (its start Z), and LinuxCNC's own interpreter cuts pass 1 (OPTION 3, depth
// 0.3, shifted 0.3 tan 30 = 0.173205 in the cutting direction) from Z 7.965031 - 0.173205 =
// 7.791826 to -30 - 1.2 tan 30 + 0.173205 = -29.480385, at radius 10 - 0.3 = 9.7.
TEST(RunIn, AutoOnLinuxcncG76AsRs274CutsIt) {
  if (!rs274_available()) GTEST_SKIP() << "rs274 not installed (linuxcnc-uspace): skipped";
  const std::string dir = temp_dir();
  write_file(dir + "/t.cl", thread_cl(3));
  RunResult post = run("cd " + quote(dir) + " && " + quote(clpost_bin()) +
                       " -m linuxcnc-lathe --set threading.run_in=auto --verify -o t.ngc t.cl");
  ASSERT_EQ(post.exit_code, 0) << post.err;
  const std::string nc = read_file(dir + "/t.ngc");
  EXPECT_TRUE(has(nc, "X23.4641 Z7.96503\n")) << nc;
  EXPECT_TRUE(has(nc, "G76 P2. Z-30. I-3.4641 J0.6 K2.4 R1 Q30. H0\n")) << nc;
  RunResult r = run_rs274(dir, "t.ngc");
  ASSERT_EQ(r.exit_code, 0) << r.err;
  const std::vector<CanonSegment> cuts = rs274_synced_moves(r.out);
  ASSERT_EQ(cuts.size(), 4u) << r.out;
  EXPECT_NEAR(cuts[0].from.z, 7.791826, 0.001);
  EXPECT_NEAR(cuts[0].to.z, -29.480385, 0.001);
  EXPECT_NEAR(cuts[0].from.x, 9.7, 0.001);
  fs::remove_all(dir);
}

TEST(RunIn, RunInIsANumberOrAuto) {
  RunResult r = clpost(thread_cl(0), "--set threading.run_in=atuo -o -");
  EXPECT_EQ(r.exit_code, 2);
  EXPECT_TRUE(has(r.err,
                  "'threading.run_in' must be a number or auto, not 'atuo' (did you mean "
                  "'auto'?)"))
      << r.err;
}

}  // namespace
}  // namespace clpost::test

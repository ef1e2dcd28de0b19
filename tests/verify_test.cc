// clpost verify and --verify on whole programs: a reviewed golden with one depth word edited or
// one pass dropped must fail, naming the thread, the pass and the numbers; posting with --verify
// writes nothing when the program does not cut the plan. (Every golden verifying as written:
// golden_test.cc; every machine on generated cases: conformance_test.cc.)
#include <gtest/gtest.h>

#include "interpreter/post.h"
#include "machine/machine_schema.h"
#include "reader/line_source.h"
#include "test_util.h"
#include "verify/program_verify.h"

namespace clpost::test {
namespace {

const std::string kOptions = "samples/threads/options.apt";

// The golden of `machine` for the options sample with `from` replaced by `to` (once), verified.
RunResult verify_edited(const std::string& machine, const std::string& golden,
                        const std::string& from, const std::string& to, std::string& path) {
  std::string text = read_file(source_dir() + "/samples/golden/" + machine + "/" + golden);
  const size_t at = text.find(from);
  EXPECT_NE(at, std::string::npos) << from << " not in " << golden;
  if (at != std::string::npos) text.replace(at, from.size(), to);
  path = temp_dir() + "/" + golden;
  write_file(path, text);
  return run("cd " + quote(source_dir()) + " && " + quote(clpost_bin()) + " verify -m " + machine +
             " " + quote(path) + " --cl " + kOptions);
}

// The first diagnostic's first line.
std::string first_error(const RunResult& r) {
  return r.err.substr(0, r.err.find('\n'));
}

TEST(Verify, FanucG76HeightWordEdited) {
  std::string p;
  RunResult r = verify_edited("fanuc-0i-t", "threads-options.nc", "P920 Q376", "P900 Q376", p);
  EXPECT_EQ(r.exit_code, 1);
  // Height 0.900 instead of 0.920: the first pass sits 0.02 higher, at X15.208 (radius 7.604)
  // where the plan cuts 0.3756 deep (radius 7.6244).
  EXPECT_EQ(first_error(r), p + ":25:1: error: thread at " + kOptions +
                                ":19: pass 1: depth 0.3960, plan 0.3756 (tolerance 0.005)");
  EXPECT_NE(r.out.find("\nFAILED: 6 differences beyond 0.005 mm\n"), std::string::npos) << r.out;
}

TEST(Verify, FanucG92PassDropped) {
  std::string p;
  RunResult r = verify_edited("fanuc-0i-t", "threads-options.nc", "N110 X14.896\n", "", p);
  EXPECT_EQ(r.exit_code, 1);
  EXPECT_EQ(first_error(r), p + ":15:1: error: thread at " + kOptions +
                                ":12: pass 2 (depth 0.5520, from X14.8960 Z2.0000) is not cut by "
                                "the program");
  EXPECT_NE(r.out.find("39 passes planned, 38 cut\n"), std::string::npos) << r.out;
  EXPECT_NE(r.out.find("\nFAILED: 1 difference beyond 0.005 mm\n"), std::string::npos) << r.out;
}

TEST(Verify, Cycle99DepthArgumentEdited) {
  std::string p;
  RunResult r = verify_edited("sinumerik-840d", "threads-options.mpf",
                              "CYCLE99(2, 16, -20, 16, 0, 0, 0.92, 0, 30, 0, 6,",
                              "CYCLE99(2, 16, -20, 16, 0, 0, 0.9, 0, 30, 0, 6,", p);
  EXPECT_EQ(r.exit_code, 1);
  // Constant cross-section: pass 1 at TDEP root(1/6) = 0.9 x 0.40825 = 0.3674.
  EXPECT_EQ(first_error(r), p + ":41:1: error: thread at " + kOptions +
                                ":19: pass 1: depth 0.3674, plan 0.3756 (tolerance 0.001)");
}

TEST(Verify, LinuxcncG76DepthWordEdited) {
  std::string p;
  RunResult r = verify_edited("linuxcnc-lathe", "threads-options.ngc",
                              "G76 P1.5 Z-20. I-2.59808 J0.751177 K1.84 R2 Q30. H0",
                              "G76 P1.5 Z-20. I-2.59808 J0.751177 K1.8 R2 Q30. H0", p);
  EXPECT_EQ(r.exit_code, 1);
  // K (a diameter in G7) 1.8: the full depth is 0.9, and the passes end K tan 30 = 0.0115 earlier.
  EXPECT_NE(r.err.find(p + ":43:1: error: thread at " + kOptions +
                       ":19: pass 6: depth 0.9000, plan 0.9200 (tolerance 1e-05)\n"),
            std::string::npos)
      << r.err;
  EXPECT_EQ(first_error(r), p + ":43:1: error: thread at " + kOptions +
                                ":19: pass 1: ends at X15.2488 Z-19.6972, plan X15.2488 "
                                "Z-19.6857 (tolerance 1e-05)");
}

TEST(Verify, HeidenhainG31DepthWordEdited) {
  std::string p;
  RunResult r = verify_edited("heidenhain-pilot", "threads-options.nc", "G31 F1.5 U0.92 IC6",
                              "G31 F1.5 U0.9 IC6", p);
  EXPECT_EQ(r.exit_code, 1);
  EXPECT_EQ(first_error(r), p + ":45:1: error: thread at " + kOptions +
                                ":19: pass 1: depth 0.3674, plan 0.3756 (tolerance 0.001)");
}

TEST(Verify, HaasG76HeightWordEdited) {
  std::string p;
  RunResult r = verify_edited("haas-st", "threads-options.nc", "K0.92 D0.376", "K0.9 D0.376", p);
  EXPECT_EQ(r.exit_code, 1);
  EXPECT_EQ(first_error(r), p + ":24:1: error: thread at " + kOptions +
                                ":19: pass 1: depth 0.3960, plan 0.3756 (tolerance 0.005)");
}

TEST(Verify, G33LoopInfeedEdited) {
  std::string p;
  RunResult r = verify_edited("nct-2000t", "threads-options.nc", "N150 G1 X14.896 F0.2",
                              "N150 G1 X14.8 F0.2", p);
  EXPECT_EQ(r.exit_code, 1);
  // The G33 block cuts at the infeed's X: radius 7.4, 0.6 below the crest at radius 8.
  EXPECT_EQ(first_error(r), p + ":21:1: error: thread at " + kOptions +
                                ":12: pass 2: depth 0.6000, plan 0.5520 (tolerance 0.001)");
}

// A chained thread (threading.md section 11): one segment of one pass moved 0.05 in radius is
// found, at its move within the pass. The plan's second vertex of pass 1 is (X 15 + 3 - 0.411437,
// Z -60 - 0.237543) as diameter X35.1771.
TEST(Verify, ChainSegmentEdited) {
  const std::string cl = "samples/threads/chain.apt";
  std::string text = read_file(source_dir() + "/samples/golden/generic-lathe/threads-chain.nc");
  const std::string from = "N110 X35.177 Z-60.238 F2.\n";
  const size_t at = text.find(from);
  ASSERT_NE(at, std::string::npos);
  text.replace(at, from.size(), "N110 X35.277 Z-60.238 F2.\n");
  const std::string path = temp_dir() + "/threads-chain.nc";
  write_file(path, text);
  RunResult r = run("cd " + quote(source_dir()) + " && " + quote(clpost_bin()) +
                    " verify -m generic-lathe " + quote(path) + " --cl " + cl);
  EXPECT_EQ(r.exit_code, 1);
  EXPECT_EQ(first_error(r), path + ":15:1: error: thread at " + cl +
                                ":12: pass 1: move 2 ends at X35.2770 Z-60.2380, plan X35.1771 "
                                "Z-60.2375 (tolerance 0.001)");
  EXPECT_NE(r.out.find("\nFAILED: 1 difference beyond 0.001 mm\n"), std::string::npos) << r.out;
}

// CYCLE98 read back through the same law the emitter checks: TDEP 0.92 edited to 0.9 moves
// pass 1 to depth 0.9 sqrt(1/5) = 0.402492 (diameter 30 - 2 x 0.402492 = 29.1950), shifted
// 0.402492 tan 30 = 0.2324 along -Z, where the plan has 0.411437 (29.1771, Z-0.2375).
TEST(Verify, Cycle98DepthArgumentEdited) {
  const std::string cl = "samples/threads/chain.apt";
  std::string text = read_file(source_dir() + "/samples/golden/sinumerik-840d/threads-chain.mpf");
  const std::string from = "-80, 50, 0, 0, 0.92, 0, 30,";
  const size_t at = text.find(from);
  ASSERT_NE(at, std::string::npos);
  text.replace(at, from.size(), "-80, 50, 0, 0, 0.9, 0, 30,");
  const std::string path = temp_dir() + "/threads-chain.mpf";
  write_file(path, text);
  RunResult r = run("cd " + quote(source_dir()) + " && " + quote(clpost_bin()) +
                    " verify -m sinumerik-840d " + quote(path) + " --cl " + cl);
  EXPECT_EQ(r.exit_code, 1);
  EXPECT_EQ(first_error(r), path + ":11:1: error: thread at " + cl +
                                ":12: pass 1: starts at X29.1950 Z-0.2324, plan X29.1771 Z-0.2375 "
                                "(tolerance 0.001)");
}

TEST(Verify, AgainstASavedPlan) {
  const std::string dir = temp_dir();
  RunResult plan =
      run("cd " + quote(source_dir()) + " && " + quote(clpost_bin()) +
          " plan -m haas-st --format json " + kOptions + " > " + quote(dir + "/plan.json"));
  ASSERT_EQ(plan.exit_code, 0) << plan.err;
  const std::string golden = source_dir() + "/samples/golden/haas-st/threads-options.nc";
  RunResult r = run(quote(clpost_bin()) + " verify -m haas-st " + quote(golden) + " --plan " +
                    quote(dir + "/plan.json"));
  EXPECT_EQ(r.exit_code, 0) << r.out << r.err;
  EXPECT_NE(r.out.find("7 threads, 39 passes planned, 39 cut\n"), std::string::npos) << r.out;
  // The plan's third pass of the first thread moved 0.01 deeper (radius 7.264 -> 7.254): the
  // program (G92 X14.528) now cuts it 0.01 short.
  std::string json = read_file(dir + "/plan.json");
  const std::string to = "\"to\": {\"x\": 7.264, \"z\": -20}";
  const size_t at = json.find(to);
  ASSERT_NE(at, std::string::npos) << json.substr(0, 2000);
  json.replace(at, to.size(), "\"to\": {\"x\": 7.254, \"z\": -20}");
  write_file(dir + "/plan.json", json);
  r = run(quote(clpost_bin()) + " verify -m haas-st " + quote(golden) + " --plan " +
          quote(dir + "/plan.json"));
  EXPECT_EQ(r.exit_code, 1);
  EXPECT_EQ(first_error(r), golden + ":17:1: error: thread at " + dir +
                                "/plan.json:12: pass 3: depth 0.7260, plan 0.7360 (tolerance "
                                "0.005)");
}

// A chain's plan JSON (points, every pass's path) read back: the golden cuts it; the middle
// vertex of pass 1 moved 0.05 outward in the JSON (radius 14.203 -> 14.253) is found at its move.
TEST(Verify, AgainstASavedChainPlan) {
  const std::string dir = temp_dir();
  const std::string cl = "samples/threads/chain-internal.apt";
  RunResult plan =
      run("cd " + quote(source_dir()) + " && " + quote(clpost_bin()) +
          " plan -m fanuc-0i-t --format json " + cl + " > " + quote(dir + "/plan.json"));
  ASSERT_EQ(plan.exit_code, 0) << plan.err;
  const std::string golden = source_dir() + "/samples/golden/fanuc-0i-t/threads-chain-internal.nc";
  RunResult r = run(quote(clpost_bin()) + " verify -m fanuc-0i-t " + quote(golden) + " --plan " +
                    quote(dir + "/plan.json"));
  EXPECT_EQ(r.exit_code, 0) << r.out << r.err;
  EXPECT_NE(r.out.find("1 threads, 4 passes planned, 4 cut\n"), std::string::npos) << r.out;
  std::string json = read_file(dir + "/plan.json");
  const std::string vertex = "{\"x\": 14.203, \"z\": -10.117202}";
  const size_t at = json.find(vertex);
  ASSERT_NE(at, std::string::npos) << json.substr(0, 2000);
  json.replace(at, vertex.size(), "{\"x\": 14.253, \"z\": -10.117202}");
  write_file(dir + "/plan.json", json);
  r = run(quote(clpost_bin()) + " verify -m fanuc-0i-t " + quote(golden) + " --plan " +
          quote(dir + "/plan.json"));
  EXPECT_EQ(r.exit_code, 1);
  EXPECT_EQ(first_error(r), golden + ":16:1: error: thread at " + dir +
                                "/plan.json:11: pass 1: move 1 ends at X28.4060 Z-10.1170, plan "
                                "X28.5060 Z-10.1172 (tolerance 0.005)");
}

TEST(Verify, PlanJsonErrorsPointIntoTheJson) {
  const std::string dir = temp_dir();
  const std::string golden = source_dir() + "/samples/golden/haas-st/threads-options.nc";
  write_file(dir + "/a.json", "{\"file\": \"x\", \"units\": \"mm\",\n  \"threadz\": []}\n");
  RunResult r = run(quote(clpost_bin()) + " verify -m haas-st " + quote(golden) + " --plan " +
                    quote(dir + "/a.json"));
  EXPECT_EQ(r.exit_code, 1);
  EXPECT_EQ(r.err, dir +
                       "/a.json:1:1: error: plan JSON: 'threads' missing\n"
                       "  {\"file\": \"x\", \"units\": \"mm\",\n  ^\n");
  write_file(dir + "/b.json",
             "{\"file\": \"x\", \"units\": \"mm\",\n  \"threads\": [ {\"line\": 3, \"form\": "
             "\"couple\"} ]}\n");
  r = run(quote(clpost_bin()) + " verify -m haas-st " + quote(golden) + " --plan " +
          quote(dir + "/b.json"));
  EXPECT_EQ(r.exit_code, 1);
  EXPECT_EQ(first_error(r), dir +
                                "/b.json:2:16: error: thread at line 3: a couple thread's path "
                                "is not in the plan JSON; verify against the CL file (--cl)");
  r = run(quote(clpost_bin()) + " verify -m haas-st " + quote(golden));
  EXPECT_EQ(r.exit_code, 2);
  EXPECT_EQ(r.err, "clpost verify: error: give the plan: --cl INPUT.cl or --plan PLAN.json\n");
}

TEST(Verify, ProgramThatIsNotNc) {
  const std::string dir = temp_dir();
  write_file(dir + "/p.nc", "G0 X10 Z5\nG1 X1.2.3\n");
  RunResult r = run("cd " + quote(source_dir()) + " && " + quote(clpost_bin()) +
                    " verify -m generic-lathe " + quote(dir + "/p.nc") + " --cl " + kOptions);
  EXPECT_EQ(r.exit_code, 1);
  EXPECT_EQ(r.err, dir + "/p.nc:2:4: error: invalid number 'X1.2.3'\n  G1 X1.2.3\n     ^\n");
}

TEST(Verify, PostWithVerifyWritesTheProgramWhenItCutsThePlan) {
  const std::string out = temp_dir() + "/options.nc";
  RunResult r = run("cd " + quote(source_dir()) + " && " + quote(clpost_bin()) +
                    " -m haas-st --verify -o " + quote(out) + " " + kOptions);
  EXPECT_EQ(r.exit_code, 0) << r.err;
  EXPECT_EQ(read_file(out), read_file(source_dir() + "/samples/golden/haas-st/threads-options.nc"));
  EXPECT_NE(r.err.find("7 threads, 39 passes planned, 39 cut\n"), std::string::npos) << r.err;
  EXPECT_NE(r.err.find("\nok: every pass is cut as planned, within 0.005 mm\n"), std::string::npos)
      << r.err;
}

TEST(Verify, PostWithVerifyWritesNothingWhenTheMachineRoundsThePassesAway) {
  // X to 0.1 mm on a diameter: the last pass of the OPTION 4 thread lands at X14.2, 0.02 short.
  const std::string out = temp_dir() + "/options.nc";
  RunResult r = run("cd " + quote(source_dir()) + " && " + quote(clpost_bin()) +
                    " -m generic-lathe --set formats.X.decimals=1 --verify -o " + quote(out) + " " +
                    kOptions);
  EXPECT_EQ(r.exit_code, 1);
  EXPECT_FALSE(file_exists(out));
  EXPECT_NE(r.err.find(":54: pass 4: depth 0.9000, plan 0.9200 (tolerance 0.001)\n"),
            std::string::npos)
      << r.err;
}

TEST(Verify, ABatchVerifiesEveryProgram) {
  const std::string dir = temp_dir();
  RunResult r = run("cd " + quote(source_dir()) + " && " + quote(clpost_bin()) +
                    " -m fanuc-0i-t --verify -d " + quote(dir) +
                    " samples/threads/options.apt samples/threads/multistart.apt");
  EXPECT_EQ(r.exit_code, 0) << r.err;
  EXPECT_NE(r.err.find("ok        samples/threads/options.apt\n"
                       "ok        samples/threads/multistart.apt\n"),
            std::string::npos)
      << r.err;
  EXPECT_EQ(read_file(dir + "/options.nc"),
            read_file(source_dir() + "/samples/golden/fanuc-0i-t/threads-options.nc"));
  // X to 0.1 mm: every file fails with its first difference, and nothing is written.
  const std::string bad = temp_dir();
  r = run("cd " + quote(source_dir()) + " && " + quote(clpost_bin()) +
          " -m generic-lathe --set formats.X.decimals=1 --verify --keep-going -d " + quote(bad) +
          " samples/threads/options.apt");
  EXPECT_EQ(r.exit_code, 1);
  EXPECT_NE(r.err.find("error     samples/threads/options.apt: error: --verify: the program does "
                       "not cut the plan: " +
                       bad +
                       "/options.nc:16: thread at samples/threads/options.apt:12: pass 1: depth "
                       "0.3000, plan 0.3067 (tolerance 0.001) (+34 more)\n"),
            std::string::npos)
      << r.err;
  EXPECT_FALSE(file_exists(bad + "/options.nc"));
}

// `count` identical multi-pass threads, each 5 passes (4 cuts and a finish) on generic-lathe.
std::string identical_threads(int count) {
  std::string cl = "PARTNO THREADS\nUNITS/MM\nLOADTL/7,ADJUST,7\nSPINDL/600,RPM,CLW\n";
  for (int i = 0; i < count; ++i)
    cl +=
        "RAPID\nGOTO/15.0000,0.0000,5.0000\n"
        "THREAD/ON,DEPTH,1.534,CUTS,4,FINCUT,1,0.1,OPTION,1,MMPR,2.5,CHAMFR,2.5\n"
        "GOTO/10.0000,0.0000,2.0000\nGOTO/10.0000,0.0000,-30.0000\nTHREAD/OFF\n";
  return cl + "RAPID\nGOTO/50.0000,0.0000,50.0000\nSPINDL/OFF\nEND\nFINI\n";
}

// Line `n` (1-based) of the lines of `text` that contain `what`, replaced by `to`.
void replace_nth_line(std::string& text, const std::string& what, int n, const std::string& to) {
  size_t at = 0;
  for (int seen = 0; (at = text.find(what, at)) != std::string::npos; ++at)
    if (++seen == n) break;
  ASSERT_NE(at, std::string::npos) << what << " " << n;
  const size_t begin = text.rfind('\n', at) + 1;
  text.replace(begin, text.find('\n', at) - begin, to);
}

// --verify compares the threads in windows as the program is written (ThreadStream, 64 threads
// at a time): on 100 identical threads, with a pass ending short in thread 30 and a pass
// dropped in thread 90, it says word for word what `clpost verify` says comparing the whole
// program at once. (Thread 90's missing pass is named as thread 91's first: the threads are
// identical, and the alignment puts the gap where it costs least.)
TEST(Verify, StreamedThreadsReportAsTheWholeProgram) {
  const Machine m = shipped_machine("generic-lathe");
  PostOptions options;
  options.keep_motions = true;
  const PostedText posted = post_text(identical_threads(100), m, "t.cl", options);
  ASSERT_FALSE(posted.diags.has_errors()) << posted.diags.render_all();
  ASSERT_EQ(posted.plans.size(), 100u);
  std::string program = posted.program;
  // The 148th G33 is thread 30's pass 3 (5 per thread); the 450th, thread 90's pass 5.
  replace_nth_line(program, " G33 ", 148, "G33 Z-28.831 F2.5");
  replace_nth_line(program, " G33 ", 450, "");
  reader::LineSource src{std::string_view(program)};
  const ClExpected expected{posted.summary.holes, posted.summary.path, posted.summary.mill};
  const VerifyOutcome whole = verify_program(src, "t.nc", posted.plans, &expected, "t.cl", m, 0);

  ProgramStream stream("t.nc", "t.cl", m, 0);
  stream.program_text(program);
  for (const ThreadPlan& p : posted.plans) stream.plan(p);
  const ClPath& path = posted.summary.path;
  for (const ClMotion& c : path.motions) stream.cl_motion(c, path.states[c.state]);
  const VerifyOutcome streamed =
      stream.finish(posted.summary.holes, posted.summary.mill, path.states.size());

  EXPECT_FALSE(whole.ok);
  EXPECT_NE(whole.report.find(": 100 threads, 500 passes planned, 499 cut\n"), std::string::npos)
      << whole.report;
  // Thread 30: THREAD/ON at CL line 7 + 6 x 29, its G33 blocks on NC lines 15 + 33 x 29 to
  // 39 + 33 x 29 (33 lines a thread); its pass 3 ends 1 mm short of Z-29.8313.
  EXPECT_NE(whole.report.find("  t.cl:181     5 passes  DIFFERS G33, NC lines 972-996\n"
                              "      pass 3: ends at X17.5160 Z-28.8310, plan X17.5162 Z-29.8313 "
                              "(tolerance 0.001)\n"),
            std::string::npos)
      << whole.report;
  EXPECT_EQ(streamed.ok, whole.ok);
  EXPECT_EQ(streamed.report, whole.report);
  EXPECT_EQ(streamed.diagnostics, whole.diagnostics);
  EXPECT_EQ(streamed.errors, whole.errors);
}

// With block delete on, --verify compares the program as with it off until the two first differ
// (ProgramStream: at an optional block or an OPSKIP motion), then on its own. Here they differ
// after 30000 motions, which a program behind its header has on disk before its first line.
// The block after the OPSKIP range edited not to state X again (case E before its fix,
// docs/cl-meaning.md) is wrong only with block delete on: streamed with the CL first or the
// program first, verify says word for word what it says of the whole program.
TEST(Verify, StreamedBlockDeleteRunReportsAsTheWholeProgram) {
  const Machine m = shipped_machine("fanuc-0i-t");
  std::string cl = "UNITS/MM\nLOADTL/1\nSPINDL/500,RPM,CLW\nFEDRAT/0.2,MMPR\nGOTO/20,0,5\n";
  for (int i = 0; i < 15000; ++i) cl += "GOTO/20,0,4\nGOTO/20,0,5\n";
  cl += "OPSKIP/ON\nGOTO/10,0,-5\nOPSKIP/OFF\nGOTO/10,0,-10\nFINI\n";
  PostOptions options;
  options.keep_motions = true;
  const PostedText posted = post_text(cl, m, "t.cl", options);
  ASSERT_FALSE(posted.diags.has_errors()) << posted.diags.render_all();
  std::string program = posted.program;
  const std::string right = " G1 X20. Z-10. G99 F0.2\n";
  const size_t at = program.find(right);
  ASSERT_NE(at, std::string::npos) << program.substr(program.size() - 200);
  program.replace(at, right.size(), " Z-10.\n");
  reader::LineSource src{std::string_view(program)};
  const ClExpected expected{posted.summary.holes, posted.summary.path, posted.summary.mill};
  const VerifyOutcome whole = verify_program(src, "t.nc", {}, &expected, "t.cl", m, 0);
  EXPECT_FALSE(whole.ok);
  EXPECT_EQ(whole.errors, 1u);
  EXPECT_NE(whole.diagnostics.find("error: motion at t.cl:30009: X20.0000 Z-10.0000 is not "
                                   "reached by the program in order (block delete on)\n"),
            std::string::npos)
      << whole.diagnostics;
  EXPECT_NE(whole.report.find("block delete on: 1 difference (see the errors)\n"),
            std::string::npos)
      << whole.report;

  // Behind a header the whole CL comes first; without one, the program may run ahead of it.
  Machine no_header = m;
  no_header.templates.erase(std::string(tmpl::kProgramHeader.name));
  const ClPath& path = posted.summary.path;
  for (const bool cl_first : {true, false}) {
    ProgramStream stream("t.nc", "t.cl", cl_first ? m : no_header, 0);
    if (!cl_first) stream.program_text(program);
    for (const ClMotion& c : path.motions) stream.cl_motion(c, path.states[c.state]);
    if (cl_first) stream.program_text(program);
    const VerifyOutcome streamed =
        stream.finish(posted.summary.holes, posted.summary.mill, path.states.size());
    EXPECT_EQ(streamed.ok, whole.ok) << cl_first;
    EXPECT_EQ(streamed.report, whole.report) << cl_first;
    EXPECT_EQ(streamed.diagnostics, whole.diagnostics) << cl_first;
    EXPECT_EQ(streamed.errors, whole.errors) << cl_first;
  }
}

// `clpost verify --cl` reads the program into the stream a line at a time
// (ProgramStream::program_lines) after the whole CL, as a program behind its header comes: on
// a program with CRLF line ends and a thread pass edited, and on one with a line longer than
// 64 KiB (it cannot be read), it says word for word what verify of the whole program says.
TEST(Verify, ProgramReadIntoTheStreamReportsAsTheWholeProgram) {
  const Machine m = shipped_machine("generic-lathe");
  PostOptions options;
  options.keep_motions = true;
  const PostedText posted = post_text(identical_threads(3), m, "t.cl", options);
  ASSERT_FALSE(posted.diags.has_errors()) << posted.diags.render_all();
  std::string edited = posted.program, too_long = posted.program;
  replace_nth_line(edited, " G33 ", 7, "G33 Z-28.831 F2.5");
  replace_nth_line(too_long, " G33 ", 2, "(" + std::string(70000, 'x') + ")");
  const std::string first_errors[] = {
      "t.nc:54:1: error: thread at t.cl:13: pass 2: ends at X17.9720 Z-28.8310, plan X17.9720 "
      "Z-29.6998 (tolerance 0.001)\n",
      "t.nc:21:1: error: line longer than 65536 bytes\n"};
  int k = 0;
  for (const std::string& program : {edited, too_long}) {
    std::string crlf;
    for (char c : program) crlf += c == '\n' ? std::string("\r\n") : std::string(1, c);
    reader::LineSource whole_src{std::string_view(crlf)};
    const ClExpected expected{posted.summary.holes, posted.summary.path, posted.summary.mill};
    const VerifyOutcome whole =
        verify_program(whole_src, "t.nc", posted.plans, &expected, "t.cl", m, 0);
    EXPECT_FALSE(whole.ok);
    EXPECT_EQ(whole.diagnostics.rfind(first_errors[k++], 0), 0u) << whole.diagnostics;

    ProgramStream stream("t.nc", "t.cl", m, 0);
    for (const ThreadPlan& p : posted.plans) stream.plan(p);
    const ClPath& path = posted.summary.path;
    for (const ClMotion& c : path.motions) stream.cl_motion(c, path.states[c.state]);
    reader::LineSource src{std::string_view(crlf)};
    stream.program_lines(src);
    const VerifyOutcome streamed =
        stream.finish(posted.summary.holes, posted.summary.mill, path.states.size());
    EXPECT_EQ(streamed.ok, whole.ok);
    EXPECT_EQ(streamed.report, whole.report);
    EXPECT_EQ(streamed.diagnostics, whole.diagnostics);
    EXPECT_EQ(streamed.errors, whole.errors);
  }
}

}  // namespace
}  // namespace clpost::test

// Batch posting through the binary: `clpost -d OUTDIR [-r] [-j N] [--keep-going] [--quiet]
// [--report FILE] INPUT…` — what it writes, what it prints, its exit status.
#include <gtest/gtest.h>
#include <unistd.h>

#include <filesystem>
#include <regex>

#include "test_util.h"

namespace clpost::test {
namespace {

namespace fs = std::filesystem;

std::string bin() {
  return quote(clpost_bin());
}

constexpr const char* kTurning =
    "PARTNO SHAFT\n"
    "UNITS/MM\n"
    "LOADTL/1\n"
    "SPINDL/1200,RPM,CLW\n"
    "FEDRAT/0.25,MMPR\n"
    "RAPID\n"
    "GOTO/20,0,2\n"
    "GOTO/19.5,0,-30\n"
    "GOTO/21,0,-31\n"
    "FINI\n";

constexpr const char* kThread =
    "PARTNO M20X2.5\n"
    "UNITS/MM\n"
    "LOADTL/7,ADJUST,7\n"
    "SPINDL/600,RPM,CLW\n"
    "FEDRAT/0.2,MMPR\n"
    "RAPID\n"
    "GOTO/15,0,5\n"
    "RAPID\n"
    "THREAD/ON,DEPTH,1.534,CUTS,4,FINCUT,1,0.1,OPTION,1,MMPR,2.5,CHAMFR,2.5\n"
    "GOTO/10,0,2\n"
    "GOTO/10,0,-30\n"
    "THREAD/OFF\n"
    "RAPID\n"
    "GOTO/50,0,50\n"
    "FINI\n";

constexpr const char* kWarning =
    "UNITS/MM\n"
    "FEDRAT/0.1,MMPR\n"
    "FROB/1,2\n"
    "GOTO/1,0,1\n"
    "FINI\n";

// A bad number on line 7, column 11.
constexpr const char* kBad =
    "PARTNO BAD\n"
    "UNITS/MM\n"
    "LOADTL/1\n"
    "SPINDL/1000,RPM,CLW\n"
    "FEDRAT/0.2,MMPR\n"
    "GOTO/10,0,2\n"
    "GOTO/10,0,-1.2.3\n"
    "FINI\n";

// The summary ends in the time taken: replaced by "T s".
std::string without_time(const std::string& err) {
  return std::regex_replace(err, std::regex("; [0-9]+\\.[0-9]+ s\n"), "; T s\n");
}

size_t entries(const std::string& dir) {
  return static_cast<size_t>(std::distance(fs::directory_iterator(dir), fs::directory_iterator()));
}

// in/a-turning.cl, in/b-bad.cl, in/c-thread.cl
struct Inputs {
  std::string dir = temp_dir();
  std::string in = dir + "/in";
  std::string out = dir + "/out";
  Inputs() {
    fs::create_directories(in);
    write_file(in + "/a-turning.cl", kTurning);
    write_file(in + "/b-bad.cl", kBad);
    write_file(in + "/c-thread.cl", kThread);
  }
  ~Inputs() { fs::remove_all(dir); }
  std::string files() const {
    return quote(in + "/a-turning.cl") + " " + quote(in + "/b-bad.cl") + " " +
           quote(in + "/c-thread.cl");
  }
};

TEST(Batch, EveryInputBecomesStemPlusExtensionAndMatchesASinglePost) {
  Inputs t;
  write_file(t.in + "/b-bad.cl", kWarning);  // no failure here
  RunResult r = run(bin() + " -m linuxcnc-lathe -d " + quote(t.out) + " " + t.files());
  EXPECT_EQ(r.exit_code, 0) << r.err;
  EXPECT_EQ(
      without_time(r.err),
      "ok        " + t.in + "/a-turning.cl\n" + "warnings  " + t.in +
          "/b-bad.cl:3:1: warning: unknown statement 'FROB' written as a comment\n" + "ok        " +
          t.in + "/c-thread.cl\n" +
          "3 files: 2 ok, 1 with warnings, 0 failed, 0 not posted; 0 errors, 1 warning; " +
          std::to_string(fs::file_size(t.in + "/a-turning.cl") + fs::file_size(t.in + "/b-bad.cl") +
                         fs::file_size(t.in + "/c-thread.cl")) +
          " bytes in, " +
          std::to_string(fs::file_size(t.out + "/a-turning.ngc") +
                         fs::file_size(t.out + "/b-bad.ngc") +
                         fs::file_size(t.out + "/c-thread.ngc")) +
          " bytes out; T s\n");
  EXPECT_EQ(entries(t.out), 3u);
  for (const char* stem : {"a-turning", "b-bad", "c-thread"}) {
    RunResult single = run(bin() + " -m linuxcnc-lathe " + quote(t.in + "/" + stem + ".cl"));
    ASSERT_EQ(single.exit_code, 0) << single.err;
    EXPECT_EQ(read_file(t.out + "/" + stem + ".ngc"), single.out) << stem;
  }
  EXPECT_NE(read_file(t.out + "/c-thread.ngc").find("G33"), std::string::npos);
}

TEST(Batch, OutputIsTheSameWhateverTheNumberOfJobs) {
  Inputs t;
  write_file(t.in + "/b-bad.cl", kWarning);
  for (int i = 0; i < 12; ++i)
    write_file(t.in + "/more-" + std::to_string(i) + ".cl", i % 2 ? kThread : kTurning);
  RunResult j1 = run(bin() + " -j 1 -r -d " + quote(t.dir + "/j1") + " " + quote(t.in));
  RunResult j4 = run(bin() + " -j 4 -r -d " + quote(t.dir + "/j4") + " " + quote(t.in));
  EXPECT_EQ(j1.exit_code, 0) << j1.err;
  EXPECT_EQ(j4.exit_code, 0) << j4.err;
  EXPECT_EQ(without_time(j1.err), without_time(j4.err));  // in input order both times
  ASSERT_EQ(entries(t.dir + "/j1"), 15u);
  ASSERT_EQ(entries(t.dir + "/j4"), 15u);
  for (const auto& e : fs::directory_iterator(t.dir + "/j1")) {
    std::string name = e.path().filename().string();
    std::string a = read_file(e.path().string());
    EXPECT_FALSE(a.empty()) << name;
    EXPECT_EQ(a, read_file(t.dir + "/j4/" + name)) << name;
  }
}

TEST(Batch, AFailureStopsTheBatchWithoutKeepGoing) {
  Inputs t;
  RunResult r = run(bin() + " -j 1 -d " + quote(t.out) + " " + t.files());
  EXPECT_EQ(r.exit_code, 1);
  const size_t in_a = fs::file_size(t.in + "/a-turning.cl"),
               in_b = fs::file_size(t.in + "/b-bad.cl");
  EXPECT_EQ(without_time(r.err),
            "ok        " + t.in + "/a-turning.cl\n" + "error     " + t.in +
                "/b-bad.cl:7:11: error: invalid number '-1.2.3'\n" + "skipped   " + t.in +
                "/c-thread.cl (not posted after an earlier error; --keep-going posts it)\n" +
                "3 files: 1 ok, 0 with warnings, 1 failed, 1 not posted; 1 error, 0 warnings; " +
                std::to_string(in_a + in_b) + " bytes in, " +
                std::to_string(fs::file_size(t.out + "/a-turning.nc")) + " bytes out; T s\n");
  EXPECT_TRUE(file_exists(t.out + "/a-turning.nc"));
  EXPECT_FALSE(file_exists(t.out + "/b-bad.nc"));
  EXPECT_FALSE(file_exists(t.out + "/c-thread.nc"));
  EXPECT_EQ(entries(t.out), 1u);  // no temporary file left behind
}

TEST(Batch, KeepGoingPostsEverythingAndStillExitsOne) {
  Inputs t;
  RunResult r = run(bin() + " -j 2 --keep-going -d " + quote(t.out) + " " + t.files());
  EXPECT_EQ(r.exit_code, 1);
  const size_t in = fs::file_size(t.in + "/a-turning.cl") + fs::file_size(t.in + "/b-bad.cl") +
                    fs::file_size(t.in + "/c-thread.cl");
  const size_t out = fs::file_size(t.out + "/a-turning.nc") + fs::file_size(t.out + "/c-thread.nc");
  EXPECT_EQ(without_time(r.err),
            "ok        " + t.in + "/a-turning.cl\n" + "error     " + t.in +
                "/b-bad.cl:7:11: error: invalid number '-1.2.3'\n" + "ok        " + t.in +
                "/c-thread.cl\n" +
                "3 files: 2 ok, 0 with warnings, 1 failed, 0 not posted; 1 error, 0 warnings; " +
                std::to_string(in) + " bytes in, " + std::to_string(out) + " bytes out; T s\n");
  EXPECT_FALSE(file_exists(t.out + "/b-bad.nc"));
  EXPECT_EQ(entries(t.out), 2u);
}

TEST(Batch, AFailedFileNeverReplacesAGoodProgram) {
  Inputs t;
  fs::create_directories(t.out);
  write_file(t.out + "/b-bad.nc", "good program\n");
  RunResult r = run(bin() + " --keep-going -d " + quote(t.out) + " " + t.files());
  EXPECT_EQ(r.exit_code, 1);
  EXPECT_EQ(read_file(t.out + "/b-bad.nc"), "good program\n");
  EXPECT_EQ(entries(t.out), 3u);
}

TEST(Batch, QuietPrintsOnlyTheFailures) {
  Inputs t;
  RunResult r = run(bin() + " --quiet --keep-going -d " + quote(t.out) + " " + t.files());
  EXPECT_EQ(r.exit_code, 1);
  EXPECT_EQ(r.err, "error     " + t.in + "/b-bad.cl:7:11: error: invalid number '-1.2.3'\n");
  RunResult ok = run(bin() + " -q -d " + quote(t.out) + " " + quote(t.in + "/c-thread.cl"));
  EXPECT_EQ(ok.exit_code, 0);
  EXPECT_EQ(ok.err, "");
  EXPECT_EQ(ok.out, "");
}

TEST(Batch, UnwritableOutputDirectoryStopsBeforePosting) {
  Inputs t;
  // A path below a regular file cannot be created, not even by root.
  write_file(t.dir + "/plain-file", "x");
  RunResult r = run(bin() + " -d " + quote(t.dir + "/plain-file/out") + " " + t.files());
  EXPECT_EQ(r.exit_code, 2);
  EXPECT_EQ(r.err, "clpost: error: cannot create the output directory '" + t.dir +
                       "/plain-file/out': Not a directory\n");
  RunResult f = run(bin() + " -d " + quote(t.dir + "/plain-file") + " " + t.files());
  EXPECT_EQ(f.exit_code, 2);
  EXPECT_EQ(f.err, "clpost: error: cannot create the output directory '" + t.dir +
                       "/plain-file': Not a directory\n");
}

TEST(Batch, ReadOnlyOutputDirectory) {
  if (::geteuid() == 0) GTEST_SKIP() << "root writes to read-only directories";
  Inputs t;
  fs::create_directories(t.out);
  fs::permissions(t.out, fs::perms::owner_read | fs::perms::owner_exec);
  RunResult r = run(bin() + " -d " + quote(t.out) + " " + t.files());
  fs::permissions(t.out, fs::perms::owner_all);
  EXPECT_EQ(r.exit_code, 2);
  EXPECT_EQ(r.err, "clpost: error: cannot write to the output directory '" + t.out +
                       "': Permission denied\n");
  EXPECT_EQ(entries(t.out), 0u);
}

TEST(Batch, DuplicateStemsAreRefusedUpFront) {
  Inputs t;
  fs::create_directories(t.in + "/other");
  write_file(t.in + "/other/a-turning.apt", kTurning);
  RunResult r = run(bin() + " -d " + quote(t.out) + " " + t.files() + " " +
                    quote(t.in + "/other/a-turning.apt"));
  EXPECT_EQ(r.exit_code, 2);
  EXPECT_EQ(r.err, "clpost: error: '" + t.in + "/a-turning.cl' and '" + t.in +
                       "/other/a-turning.apt' would both be written to '" + t.out +
                       "/a-turning.nc'\n");
  EXPECT_FALSE(file_exists(t.out));  // nothing posted, nothing created
}

TEST(Batch, RecursiveDirectories) {
  Inputs t;
  fs::create_directories(t.in + "/sub/deeper");
  write_file(t.in + "/sub/deeper/d-nested.APT", kTurning);
  write_file(t.in + "/sub/readme.txt", "not CL");
  fs::remove(t.in + "/b-bad.cl");
  RunResult no_r = run(bin() + " -d " + quote(t.out) + " " + quote(t.in));
  EXPECT_EQ(no_r.exit_code, 2);
  EXPECT_EQ(no_r.err,
            "clpost: error: " + t.in + ": is a directory (use -r to post the CL files in it)\n");
  RunResult r = run(bin() + " -r -d " + quote(t.out) + " " + quote(t.in));
  EXPECT_EQ(r.exit_code, 0) << r.err;
  EXPECT_EQ(without_time(r.err).substr(0, r.err.find("3 files")),
            "ok        " + t.in + "/a-turning.cl\n" + "ok        " + t.in + "/c-thread.cl\n" +
                "ok        " + t.in + "/sub/deeper/d-nested.APT\n");
  EXPECT_EQ(entries(t.out), 3u);
  EXPECT_EQ(read_file(t.out + "/d-nested.nc"), read_file(t.out + "/a-turning.nc"));
}

TEST(Batch, ReportJson) {
  Inputs t;
  write_file(t.in + "/a-turning.cl", kWarning);
  std::string report = t.dir + "/report.json";
  RunResult r = run(bin() + " -j 2 --keep-going --report " + quote(report) + " -d " + quote(t.out) +
                    " " + t.files());
  EXPECT_EQ(r.exit_code, 1);
  const std::string json = std::regex_replace(
      read_file(report), std::regex("\"seconds\": [0-9]+\\.[0-9]+"), "\"seconds\": T");
  const size_t a = fs::file_size(t.in + "/a-turning.cl"), b = fs::file_size(t.in + "/b-bad.cl"),
               c = fs::file_size(t.in + "/c-thread.cl");
  const size_t oa = fs::file_size(t.out + "/a-turning.nc"),
               oc = fs::file_size(t.out + "/c-thread.nc");
  auto n = [](size_t v) { return std::to_string(v); };
  EXPECT_EQ(
      json,
      "{\n"
      "  \"machine\": \"generic-lathe\",\n"
      "  \"output_dir\": \"" +
          t.out +
          "\",\n"
          "  \"jobs\": 2,\n"
          "  \"summary\": {\"files\": 3, \"ok\": 1, \"with_warnings\": 1, \"failed\": 1, "
          "\"not_posted\": 0, \"errors\": 1, \"warnings\": 1, \"bytes_in\": " +
          n(a + b + c) + ", \"bytes_out\": " + n(oa + oc) +
          ", \"seconds\": T},\n"
          "  \"files\": [\n"
          "    {\"input\": \"" +
          t.in + "/a-turning.cl\", \"output\": \"" + t.out +
          "/a-turning.nc\", \"status\": \"warnings\", \"errors\": 0, \"warnings\": 1, "
          "\"statements\": 5, \"motions\": 1, \"threads\": 0, \"passes\": 0, \"bytes_in\": " +
          n(a) + ", \"bytes_out\": " + n(oa) +
          ", \"seconds\": T, \"cycle_time\": {\"seconds\": T, \"rapids_timed\": true, "
          "\"tools\": []}, \"sheet\": null, \"diagnostics\": [\n"
          "      {\"severity\": \"warning\", \"line\": 3, \"column\": 1, \"message\": "
          "\"unknown statement 'FROB' written as a comment\"}\n"
          "    ]},\n"
          "    {\"input\": \"" +
          t.in +
          "/b-bad.cl\", \"output\": null, \"status\": \"error\", "
          "\"errors\": 1, \"warnings\": 0, \"statements\": 8, \"motions\": 1, \"threads\": 0, "
          "\"passes\": 0, \"bytes_in\": " +
          n(b) +
          ", \"bytes_out\": 0, \"seconds\": T, \"cycle_time\": null, \"sheet\": null, "
          "\"diagnostics\": [\n"
          "      {\"severity\": \"error\", \"line\": 7, \"column\": 11, \"message\": "
          "\"invalid number '-1.2.3'\"}\n"
          "    ]},\n"
          "    {\"input\": \"" +
          t.in + "/c-thread.cl\", \"output\": \"" + t.out +
          "/c-thread.nc\", \"status\": \"ok\", \"errors\": 0, \"warnings\": 0, "
          "\"statements\": 15, \"motions\": 22, \"threads\": 1, \"passes\": 5, \"bytes_in\": " +
          n(c) + ", \"bytes_out\": " + n(oc) +
          ", \"seconds\": T, \"cycle_time\": {\"seconds\": T, \"rapids_timed\": true, "
          "\"tools\": [{\"tool\": 7, \"offset\": 7, \"seconds\": T, \"text\": \"\"}]}, "
          "\"sheet\": null, \"diagnostics\": []}\n"
          "  ]\n"
          "}\n");
}

TEST(Batch, UsageErrors) {
  Inputs t;
  RunResult two = run(bin() + " " + t.files());
  EXPECT_EQ(two.exit_code, 2);
  EXPECT_EQ(two.err, "clpost: error: several inputs need an output directory: -d OUTDIR\n");
  RunResult j = run(bin() + " -j 2 " + quote(t.in + "/a-turning.cl"));
  EXPECT_EQ(j.exit_code, 2);
  EXPECT_EQ(j.err, "clpost: error: -r, -j, --keep-going, --quiet and --report need -d OUTDIR\n");
  RunResult o = run(bin() + " -o x.nc -d " + quote(t.out) + " " + quote(t.in + "/a-turning.cl"));
  EXPECT_EQ(o.exit_code, 2);
  EXPECT_EQ(o.err, "clpost: error: -o and -d cannot be used together\n");
  RunResult zero = run(bin() + " -j 0 -d " + quote(t.out) + " " + quote(t.in + "/a-turning.cl"));
  EXPECT_EQ(zero.exit_code, 2);
  RunResult missing = run(bin() + " -d " + quote(t.out) + " " + quote(t.in + "/nope.cl"));
  EXPECT_EQ(missing.exit_code, 2);
  EXPECT_EQ(missing.err, "clpost: error: " + t.in + "/nope.cl: no such file or directory\n");
}

}  // namespace
}  // namespace clpost::test

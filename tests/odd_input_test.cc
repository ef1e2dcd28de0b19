// Hostile and odd input through the whole program (issue 7): empty and binary files, line ends,
// a BOM, outputs that cannot be written, devices and pipes. Exact diagnostics, exit codes, and
// nothing left behind.
#include <gtest/gtest.h>
#include <sys/stat.h>

#include <filesystem>

#include "test_util.h"

namespace clpost::test {
namespace {

namespace fs = std::filesystem;

std::string bin() {
  return quote(clpost_bin());
}

size_t entries(const std::string& dir) {
  return static_cast<size_t>(std::distance(fs::directory_iterator(dir), fs::directory_iterator()));
}

const std::string kSample = "/samples/thread-m20.apt";

// The program clpost writes for the sample on standard output (the goldens test that one).
const std::string& expected_program() {
  static const std::string out = [] {
    RunResult r = run(bin() + " " + quote(source_dir() + kSample));
    EXPECT_EQ(r.exit_code, 0) << r.err;
    EXPECT_NE(r.out.find("G33 Z-30. F2.5"), std::string::npos) << r.out;
    return r.out;
  }();
  return out;
}

TEST(OddInput, EmptyFileIsAnErrorAndWritesNothing) {
  std::string dir = temp_dir();
  for (const char* text : {"", "\n\n  \t\n", "$$ only a comment\n", "\xEF\xBB\xBF"}) {
    write_file(dir + "/empty.cl", text);
    RunResult r = run(bin() + " -o " + quote(dir + "/out.nc") + " " + quote(dir + "/empty.cl"));
    EXPECT_EQ(r.exit_code, 1) << text;
    EXPECT_EQ(r.err, dir + "/empty.cl: error: no CL statements in the file\n") << text;
    EXPECT_EQ(entries(dir), 1u) << text;
  }
  fs::remove_all(dir);
}

TEST(OddInput, BinaryGarbageIsOneErrorAndStops) {
  std::string dir = temp_dir();
  // An executable's first bytes, then 1 MB of noise: one error at the first NUL.
  std::string garbage(
      "\x7f"
      "ELF\x02\x01\x01\0\0\0",
      10);
  uint32_t seed = 7;
  while (garbage.size() < (1 << 20)) {
    seed = seed * 1664525u + 1013904223u;
    garbage += static_cast<char>(seed >> 24);
  }
  write_file(dir + "/a.out", garbage);
  RunResult r = run(bin() + " -o " + quote(dir + "/out.nc") + " " + quote(dir + "/a.out"));
  EXPECT_EQ(r.exit_code, 1);
  EXPECT_EQ(r.err, dir + "/a.out: error: not a CL text file (binary data at byte 7)\n");
  EXPECT_EQ(entries(dir), 1u);
  // Control characters without a NUL: more than one byte in ten is not text.
  std::string controls;
  for (int i = 0; i < 1000; ++i) controls += "GO\x01\x02\x03\x04TO/1\n";
  write_file(dir + "/ctl.cl", controls);
  RunResult c = run(bin() + " check " + quote(dir + "/ctl.cl"));
  EXPECT_EQ(c.exit_code, 1);
  EXPECT_EQ(c.err.substr(0, c.err.find('\n') + 1),
            dir + "/ctl.cl: error: not a CL text file (binary data at byte 2)\n");
  fs::remove_all(dir);
}

TEST(OddInput, CrlfMixedLineEndsAndBomGiveTheSameProgram) {
  std::string dir = temp_dir();
  const std::string lf = read_file(source_dir() + kSample);
  std::string crlf = "\xEF\xBB\xBF", mixed;
  int i = 0;
  for (char c : lf) {
    if (c != '\n') {
      crlf += c;
      mixed += c;
      continue;
    }
    crlf += "\r\n";
    mixed += i % 3 == 0 ? "\r\n" : i % 3 == 1 ? "\r" : "\n";
    ++i;
  }
  write_file(dir + "/crlf.apt", crlf);
  write_file(dir + "/mixed.apt", mixed);
  const std::string golden = expected_program();
  for (const char* name : {"/crlf.apt", "/mixed.apt"}) {
    RunResult r = run(bin() + " " + quote(dir + name));
    EXPECT_EQ(r.exit_code, 0) << name;
    EXPECT_EQ(r.err, "") << name;
    EXPECT_EQ(r.out, golden) << name;
  }
  fs::remove_all(dir);
}

TEST(OddInput, AnErrorLateInTheFileReportsItsLineAfterCrlf) {
  std::string dir = temp_dir();
  write_file(dir + "/bad.cl",
             "UNITS/MM\r\nFEDRAT/0.1,MMPR\r\nGOTO/1,0,1\r\nGOTO/1,0,--1\r\nFINI\r\n");
  RunResult r = run(bin() + " " + quote(dir + "/bad.cl"));
  EXPECT_EQ(r.exit_code, 1);
  EXPECT_EQ(r.err, dir +
                       "/bad.cl:4:10: error: invalid number '--1'\n"
                       "  GOTO/1,0,--1\n"
                       "           ^\n");
  EXPECT_EQ(r.out, "");
  fs::remove_all(dir);
}

TEST(OddInput, OutputInAMissingDirectory) {
  std::string dir = temp_dir();
  const std::string out = dir + "/no/such/dir/part.nc";
  RunResult r = run(bin() + " -o " + quote(out) + " " + quote(source_dir() + kSample));
  EXPECT_EQ(r.exit_code, 1);
  EXPECT_EQ(r.err, source_dir() + kSample + ": error: cannot write '" + out +
                       "': No such file or directory\n");
  EXPECT_EQ(entries(dir), 0u);
  fs::remove_all(dir);
}

TEST(OddInput, OutputOnAFullDevice) {
  RunResult r = run(bin() + " -o /dev/full " + quote(source_dir() + kSample));
  EXPECT_EQ(r.exit_code, 1);
  EXPECT_EQ(r.err, source_dir() + kSample +
                       ": error: cannot write '/dev/full': No space left on "
                       "device\n");
  EXPECT_EQ(r.out, "");
  struct stat st {};
  ASSERT_EQ(::lstat("/dev/full", &st), 0);
  EXPECT_TRUE(S_ISCHR(st.st_mode));  // still the device, never renamed over
}

TEST(OddInput, OutputToDevNullAndDevStdoutIsWrittenDirectly) {
  RunResult null = run(bin() + " -o /dev/null " + quote(source_dir() + kSample));
  EXPECT_EQ(null.exit_code, 0) << null.err;
  EXPECT_EQ(null.err, "");
  EXPECT_EQ(null.out, "");
  EXPECT_TRUE(fs::is_character_file("/dev/null"));
  // Standard output is a regular file here (run() redirects it): /dev/stdout must still be
  // written through, not replaced by a renamed temporary file.
  RunResult out = run(bin() + " -o /dev/stdout " + quote(source_dir() + kSample));
  EXPECT_EQ(out.exit_code, 0) << out.err;
  EXPECT_EQ(out.out, expected_program());
  EXPECT_TRUE(fs::is_symlink("/dev/stdout"));
  // And through a pipe.
  RunResult piped = run(bin() + " -o /dev/stdout " + quote(source_dir() + kSample) + " | cat");
  EXPECT_EQ(piped.exit_code, 0) << piped.err;
  EXPECT_EQ(piped.out, expected_program());
}

TEST(OddInput, OutputToANamedPipe) {
  std::string dir = temp_dir();
  const std::string fifo = dir + "/fifo";
  ASSERT_EQ(::mkfifo(fifo.c_str(), 0600), 0);
  RunResult r = run("cat " + quote(fifo) + " & " + bin() + " -o " + quote(fifo) + " " +
                    quote(source_dir() + kSample) + "; rc=$?; wait; exit $rc");
  EXPECT_EQ(r.exit_code, 0) << r.err;
  EXPECT_EQ(r.out, expected_program());
  struct stat st {};
  ASSERT_EQ(::lstat(fifo.c_str(), &st), 0);
  EXPECT_TRUE(S_ISFIFO(st.st_mode));
  EXPECT_EQ(entries(dir), 1u);
  fs::remove_all(dir);
}

TEST(OddInput, TooManyLexicalErrorsStopEarly) {
  std::string dir = temp_dir();
  std::string text;
  // Lines without a major word: the reader's own errors (a statement it can read but not its
  // arguments is delivered to the interpreter instead).
  for (int i = 0; i < 200000; ++i) text += "1,,2\n";
  write_file(dir + "/bad.cl", text);
  RunResult r = run(bin() + " -o " + quote(dir + "/out.nc") + " " + quote(dir + "/bad.cl"));
  EXPECT_EQ(r.exit_code, 1);
  // 100 errors of three lines each, then the note; nothing about lines after the 100th.
  size_t lines = 0;
  for (char c : r.err) lines += c == '\n';
  EXPECT_EQ(lines, 301u);
  const std::string last = dir + "/bad.cl: note: too many errors, stopping\n";
  ASSERT_GT(r.err.size(), last.size());
  EXPECT_EQ(r.err.substr(r.err.size() - last.size()), last);
  EXPECT_EQ(r.err.find("bad.cl:101:"), std::string::npos);
  EXPECT_EQ(entries(dir), 1u);
  fs::remove_all(dir);
}

}  // namespace
}  // namespace clpost::test

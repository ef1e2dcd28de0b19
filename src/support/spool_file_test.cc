#include "support/spool_file.h"

#include <gtest/gtest.h>
#include <stdlib.h>

#include <filesystem>
#include <string>
#include "support/temp_dir_test_util.h"

namespace clpost {
namespace {

namespace fs = std::filesystem;

// A body larger than the buffer, small writes and one larger than the buffer; the insert after
// its first two lines; the file never has a name in the directory.
TEST(SpoolFile, InsertsAfterTheFirstLinesAndLeavesNoFile) {
  TempDir dir("clpost-spool");
  std::string expected_body = "%\nO0001\n";
  SpoolFile spool;
  std::string error;
  ASSERT_TRUE(spool.open(dir.path, error)) << error;
  spool.write("%\nO");
  spool.write("0001\n");
  for (int i = 0; i < 20000; ++i) {
    const std::string line = "N" + std::to_string(i) + " G1 X1.\n";
    spool.write(line);
    expected_body += line;
  }
  const std::string big(100000, 'x');
  spool.write(big);
  expected_body += big;
  EXPECT_EQ(dir.entries(), 0u);  // unnamed while it is written
  StringSink out;
  ASSERT_TRUE(spool.copy_to(out, 2, "(HEADER)\n", error)) << error;
  EXPECT_EQ(out.out, "%\nO0001\n(HEADER)\n" + expected_body.substr(8));
  EXPECT_EQ(dir.entries(), 0u);
}

TEST(SpoolFile, FewerLinesThanAskedPutsTheInsertAtTheEnd) {
  SpoolFile spool;
  std::string error;
  ASSERT_TRUE(spool.open("", error)) << error;
  spool.write("one line\nno end");
  StringSink out;
  ASSERT_TRUE(spool.copy_to(out, 3, "(H)\n", error)) << error;
  EXPECT_EQ(out.out, "one line\nno end(H)\n");
}

TEST(SpoolFile, NoLinesBeforeTheInsertPutsItFirst) {
  SpoolFile spool;
  std::string error;
  ASSERT_TRUE(spool.open("", error)) << error;
  spool.write("A\nB\n");
  StringSink out;
  ASSERT_TRUE(spool.copy_to(out, 0, "(H)\n", error)) << error;
  EXPECT_EQ(out.out, "(H)\nA\nB\n");
}

TEST(SpoolFile, MissingDirectoryIsAnErrorAtOpenAndAtCopy) {
  SpoolFile spool;
  std::string error;
  EXPECT_FALSE(spool.open("/nonexistent-clpost-dir", error));
  EXPECT_EQ(error,
            "cannot create a temporary file in '/nonexistent-clpost-dir': No such file or "
            "directory");
  spool.write("dropped\n");
  StringSink out;
  EXPECT_FALSE(spool.copy_to(out, 1, "(H)\n", error));
  EXPECT_EQ(error, "cannot spool the program: no temporary file");
  EXPECT_EQ(out.out, "");
}

}  // namespace
}  // namespace clpost

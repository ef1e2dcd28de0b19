#include "support/output_file.h"

#include <fcntl.h>
#include <gtest/gtest.h>
#include <sys/stat.h>
#include <unistd.h>

#include <filesystem>
#include <fstream>
#include <memory>
#include <sstream>
#include <string>
#include <thread>
#include <vector>
#include "support/temp_dir_test_util.h"

namespace clpost {
namespace {

namespace fs = std::filesystem;

std::string slurp(const std::string& path) {
  std::ifstream in(path, std::ios::binary);
  std::ostringstream ss;
  ss << in.rdbuf();
  return ss.str();
}

TEST(OutputFile, RegularFileAppearsOnlyAtCommit) {
  TempDir d("clpost-output");
  const std::string path = d.path + "/part.nc";
  OutputFile out;
  std::string err;
  ASSERT_TRUE(out.open(path, err)) << err;
  EXPECT_FALSE(out.direct());
  out.write("G0 X1.\n");
  out.write(std::string(100000, 'x'));  // larger than the buffer: written through
  EXPECT_FALSE(fs::exists(path));
  EXPECT_EQ(d.entries(), 1u);  // the temporary file
  ASSERT_TRUE(out.commit(err)) << err;
  EXPECT_EQ(slurp(path), "G0 X1.\n" + std::string(100000, 'x'));
  EXPECT_EQ(out.bytes(), 100007u);
  EXPECT_EQ(d.entries(), 1u);
  EXPECT_EQ(fs::status(path).permissions(), fs::perms::owner_read | fs::perms::owner_write |
                                                fs::perms::group_read | fs::perms::others_read);
}

TEST(OutputFile, SmallWritesAcrossTheBufferKeepEveryByteInOrder) {
  // Blocks are copied into the 64 KiB buffer inline and flushed when one does not fit: about
  // 300 KB of them cross the buffer's end several times, mid-block.
  TempDir d("clpost-output");
  const std::string path = d.path + "/many.nc";
  OutputFile out;
  std::string err;
  ASSERT_TRUE(out.open(path, err)) << err;
  std::string expect;
  for (int i = 0; i < 20000; ++i) {
    const std::string block = "N" + std::to_string(i) + " G1 X" + std::to_string(i % 97) + ".\n";
    out.write(block);
    expect += block;
  }
  EXPECT_GT(expect.size(), 4u * 65536u);
  EXPECT_EQ(out.bytes(), expect.size());  // what is still in the buffer counts too
  ASSERT_TRUE(out.commit(err)) << err;
  EXPECT_EQ(slurp(path), expect);
  EXPECT_EQ(out.bytes(), expect.size());
}

TEST(OutputFile, AbortLeavesTheOldFileAndNoTemporary) {
  TempDir d("clpost-output");
  const std::string path = d.path + "/part.nc";
  std::ofstream(path) << "good program\n";
  {
    OutputFile out;
    std::string err;
    ASSERT_TRUE(out.open(path, err)) << err;
    out.write("half a program");
    out.abort();
  }
  {
    OutputFile out;  // destroyed without commit
    std::string err;
    ASSERT_TRUE(out.open(path, err)) << err;
    out.write("half a program");
  }
  EXPECT_EQ(slurp(path), "good program\n");
  EXPECT_EQ(d.entries(), 1u);
}

TEST(OutputFile, MissingDirectoryIsAnErrorAtOpen) {
  TempDir d("clpost-output");
  const std::string path = d.path + "/no/such/dir/part.nc";
  OutputFile out;
  std::string err;
  EXPECT_FALSE(out.open(path, err));
  EXPECT_EQ(err, "cannot write '" + path + "': No such file or directory");
  EXPECT_EQ(d.entries(), 0u);
}

TEST(OutputFile, MissingDeviceIsNotCreated) {
  OutputFile out;
  std::string err;
  EXPECT_FALSE(out.open("/dev/clpost-no-such-device", err));
  EXPECT_EQ(err, "cannot open '/dev/clpost-no-such-device': No such file or directory");
  EXPECT_FALSE(fs::exists("/dev/clpost-no-such-device"));
}

TEST(OutputFile, DevNullIsWrittenDirectly) {
  OutputFile out;
  std::string err;
  ASSERT_TRUE(out.open("/dev/null", err)) << err;
  EXPECT_TRUE(out.direct());
  out.write(std::string(300000, 'x'));
  EXPECT_TRUE(out.commit(err)) << err;
  EXPECT_TRUE(fs::is_character_file("/dev/null"));
}

TEST(OutputFile, DevFullIsAWriteErrorSmallOrLarge) {
  for (size_t size : {size_t{10}, size_t{70000}, size_t{300000}}) {
    OutputFile out;
    std::string err;
    ASSERT_TRUE(out.open("/dev/full", err)) << err;
    EXPECT_TRUE(out.direct());
    for (size_t i = 0; i < size; i += 10) out.write("G1 X1. Z2\n");
    EXPECT_FALSE(out.commit(err)) << size;
    EXPECT_EQ(err, "cannot write '/dev/full': No space left on device") << size;
  }
  EXPECT_TRUE(fs::is_character_file("/dev/full"));
}

TEST(OutputFile, PipeIsStreamedNotRenamedOver) {
  TempDir d("clpost-output");
  const std::string fifo = d.path + "/fifo";
  ASSERT_EQ(::mkfifo(fifo.c_str(), 0600), 0);
  const int rd = ::open(fifo.c_str(), O_RDONLY | O_NONBLOCK);
  ASSERT_GE(rd, 0);
  ::fcntl(rd, F_SETFL, 0);  // blocking reads from now on
  std::string received;
  size_t before_commit = 0;
  OutputFile out;
  std::string err;
  ASSERT_TRUE(out.open(fifo, err)) << err;
  EXPECT_TRUE(out.direct());
  // 1 MB is far more than a pipe holds: the writer can only finish if it streams to a reader.
  std::thread reader([&] {
    char buf[4096];
    ssize_t n;
    while ((n = ::read(rd, buf, sizeof buf)) > 0) received.append(buf, static_cast<size_t>(n));
  });
  const std::string block(1000, 'y');
  for (int i = 0; i < 1000; ++i) out.write(block);
  before_commit = out.bytes();
  EXPECT_TRUE(out.commit(err)) << err;
  reader.join();
  ::close(rd);
  EXPECT_EQ(before_commit, 1000000u);
  EXPECT_EQ(received.size(), 1000000u);
  struct stat st {};
  ASSERT_EQ(::stat(fifo.c_str(), &st), 0);
  EXPECT_TRUE(S_ISFIFO(st.st_mode));
  EXPECT_EQ(d.entries(), 1u);
}

TEST(OutputFile, SymlinkToAFileReplacesTheFileAndKeepsTheLink) {
  TempDir d("clpost-output");
  fs::create_directory(d.path + "/real");
  std::ofstream(d.path + "/real/part.nc") << "old\n";
  fs::create_symlink("real/part.nc", d.path + "/link.nc");
  OutputFile out;
  std::string err;
  ASSERT_TRUE(out.open(d.path + "/link.nc", err)) << err;
  EXPECT_FALSE(out.direct());
  out.write("new\n");
  ASSERT_TRUE(out.commit(err)) << err;
  EXPECT_TRUE(fs::is_symlink(d.path + "/link.nc"));
  EXPECT_EQ(slurp(d.path + "/real/part.nc"), "new\n");
  EXPECT_EQ(d.entries(), 2u);
}

// A batch publishes its programs together: finish() writes a program out without publishing
// it; publish_all() makes all of them appear, each with its own result.
TEST(OutputFile, FinishedFilesAppearOnlyWhenPublished) {
  TempDir d("clpost-output");
  std::vector<std::unique_ptr<OutputFile>> outs;
  std::vector<OutputFile*> files;
  std::string err;
  for (const char* name : {"a.nc", "b.nc", "c.nc"}) {
    outs.push_back(std::make_unique<OutputFile>());
    ASSERT_TRUE(outs.back()->open(d.path + "/" + name, err)) << err;
    outs.back()->write(std::string("G0 X1.\n") + name);
    ASSERT_TRUE(outs.back()->finish(err)) << err;
    files.push_back(outs.back().get());
  }
  EXPECT_FALSE(fs::exists(d.path + "/a.nc"));
  EXPECT_FALSE(fs::exists(d.path + "/b.nc"));
  fs::create_directory(d.path + "/c.nc");  // in the way: c's rename fails
  EXPECT_EQ(d.entries(), 4u);              // three temporary files and c.nc/
  std::vector<std::string> errors;
  OutputFile::publish_all(files, errors);
  ASSERT_EQ(errors.size(), 3u);
  EXPECT_EQ(errors[0], "");
  EXPECT_EQ(errors[1], "");
  EXPECT_NE(errors[2].find("cannot write"), std::string::npos) << errors[2];
  EXPECT_EQ(slurp(d.path + "/a.nc"), "G0 X1.\na.nc");
  EXPECT_EQ(slurp(d.path + "/b.nc"), "G0 X1.\nb.nc");
  EXPECT_TRUE(fs::is_directory(d.path + "/c.nc"));
  EXPECT_EQ(d.entries(), 3u);  // the failed one's temporary file is gone
}

TEST(OutputFile, FinishedButNeverPublishedLeavesNothing) {
  TempDir d("clpost-output");
  {
    OutputFile out;
    std::string err;
    ASSERT_TRUE(out.open(d.path + "/a.nc", err)) << err;
    out.write("G0 X1.\n");
    ASSERT_TRUE(out.finish(err)) << err;
  }
  EXPECT_EQ(d.entries(), 0u);
}

}  // namespace
}  // namespace clpost

#include "reader/line_source.h"

#include <gtest/gtest.h>

#include <cstdio>
#include <string>
#include <vector>

namespace clpost::reader {
namespace {

using Status = LineSource::Status;

// A tmpfile() holding `text`, rewound. Closed by the caller.
std::FILE* file_with(const std::string& text) {
  std::FILE* f = std::tmpfile();
  EXPECT_NE(f, nullptr);
  EXPECT_EQ(std::fwrite(text.data(), 1, text.size(), f), text.size());
  std::rewind(f);
  return f;
}

// "number:text" of every line.
std::vector<std::string> all_lines(LineSource& src) {
  std::vector<std::string> out;
  LineSource::Line l;
  for (;;) {
    src.mark();
    Status s = src.next_line(1 << 20, l);
    if (s != Status::kLine) {
      EXPECT_EQ(s, Status::kEnd);
      break;
    }
    out.push_back(std::to_string(l.number) + ":" + std::string(src.text(l)));
  }
  return out;
}

std::vector<std::string> all_lines_both(const std::string& text) {
  LineSource mem(text);
  std::vector<std::string> from_memory = all_lines(mem);
  EXPECT_EQ(mem.bytes_read(), text.size());
  std::FILE* f = file_with(text);
  LineSource file(f);
  std::vector<std::string> from_file = all_lines(file);
  EXPECT_EQ(file.bytes_read(), text.size());
  std::fclose(f);
  EXPECT_EQ(from_memory, from_file);
  return from_memory;
}

TEST(LineSource, LineEnds) {
  using V = std::vector<std::string>;
  EXPECT_EQ(all_lines_both("A\nB\n"), (V{"1:A", "2:B"}));
  EXPECT_EQ(all_lines_both("A\r\nB\r\n"), (V{"1:A", "2:B"}));
  EXPECT_EQ(all_lines_both("A\rB\r"), (V{"1:A", "2:B"}));
  EXPECT_EQ(all_lines_both("A\r\nB\rC\nD"), (V{"1:A", "2:B", "3:C", "4:D"}));
  EXPECT_EQ(all_lines_both("A\n\r\nB"), (V{"1:A", "2:", "3:B"}));
  EXPECT_EQ(all_lines_both("A\n\rB"), (V{"1:A", "2:", "3:B"}));
  EXPECT_EQ(all_lines_both(""), V{});
  EXPECT_EQ(all_lines_both("\n"), V{"1:"});
  EXPECT_EQ(all_lines_both("last line without end"), V{"1:last line without end"});
}

TEST(LineSource, ByteOrderMarkSkipped) {
  using V = std::vector<std::string>;
  EXPECT_EQ(all_lines_both("\xEF\xBB\xBFGOTO/1\nFINI\n"), (V{"1:GOTO/1", "2:FINI"}));
  EXPECT_EQ(all_lines_both("\xEF\xBB\xBF"), V{});
  // Only at the start.
  EXPECT_EQ(all_lines_both("A\n\xEF\xBB\xBF"), (V{"1:A", "2:\xEF\xBB\xBF"}));
}

// CRLF, CR and lines cut by the 64 KiB chunk boundary.
TEST(LineSource, ChunkBoundaries) {
  for (size_t shift = 0; shift < 4; ++shift) {
    std::string text(LineSource::kChunk - 2 - shift, 'x');
    text += "\r\nAB\rCD\r\nEF";
    std::vector<std::string> lines = all_lines_both(text);
    ASSERT_EQ(lines.size(), 4u) << shift;
    EXPECT_EQ(lines[0].size(), 2 + LineSource::kChunk - 2 - shift);
    EXPECT_EQ(lines[1], "2:AB");
    EXPECT_EQ(lines[2], "3:CD");
    EXPECT_EQ(lines[3], "4:EF");
  }
}

TEST(LineSource, TooLongLineIsLeftForSkipLine) {
  LineSource src(std::string_view("0123456789ABCDEF  $ \nnext\n"));
  LineSource::Line l;
  ASSERT_EQ(src.next_line(10, l), Status::kTooLong);
  EXPECT_EQ(l.number, 1u);
  EXPECT_GT(l.size, 10u);
  EXPECT_EQ(src.text(l).substr(0, 11), "0123456789A");
  EXPECT_EQ(src.line_number(), 0u);  // not consumed
  LineTail tail = src.skip_line();
  EXPECT_TRUE(tail.code_continues());
  EXPECT_EQ(src.line_number(), 1u);
  EXPECT_EQ(src.bytes_read(), 21u);
  ASSERT_EQ(src.next_line(10, l), Status::kLine);
  EXPECT_EQ(src.text(l), "next");
  EXPECT_EQ(l.number, 2u);
  // max_len 0: only an empty line fits.
  LineSource empty(std::string_view("\nX\n"));
  EXPECT_EQ(empty.next_line(0, l), Status::kLine);
  EXPECT_EQ(empty.next_line(0, l), Status::kTooLong);
}

// A 10 MB line is skipped without being held in memory.
TEST(LineSource, HugeLineSkippedInBoundedMemory) {
  std::string text = "GOTO/1\n";
  text += std::string(10 << 20, '7');
  text += "$\r\nFINI\n";
  std::FILE* f = file_with(text);
  LineSource src(f);
  LineSource::Line l;
  src.mark();
  ASSERT_EQ(src.next_line(1 << 20, l), Status::kLine);
  src.mark();
  ASSERT_EQ(src.next_line(1 << 20, l), Status::kTooLong);
  EXPECT_TRUE(src.skip_line().code_continues());
  src.mark();
  ASSERT_EQ(src.next_line(1 << 20, l), Status::kLine);
  EXPECT_EQ(src.text(l), "FINI");
  EXPECT_EQ(l.number, 3u);
  EXPECT_EQ(src.bytes_read(), text.size());
  EXPECT_LT(src.capacity(), 3u << 20);
  std::fclose(f);
}

TEST(LineSource, Unread) {
  LineSource src(std::string_view("A\nB\n"));
  LineSource::Line l;
  src.mark();
  ASSERT_EQ(src.next_line(100, l), Status::kLine);
  src.unread(l);
  EXPECT_EQ(src.line_number(), 0u);
  ASSERT_EQ(src.next_line(100, l), Status::kLine);
  EXPECT_EQ(src.text(l), "A");
  EXPECT_EQ(l.number, 1u);
}

// A NUL byte alone does not make a file binary: the line holding it is read (the reader
// reports it at its line and column).
TEST(LineSource, NulByteAloneIsNotBinary) {
  const std::string text("GOTO/1\nGO\0TO\n", 13);
  LineSource src(text);
  LineSource::Line l;
  EXPECT_EQ(src.next_line(100, l), Status::kLine);
  EXPECT_EQ(src.next_line(100, l), Status::kLine);
  EXPECT_EQ(src.text(l), std::string_view("GO\0TO", 5));
  EXPECT_EQ(src.next_line(100, l), Status::kEnd);
}

TEST(LineSource, NulInLaterChunkIsReadAsALine) {
  std::string text;
  while (text.size() < LineSource::kChunk + 100) text += "GOTO/1,2,3\n";
  text += std::string("\0\0\0\n", 4);
  text += "FINI\n";
  std::FILE* f = file_with(text);
  LineSource src(f);
  LineSource::Line l;
  std::string last;
  Status s;
  while ((s = src.next_line(100, l)) == Status::kLine) last = src.text(l);
  EXPECT_EQ(s, Status::kEnd);
  EXPECT_EQ(last, "FINI");
  std::fclose(f);
}

TEST(LineSource, MostlyNulIsBinary) {
  LineSource src(std::string_view("GOTO/1\n\0\0\0", 10));
  LineSource::Line l;
  EXPECT_EQ(src.next_line(100, l), Status::kBinary);
  EXPECT_EQ(src.binary_offset(), 7u);
}

TEST(LineSource, ControlCharactersAreBinary) {
  LineSource src(std::string_view("AB\x01\x02\x03\x04\nX\n"));
  LineSource::Line l;
  EXPECT_EQ(src.next_line(100, l), Status::kBinary);
  EXPECT_EQ(src.binary_offset(), 2u);
  // One stray control character in a text file is not binary.
  LineSource text(std::string_view("GOTO/1,2,3\x01\nFINI\n"));
  EXPECT_EQ(text.next_line(100, l), Status::kLine);
}

}  // namespace
}  // namespace clpost::reader

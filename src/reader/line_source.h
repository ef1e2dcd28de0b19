#pragma once
// Physical lines from a FILE* (read in 64 KiB chunks) or from memory, with LF, CRLF and lone CR
// line ends, a UTF-8 BOM skipped, and binary input detected. Lines are kept in one buffer from
// the last mark() on, so a statement's lines can be viewed together; a line too long to keep is
// skipped by streaming over it (skip_line), so memory never grows with the input.
#include <cstddef>
#include <cstdint>
#include <cstdio>
#include <memory>
#include <string>
#include <string_view>

#include "reader/continuation.h"

namespace clpost::reader {

class LineSource {
 public:
  static constexpr size_t kChunk = 64 * 1024;

  explicit LineSource(std::FILE* in);          // not owned
  explicit LineSource(std::string_view text);  // must outlive the source

  enum class Status {
    kLine,       // a line was read
    kTooLong,    // the next line is longer than max_len; not consumed (see next_line)
    kEnd,        // end of input
    kBinary,     // binary data (decided on the first chunk): binary_offset()
    kReadError,  // read_error()
  };
  // A line, as an offset from the mark (so it survives the buffer moving).
  struct Line {
    size_t offset = 0;
    size_t size = 0;  // without the line terminator
    uint32_t number = 0;
  };

  // Lines before the current position may be dropped from the buffer from now on.
  void mark();
  // Reads the next physical line if it is at most `max_len` bytes long. kTooLong leaves the line
  // unread; `line` then covers its first bytes (more than max_len of them) for a look with
  // text(), and skip_line() consumes it.
  Status next_line(size_t max_len, Line& line);
  // Consumes the rest of the current line without keeping it; tells how it ends.
  LineTail skip_line();
  // For the fast path (plain_line.h), which finds and reads a line in place: the unread bytes
  // held in the buffer (nothing once reading has failed, or before the first next_line()), and
  // consume_line() to take a line of them, `size` bytes and a `terminator` of 1 or 2, as
  // next_line() would have.
  std::string_view buffered() const {
    if (!started_ || failed_ != Status::kLine) return {};
    return std::string_view(data_ + pos_, len_ - pos_);
  }
  Line consume_line(size_t size, size_t terminator) {
    const Line line{pos_ - mark_, size, ++line_no_};
    pos_ += size + terminator;
    return line;
  }
  // Puts back the line just read by next_line().
  void unread(const Line& line);
  // The text of a line read since the mark; valid until the next next_line()/skip_line().
  std::string_view text(const Line& line) const {
    return std::string_view(data_ + mark_ + line.offset, line.size);
  }

  size_t bytes_read() const { return base_ + pos_; }
  uint32_t line_number() const { return line_no_; }
  size_t binary_offset() const { return binary_offset_; }
  // The input's first bytes, as read so far (before any line was read; binary detection).
  std::string_view head() const { return base_ == 0 ? std::string_view(data_, len_) : ""; }
  const std::string& read_error() const { return read_error_; }
  // Bytes held for file input (tests check that memory stays bounded).
  size_t capacity() const { return cap_; }

 private:
  Status refill();
  Status start();
  void check_binary(size_t from, size_t n, bool first_chunk);

  std::FILE* in_ = nullptr;
  std::unique_ptr<char[]> storage_;  // file input only
  size_t cap_ = 0;
  const char* data_ = nullptr;  // storage_ or the text
  size_t text_size_ = 0;        // memory input: the whole text
  size_t len_ = 0;              // bytes available in data_
  size_t pos_ = 0;              // read position in data_
  size_t mark_ = 0;             // data_[mark_, len_) must be kept
  size_t base_ = 0;             // offset in the input of data_[0]
  uint32_t line_no_ = 0;
  bool started_ = false;
  bool eof_ = false;
  Status failed_ = Status::kLine;  // kBinary or kReadError once failed
  size_t binary_offset_ = 0;
  std::string read_error_;
};

}  // namespace clpost::reader

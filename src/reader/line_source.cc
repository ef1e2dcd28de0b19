#include "reader/line_source.h"

#include <algorithm>
#include <cerrno>
#include <cstring>

namespace clpost::reader {

LineSource::LineSource(std::FILE* in) : in_(in) {}

LineSource::LineSource(std::string_view text)
    : data_(text.data()), text_size_(text.size()), eof_(text.empty()) {}

void LineSource::mark() {
  mark_ = pos_;
}

LineSource::Status LineSource::start() {
  started_ = true;
  while (len_ - pos_ < 3 && !eof_) {
    if (Status s = refill(); s != Status::kLine) return s;
  }
  if (len_ >= 3 && std::memcmp(data_, "\xEF\xBB\xBF", 3) == 0) pos_ = mark_ = 3;
  return Status::kLine;
}

LineSource::Status LineSource::refill() {
  if (failed_ != Status::kLine || eof_) return failed_;
  const bool first_chunk = base_ + len_ == 0;
  size_t n = 0;
  if (in_ == nullptr) {
    // Memory input is handed out in chunks too, so that it behaves exactly like a file.
    n = std::min(kChunk, text_size_ - len_);
    len_ += n;
    eof_ = len_ == text_size_;
  } else {
    if (mark_ > 0) {
      std::memmove(storage_.get(), storage_.get() + mark_, len_ - mark_);
      base_ += mark_;
      pos_ -= mark_;
      len_ -= mark_;
      mark_ = 0;
    }
    if (cap_ - len_ < kChunk) {
      size_t cap = std::max(cap_ * 2, len_ + kChunk);
      std::unique_ptr<char[]> bigger(new char[cap]);
      if (len_ > 0) std::memcpy(bigger.get(), storage_.get(), len_);
      storage_ = std::move(bigger);
      cap_ = cap;
      data_ = storage_.get();
    }
    const size_t want = cap_ - len_;
    n = std::fread(storage_.get() + len_, 1, want, in_);
    if (n < want) {
      if (std::ferror(in_)) {
        read_error_ = std::strerror(errno);
        failed_ = Status::kReadError;
        return failed_;
      }
      eof_ = true;
    }
    len_ += n;
  }
  check_binary(len_ - n, n, first_chunk);
  return failed_;
}

void LineSource::check_binary(size_t from, size_t n, bool first_chunk) {
  // Only the first chunk decides: text has next to no control characters (NUL among them), so
  // more than one byte in ten is not text. A stray NUL in a text file is the reader's to
  // report at its line and column.
  if (!first_chunk) return;
  const char* p = data_ + from;
  size_t controls = 0;
  size_t first = 0;
  for (size_t i = 0; i < n; ++i) {
    unsigned char c = static_cast<unsigned char>(p[i]);
    bool control =
        (c < 0x20 && c != '\t' && c != '\n' && c != '\r' && c != '\f' && c != '\v') || c == 0x7f;
    if (control && controls++ == 0) first = i;
  }
  if (controls * 10 > n) {
    // Where the data stops being text: the first NUL, else the first control character.
    const void* nul = std::memchr(p, 0, n);
    binary_offset_ =
        base_ + from + (nul ? static_cast<size_t>(static_cast<const char*>(nul) - p) : first);
    failed_ = Status::kBinary;
  }
}

static bool is_line_end(char c) {
  return c == '\n' || c == '\r';
}

LineSource::Status LineSource::next_line(size_t max_len, Line& line) {
  if (!started_) {
    if (Status s = start(); s != Status::kLine) return s;
  }
  if (failed_ != Status::kLine) return failed_;
  size_t scanned = 0;  // bytes of this line already searched for its end
  for (;;) {
    const char* p = data_ + pos_;
    const size_t avail = len_ - pos_;
    const size_t limit = std::min(avail, max_len + 1);
    size_t i = scanned;
    while (i < limit && !is_line_end(p[i])) ++i;
    scanned = i;
    if (i < limit) {
      if (p[i] == '\r' && i + 1 == avail && !eof_) {
        // CR at the end of the buffer: look at the next byte before deciding CR or CRLF.
        if (Status s = refill(); s != Status::kLine) return s;
        continue;
      }
      const size_t term = (p[i] == '\r' && i + 1 < avail && p[i + 1] == '\n') ? 2 : 1;
      line = Line{pos_ - mark_, i, ++line_no_};
      pos_ += i + term;
      return Status::kLine;
    }
    if (avail > max_len) {
      line = Line{pos_ - mark_, avail, line_no_ + 1};
      return Status::kTooLong;
    }
    if (eof_) {
      if (avail == 0) return Status::kEnd;
      line = Line{pos_ - mark_, avail, ++line_no_};  // last line, no line end
      pos_ = len_;
      return Status::kLine;
    }
    if (Status s = refill(); s != Status::kLine) return s;
  }
}

LineTail LineSource::skip_line() {
  LineTail tail;
  mark_ = pos_;
  for (;;) {
    const char* p = data_ + pos_;
    const size_t avail = len_ - pos_;
    size_t i = 0;
    while (i < avail && !is_line_end(p[i])) ++i;
    tail.feed(std::string_view(p, i));
    pos_ += i;
    mark_ = pos_;  // nothing of this line is kept
    if (i < avail && !(p[i] == '\r' && i + 1 == avail && !eof_)) {
      pos_ += (p[i] == '\r' && i + 1 < avail && p[i + 1] == '\n') ? 2 : 1;
      break;
    }
    if (i == avail && eof_) break;
    if (refill() != Status::kLine) break;
  }
  mark_ = pos_;
  ++line_no_;
  return tail;
}

void LineSource::unread(const Line& line) {
  pos_ = mark_ + line.offset;
  line_no_ = line.number - 1;
}

}  // namespace clpost::reader

#pragma once
// An output that never leaves a partial or failed program behind.
// - A regular file (or a path that does not exist yet) is written to a temporary file in the
//   same directory and renamed over the target by commit(); abort() or destruction removes it.
// - Standard output ("-") and other non-regular targets (devices, pipes) are never renamed
//   over: the text is spooled to an anonymous temporary file and copied to the target by
//   commit(), so an error found late still leaves nothing behind.
#include <string>
#include <string_view>

#include "support/sink.h"

namespace clpost {

class OutputFile : public Sink {
 public:
  OutputFile() = default;
  ~OutputFile() override;
  OutputFile(const OutputFile&) = delete;
  OutputFile& operator=(const OutputFile&) = delete;

  // "-" is standard output. Returns false with a message in `error`.
  bool open(const std::string& path, std::string& error);
  void write(std::string_view text) override;
  // Flushes and publishes the output. Returns false (and leaves nothing) on a write error.
  bool commit(std::string& error);
  // Drops everything written so far.
  void abort();

  size_t bytes() const { return bytes_; }

 private:
  bool flush_buffer();

  std::string path_;      // target
  std::string temp_;      // temporary path (regular targets)
  int fd_ = -1;           // temporary file
  bool spooled_ = false;  // target is stdout or a device: copy at commit
  bool failed_ = false;
  int errno_ = 0;
  size_t bytes_ = 0;
  std::string buffer_;
};

}  // namespace clpost

#pragma once
// Text that waits on disk until what must be written before it is known: a program's body while
// its header (the tool list and the cycle time, known at the end) is still to come. Memory stays
// bounded (one 64 KiB buffer) whatever the length of the program.
//
// The file never has a name that outlives it: it is created unnamed (O_TMPFILE) in the directory
// given, or named and unlinked at once where the file system cannot, so nothing is left behind
// on any path out (success, an error, a crash) and files spooled at once (a batch) never meet.
#include <memory>
#include <string>
#include <string_view>

#include "support/sink.h"

namespace clpost {

// Writes all of `data` to `fd` (retrying short writes and EINTR); false with errno in `err`.
bool write_all(int fd, const char* data, size_t size, int& err);
// An anonymous temporary file open for reading and writing in `dir` (empty: the system's
// temporary directory): its descriptor in `fd`, else false with the reason in `error`.
bool open_anonymous_temp(const std::string& dir, int& fd, std::string& error);

class SpoolFile : public Sink {
 public:
  SpoolFile() = default;
  ~SpoolFile() override;
  SpoolFile(const SpoolFile&) = delete;
  SpoolFile& operator=(const SpoolFile&) = delete;

  // See open_anonymous_temp(). Until open() succeeds, text written is dropped.
  bool open(const std::string& dir, std::string& error);
  // Writes everything spooled to `out`, with `insert` after its first `lines` lines (at the end
  // when there are fewer), and closes the file. False, with the reason in `error`, when the
  // spool could not be written or read back (`out` may then have part of it).
  bool copy_to(Sink& out, size_t lines, std::string_view insert, std::string& error);

 private:
  void overflow(std::string_view text) override;
  bool flush_buffer();
  void fail(int err);
  void close_fd();

  int fd_ = -1;
  int errno_ = 0;  // the first error writing the spool
  std::unique_ptr<char[]> buffer_;
};

}  // namespace clpost

#pragma once
// An output that never leaves a partial or failed program behind in a file.
// - A regular file (or a path that does not exist yet) is written to a temporary file in the
//   same directory and renamed over the target by commit(); abort() or destruction removes it.
//   A symbolic link to a regular file is followed: its target is replaced, the link stays.
// - Standard output ("-") is spooled to an anonymous temporary file and copied to standard
//   output by commit(), so a program with an error found late puts nothing on standard output.
// - A device, a pipe or anything else that is not a regular file (`/dev/null`, `/dev/full`,
//   `/dev/stdout`, a FIFO, a serial port; every path under /dev/ and /proc/) is never renamed
//   over: it is opened and written directly, streaming in 64 KiB blocks, so memory stays bounded.
//   What was written before an error cannot be taken back; write errors (ENOSPC on /dev/full)
//   are reported by write() failing silently and commit() returning false.
#include <memory>
#include <string>
#include <string_view>
#include <vector>

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
  // Flushes and publishes the output. Returns false (and leaves nothing, except what was already
  // streamed to a device) on a write error. The same as finish() then publish().
  bool commit(std::string& error);
  // commit() in two steps, for outputs published together (publish_all): finish() writes out
  // everything still buffered and keeps the temporary file open, unpublished; publish() makes it
  // durable (fsync) and renames it over its target. A device or standard output is done with at
  // finish(); publish() has nothing left to do for it.
  bool finish(std::string& error);
  bool publish(std::string& error);
  // Publishes many finished outputs (a batch): their data goes to the disk with one syncfs()
  // rather than one journal commit per file, then each is published as publish() does (its
  // fsync, now cheap, still reports that file's own write errors). Nothing appears under its
  // name before its bytes are on the disk. `errors[i]` is empty or says why files[i] failed.
  static void publish_all(const std::vector<OutputFile*>& files, std::vector<std::string>& errors);
  // Drops everything written so far (a device keeps what it was already sent).
  void abort();

  // The directory where a temporary file beside `path` belongs (the directory of the file it
  // names, a symbolic link followed); empty for standard output ("-"), a device or anything
  // else that is not a regular file (the system's temporary directory then).
  static std::string directory_beside(const std::string& path);

  // Bytes written so far (flushed or buffered).
  size_t bytes() const { return bytes_ + buffered(); }
  // The target is written directly (a device or a pipe), not through a temporary file.
  bool direct() const { return mode_ == Mode::kDirect; }

 private:
  enum class Mode { kClosed, kAtomic, kSpool, kDirect };
  // Sink: the buffer is full, or the text is larger than it, or writing is over (closed or
  // failed: no buffer then, and the text is dropped).
  void overflow(std::string_view text) override;
  size_t buffered() const {
    return next_ == nullptr ? 0 : static_cast<size_t>(next_ - buffer_.get());
  }
  // Writes out the buffer; false (and failed_, no buffer any more) on a write error.
  bool flush_buffer();
  bool open_fd(const std::string& path, std::string& error);
  // Writing went wrong: errno_ says why; later text is dropped.
  void fail(int err);
  void close_fd();
  std::string target_name() const;

  std::string path_;    // target as given (messages)
  std::string target_;  // kAtomic: the file renamed over (a symbolic link resolved)
  std::string temp_;    // kAtomic: temporary path
  Mode mode_ = Mode::kClosed;
  int fd_ = -1;  // temporary file, spool, or the device
  bool owns_fd_ = false;
  bool failed_ = false;
  int errno_ = 0;
  size_t bytes_ = 0;  // written out of the buffer (or past it)
  // Sink's next_ and limit_ point into it while the file is open and writing has not failed.
  std::unique_ptr<char[]> buffer_;
};

}  // namespace clpost

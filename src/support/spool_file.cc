#include "support/spool_file.h"

#include <fcntl.h>
#include <fmt/format.h>
#include <unistd.h>

#include <cerrno>
#include <cstdio>
#include <cstring>

namespace clpost {

namespace {
constexpr size_t kBufferSize = 1 << 16;

// `dir`/.clpost-spool.XXXXXX, unlinked as soon as it is open.
bool open_unlinked(const std::string& dir, int& fd, int& err) {
  std::string name = dir + "/.clpost-spool.XXXXXX";
  fd = ::mkstemp(name.data());
  if (fd < 0) {
    err = errno;
    return false;
  }
  ::unlink(name.c_str());
  return true;
}
}  // namespace

bool write_all(int fd, const char* data, size_t size, int& err) {
  while (size > 0) {
    ssize_t n = ::write(fd, data, size);
    if (n < 0) {
      if (errno == EINTR) continue;
      err = errno;
      return false;
    }
    data += n;
    size -= static_cast<size_t>(n);
  }
  return true;
}

bool open_anonymous_temp(const std::string& dir, int& fd, std::string& error) {
  int err = 0;
  if (dir.empty()) {
    std::FILE* tmp = std::tmpfile();
    fd = tmp == nullptr ? -1 : ::dup(fileno(tmp));
    err = errno;
    if (tmp != nullptr) std::fclose(tmp);  // the anonymous file lives on through fd
  } else {
    fd = ::open(dir.c_str(), O_TMPFILE | O_RDWR | O_CLOEXEC, 0600);
    err = errno;
    // A file system without O_TMPFILE: a named file, unlinked at once.
    if (fd < 0 && (err == EOPNOTSUPP || err == EISDIR || err == EINVAL))
      open_unlinked(dir, fd, err);
  }
  if (fd < 0) {
    error = dir.empty() ? fmt::format("cannot create a temporary file: {}", std::strerror(err))
                        : fmt::format("cannot create a temporary file in '{}': {}", dir,
                                      std::strerror(err));
    return false;
  }
  return true;
}

SpoolFile::~SpoolFile() {
  close_fd();
}

bool SpoolFile::open(const std::string& dir, std::string& error) {
  close_fd();
  if (!open_anonymous_temp(dir, fd_, error)) return false;
  errno_ = 0;
  buffer_ = std::make_unique<char[]>(kBufferSize);
  next_ = buffer_.get();
  limit_ = next_ + kBufferSize;
  return true;
}

void SpoolFile::close_fd() {
  if (fd_ >= 0) ::close(fd_);
  fd_ = -1;
  next_ = limit_ = nullptr;
  buffer_.reset();
}

void SpoolFile::fail(int err) {
  if (errno_ == 0) errno_ = err;
  next_ = limit_ = nullptr;  // later text goes to overflow() and is dropped
}

bool SpoolFile::flush_buffer() {
  if (next_ == nullptr) return errno_ == 0 && fd_ >= 0;
  const size_t n = static_cast<size_t>(next_ - buffer_.get());
  next_ = buffer_.get();
  int err = 0;
  if (!write_all(fd_, buffer_.get(), n, err)) {
    fail(err);
    return false;
  }
  return true;
}

void SpoolFile::overflow(std::string_view text) {
  if (next_ == nullptr) return;  // not open, or failed
  if (!flush_buffer()) return;
  int err = 0;
  if (text.size() >= kBufferSize) {
    if (!write_all(fd_, text.data(), text.size(), err)) fail(err);
    return;
  }
  std::memcpy(next_, text.data(), text.size());
  next_ += text.size();
}

bool SpoolFile::copy_to(Sink& out, size_t lines, std::string_view insert, std::string& error) {
  if (fd_ < 0) {
    error = "cannot spool the program: no temporary file";
    return false;
  }
  bool ok = flush_buffer();
  if (ok && ::lseek(fd_, 0, SEEK_SET) != 0) {
    fail(errno);
    ok = false;
  }
  bool inserted = false;
  while (ok) {
    const ssize_t n = ::read(fd_, buffer_.get(), kBufferSize);
    if (n < 0 && errno == EINTR) continue;
    if (n < 0) {
      fail(errno);
      ok = false;
    }
    if (n <= 0) break;
    std::string_view block(buffer_.get(), static_cast<size_t>(n));
    // The first `lines` lines, then the insert, then the rest as it comes.
    while (!inserted && !block.empty()) {
      if (lines == 0) {
        out.write(insert);
        inserted = true;
        break;
      }
      const size_t eol = block.find('\n');
      const size_t take = eol == std::string_view::npos ? block.size() : eol + 1;
      out.write(block.substr(0, take));
      block.remove_prefix(take);
      if (eol != std::string_view::npos) --lines;
    }
    out.write(block);
  }
  if (ok && !inserted) out.write(insert);
  if (!ok) error = fmt::format("cannot spool the program: {}", std::strerror(errno_));
  close_fd();
  return ok;
}

}  // namespace clpost

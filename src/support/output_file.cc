#include "support/output_file.h"

#include <fcntl.h>
#include <fmt/format.h>
#include <sys/stat.h>
#include <unistd.h>

#include <cerrno>
#include <cstdio>
#include <cstdlib>
#include <cstring>
#include <filesystem>

#include "support/spool_file.h"

namespace clpost {

namespace {
constexpr size_t kBufferSize = 1 << 16;

// Paths that are never renamed over, whatever stat() says of them: /dev/stdout, for one, is a
// link to whatever standard output is, a regular file included.
bool is_system_path(const std::string& path) {
  return path.starts_with("/dev/") || path.starts_with("/proc/");
}

// The file a path names: a symbolic link is followed, so that the file it points to is
// replaced, not the link.
std::string link_target(const std::string& path) {
  std::string target = path;
  struct stat st {};
  if (::lstat(path.c_str(), &st) == 0 && S_ISLNK(st.st_mode)) {
    if (char* real = ::realpath(path.c_str(), nullptr)) {
      target = real;
      std::free(real);
    }
  }
  return target;
}

// A device, or anything else not a regular file, is opened for writing but never created: a
// device that is not there is an error, not a new file in /dev.
bool open_existing(const std::string& path, int& fd, std::string& error) {
  fd = ::open(path.c_str(), O_WRONLY | O_NOCTTY | O_CLOEXEC);
  if (fd < 0) {
    error = fmt::format("cannot open '{}': {}", path, std::strerror(errno));
    return false;
  }
  return true;
}

// A temporary file in the directory of `target`, to be renamed over it: its descriptor in `fd`,
// its path in `temp`. Errors name the path as given.
bool create_temp_beside(const std::string& target, const std::string& path, int& fd,
                        std::string& temp, std::string& error) {
  std::filesystem::path p(target);
  std::string dir = p.has_parent_path() ? p.parent_path().string() : ".";
  temp = dir + "/." + p.filename().string() + ".XXXXXX";
  fd = ::mkstemp(temp.data());
  if (fd < 0) {
    error = fmt::format("cannot write '{}': {}", path, std::strerror(errno));
    return false;
  }
  return true;
}
}  // namespace

OutputFile::~OutputFile() {
  abort();
}

std::string OutputFile::directory_beside(const std::string& path) {
  if (path == "-" || is_system_path(path)) return {};
  struct stat st {};
  const std::string target = link_target(path);
  if (::stat(target.c_str(), &st) == 0 && !S_ISREG(st.st_mode)) return {};
  std::filesystem::path p(target);
  return p.has_parent_path() ? p.parent_path().string() : ".";
}

bool OutputFile::open(const std::string& path, std::string& error) {
  if (!open_fd(path, error)) return false;
  next_ = buffer_.get();
  limit_ = next_ + kBufferSize;
  return true;
}

bool OutputFile::open_fd(const std::string& path, std::string& error) {
  abort();
  path_ = path;
  target_.clear();
  failed_ = false;
  errno_ = 0;
  bytes_ = 0;
  if (!buffer_) buffer_ = std::make_unique_for_overwrite<char[]>(kBufferSize);
  if (path == "-") {
    // Standard output is spooled to an anonymous temporary file until commit().
    if (!open_anonymous_temp("", fd_, error)) return false;
    owns_fd_ = true;
    mode_ = Mode::kSpool;
    return true;
  }
  if (path == "/dev/stdout" || path == "/dev/stderr") {
    fd_ = path == "/dev/stdout" ? STDOUT_FILENO : STDERR_FILENO;
    owns_fd_ = false;
    mode_ = Mode::kDirect;
    return true;
  }
  const std::string target = link_target(path);
  struct stat st {};
  const bool exists = ::stat(target.c_str(), &st) == 0;
  if ((exists && !S_ISREG(st.st_mode)) || is_system_path(path) || is_system_path(target)) {
    if (!open_existing(path, fd_, error)) return false;
    owns_fd_ = true;
    mode_ = Mode::kDirect;
    return true;
  }
  std::string temp;
  if (!create_temp_beside(target, path, fd_, temp, error)) return false;
  owns_fd_ = true;
  mode_ = Mode::kAtomic;
  temp_ = temp;
  target_ = target;
  // mkstemp makes 0600 files; give the program the permissions of the file it replaces, or the
  // usual ones for a new file.
  ::fchmod(fd_, exists ? (st.st_mode & 07777) : 0644);
  return true;
}

bool OutputFile::flush_buffer() {
  if (failed_) return false;
  const size_t n = buffered();
  if (n == 0) return true;
  next_ = buffer_.get();
  if (!write_all(fd_, buffer_.get(), n, errno_)) {
    fail(errno_);
    return false;
  }
  bytes_ += n;
  return true;
}

void OutputFile::fail(int err) {
  failed_ = true;
  errno_ = err;
  next_ = limit_ = nullptr;
}

void OutputFile::overflow(std::string_view text) {
  if (next_ == nullptr || !flush_buffer()) return;  // closed or failed: nothing more is written
  if (text.size() >= kBufferSize) {
    if (!write_all(fd_, text.data(), text.size(), errno_)) return fail(errno_);
    bytes_ += text.size();
    return;
  }
  std::memcpy(next_, text.data(), text.size());
  next_ += text.size();
}

void OutputFile::close_fd() {
  next_ = limit_ = nullptr;  // nothing more is written
  if (fd_ >= 0 && owns_fd_) ::close(fd_);
  fd_ = -1;
  owns_fd_ = false;
}

std::string OutputFile::target_name() const {
  return mode_ == Mode::kSpool ? "standard output" : "'" + path_ + "'";
}

bool OutputFile::commit(std::string& error) {
  return finish(error) && publish(error);
}

bool OutputFile::finish(std::string& error) {
  if (fd_ < 0) {
    error = "output is not open";
    return false;
  }
  const std::string target = target_name();
  if (!flush_buffer()) {
    error = fmt::format("cannot write {}: {}", target, std::strerror(errno_));
    abort();
    return false;
  }
  if (mode_ == Mode::kDirect) {
    bool ok = true;
    if (owns_fd_) {
      ok = ::close(fd_) == 0 || errno == EINTR;
      if (!ok) errno_ = errno;
      fd_ = -1;
      owns_fd_ = false;
    }
    mode_ = Mode::kClosed;
    if (!ok) error = fmt::format("cannot write {}: {}", target, std::strerror(errno_));
    return ok;
  }
  if (mode_ == Mode::kSpool) {
    bool ok = ::lseek(fd_, 0, SEEK_SET) == 0;
    if (!ok) errno_ = errno;
    char buf[kBufferSize];
    while (ok) {
      ssize_t n = ::read(fd_, buf, sizeof buf);
      if (n < 0 && errno == EINTR) continue;
      if (n <= 0) {
        ok = n == 0;
        if (!ok) errno_ = errno;
        break;
      }
      ok = write_all(STDOUT_FILENO, buf, static_cast<size_t>(n), errno_);
    }
    close_fd();
    mode_ = Mode::kClosed;
    if (!ok) error = fmt::format("cannot write {}: {}", target, std::strerror(errno_));
    return ok;
  }
  // kAtomic: written out; the buffer is not needed any more.
  next_ = limit_ = nullptr;
  buffer_.reset();
  return true;
}

bool OutputFile::publish(std::string& error) {
  if (mode_ != Mode::kAtomic) return true;  // finish() did it all, or there is nothing
  const std::string target = target_name();
  if (!flush_buffer()) {  // publish() without finish()
    error = fmt::format("cannot write {}: {}", target, std::strerror(errno_));
    abort();
    return false;
  }
  // The data must be on the disk before the rename makes it the program: after a crash the
  // name holds the old program or the whole new one, never a part of it.
  if (::fsync(fd_) != 0 && errno != EINVAL) {
    error = fmt::format("cannot write {}: {}", target, std::strerror(errno));
    abort();
    return false;
  }
  const bool closed = ::close(fd_) == 0 || errno == EINTR;
  const int close_errno = errno;
  fd_ = -1;
  owns_fd_ = false;
  if (!closed) {
    error = fmt::format("cannot write {}: {}", target, std::strerror(close_errno));
    abort();
    return false;
  }
  if (::rename(temp_.c_str(), target_.c_str()) != 0) {
    error = fmt::format("cannot write {}: {}", target, std::strerror(errno));
    abort();
    return false;
  }
  temp_.clear();
  mode_ = Mode::kClosed;
  return true;
}

void OutputFile::publish_all(const std::vector<OutputFile*>& files,
                             std::vector<std::string>& errors) {
  errors.assign(files.size(), std::string());
  // One fsync per file costs one journal commit (and disk cache flush) per file: for a batch of
  // small programs that is most of the time, and it serialises the workers on the disk. One
  // syncfs() writes all of them at once; its result is not needed, as each file's fsync below
  // still runs (cheap now that nothing is left to write) and reports that file's own errors
  // (a writeback error is kept per file until an fsync of a descriptor opened before it takes
  // it). syncfs also writes other programs' dirty data on the same filesystem; a batch only
  // waits for that in its publishing thread, never in the workers (see batch.cc).
  for (OutputFile* f : files) {
    if (files.size() > 1 && f->mode_ == Mode::kAtomic && f->fd_ >= 0) {
      ::syncfs(f->fd_);
      break;
    }
  }
  for (size_t i = 0; i < files.size(); ++i) files[i]->publish(errors[i]);
}

void OutputFile::abort() {
  close_fd();
  if (!temp_.empty()) ::unlink(temp_.c_str());
  temp_.clear();
  next_ = limit_ = nullptr;
  mode_ = Mode::kClosed;
}

}  // namespace clpost

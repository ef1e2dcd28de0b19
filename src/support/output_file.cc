#include "support/output_file.h"

#include <fcntl.h>
#include <fmt/format.h>
#include <sys/stat.h>
#include <unistd.h>

#include <cerrno>
#include <cstdio>
#include <cstring>
#include <filesystem>

namespace clpost {

namespace {
constexpr size_t kBufferSize = 1 << 16;

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
}  // namespace

OutputFile::~OutputFile() {
  abort();
}

bool OutputFile::open(const std::string& path, std::string& error) {
  abort();
  path_ = path;
  failed_ = false;
  bytes_ = 0;
  buffer_.clear();
  buffer_.reserve(kBufferSize);
  struct stat st {};
  bool exists = path != "-" && ::stat(path.c_str(), &st) == 0;
  if (path == "-" || (exists && !S_ISREG(st.st_mode))) {
    spooled_ = true;
    std::FILE* tmp = std::tmpfile();
    if (tmp == nullptr) {
      error = fmt::format("cannot create a temporary file: {}", std::strerror(errno));
      return false;
    }
    fd_ = ::dup(fileno(tmp));
    std::fclose(tmp);  // the anonymous file lives on through fd_
    return fd_ >= 0;
  }
  spooled_ = false;
  std::filesystem::path p(path);
  std::string dir = p.has_parent_path() ? p.parent_path().string() : ".";
  std::string templ = dir + "/." + p.filename().string() + ".XXXXXX";
  fd_ = ::mkstemp(templ.data());
  if (fd_ < 0) {
    error = fmt::format("cannot write '{}': {}", path, std::strerror(errno));
    return false;
  }
  temp_ = templ;
  // mkstemp makes 0600 files; give the program the permissions of the file it replaces, or the
  // usual ones for a new file.
  ::fchmod(fd_, exists ? (st.st_mode & 07777) : 0644);
  return true;
}

bool OutputFile::flush_buffer() {
  if (failed_ || buffer_.empty()) {
    buffer_.clear();
    return !failed_;
  }
  if (!write_all(fd_, buffer_.data(), buffer_.size(), errno_)) failed_ = true;
  buffer_.clear();
  return !failed_;
}

void OutputFile::write(std::string_view text) {
  if (fd_ < 0) return;
  bytes_ += text.size();
  if (buffer_.size() + text.size() > kBufferSize) flush_buffer();
  if (text.size() >= kBufferSize) {
    if (!failed_ && !write_all(fd_, text.data(), text.size(), errno_)) failed_ = true;
    return;
  }
  buffer_.append(text);
}

bool OutputFile::commit(std::string& error) {
  if (fd_ < 0) {
    error = "output is not open";
    return false;
  }
  std::string target = path_ == "-" ? "standard output" : "'" + path_ + "'";
  if (!flush_buffer()) {
    error = fmt::format("cannot write {}: {}", target, std::strerror(errno_));
    abort();
    return false;
  }
  if (spooled_) {
    int out = path_ == "-" ? STDOUT_FILENO : ::open(path_.c_str(), O_WRONLY | O_APPEND);
    if (out < 0) {
      error = fmt::format("cannot open {}: {}", target, std::strerror(errno));
      abort();
      return false;
    }
    bool ok = ::lseek(fd_, 0, SEEK_SET) == 0;
    char buf[kBufferSize];
    while (ok) {
      ssize_t n = ::read(fd_, buf, sizeof buf);
      if (n < 0 && errno == EINTR) continue;
      if (n <= 0) {
        ok = n == 0;
        if (!ok) errno_ = errno;
        break;
      }
      ok = write_all(out, buf, static_cast<size_t>(n), errno_);
    }
    if (path_ != "-") ::close(out);
    ::close(fd_);
    fd_ = -1;
    if (!ok) error = fmt::format("cannot write {}: {}", target, std::strerror(errno_));
    return ok;
  }
  if (::fsync(fd_) != 0 && errno != EINVAL) {
    error = fmt::format("cannot write {}: {}", target, std::strerror(errno));
    abort();
    return false;
  }
  ::close(fd_);
  fd_ = -1;
  if (::rename(temp_.c_str(), path_.c_str()) != 0) {
    error = fmt::format("cannot write {}: {}", target, std::strerror(errno));
    ::unlink(temp_.c_str());
    temp_.clear();
    return false;
  }
  temp_.clear();
  return true;
}

void OutputFile::abort() {
  if (fd_ >= 0) ::close(fd_);
  fd_ = -1;
  if (!temp_.empty()) ::unlink(temp_.c_str());
  temp_.clear();
  buffer_.clear();
}

}  // namespace clpost

#pragma once
// A fresh directory under the system's temporary one for a test, removed with everything in it
// when the test ends.
#include <stdlib.h>

#include <filesystem>
#include <iterator>
#include <string>

namespace clpost {

struct TempDir {
  // `prefix` names it ("clpost-output" gives /tmp/clpost-output-XXXXXX).
  explicit TempDir(const std::string& prefix) {
    std::string templ = (std::filesystem::temp_directory_path() / (prefix + "-XXXXXX")).string();
    path = ::mkdtemp(templ.data());
  }
  ~TempDir() { std::filesystem::remove_all(path); }
  TempDir(const TempDir&) = delete;
  TempDir& operator=(const TempDir&) = delete;
  // How many files and directories it holds.
  size_t entries() const {
    return static_cast<size_t>(std::distance(std::filesystem::directory_iterator(path),
                                             std::filesystem::directory_iterator()));
  }
  std::string path;
};

}  // namespace clpost

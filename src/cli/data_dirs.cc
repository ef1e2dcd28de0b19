#include "cli/data_dirs.h"

#include <cstdlib>
#include <filesystem>

#ifndef CLPOST_SOURCE_DIR
#define CLPOST_SOURCE_DIR "."
#endif

namespace clpost {

std::vector<std::string> data_dirs() {
  namespace fs = std::filesystem;
  std::vector<std::string> dirs;
  if (const char* env = std::getenv("CLPOST_DATA_DIR"); env != nullptr && *env != '\0')
    dirs.emplace_back(env);
  std::error_code ec;
  fs::path exe = fs::read_symlink("/proc/self/exe", ec);
  if (!ec) {
    fs::path share = exe.parent_path().parent_path() / "share" / "clpost";
    if (fs::exists(share / "machines", ec)) dirs.push_back(share.string());
  }
  dirs.emplace_back(CLPOST_SOURCE_DIR);
  return dirs;
}

}  // namespace clpost

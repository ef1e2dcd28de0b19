#include "support/input_file.h"

#include <cerrno>
#include <cstring>

namespace clpost {

InputFile::~InputFile() {
  if (f_ != nullptr && f_ != stdin) std::fclose(f_);
}

bool InputFile::open(const std::string& path, std::string& error) {
  f_ = path == "-" ? stdin : std::fopen(path.c_str(), "rb");
  if (f_ == nullptr) error = std::string("cannot open: ") + std::strerror(errno);
  return f_ != nullptr;
}

std::string InputFile::read_all() {
  std::string text;
  char buf[65536];
  for (size_t n; (n = std::fread(buf, 1, sizeof buf, f_)) > 0;) text.append(buf, n);
  return text;
}

}  // namespace clpost

#pragma once
// An input opened for reading: a path, or "-" for standard input. Closed (unless it is standard
// input) when it goes out of scope, on every return path.
#include <cstdio>
#include <string>

namespace clpost {

class InputFile {
 public:
  InputFile() = default;
  ~InputFile();
  InputFile(const InputFile&) = delete;
  InputFile& operator=(const InputFile&) = delete;

  // False with "cannot open: <reason>" in `error`.
  bool open(const std::string& path, std::string& error);
  std::FILE* get() const { return f_; }
  // The whole input as text (the plan JSON: small).
  std::string read_all();

 private:
  std::FILE* f_ = nullptr;
};

}  // namespace clpost

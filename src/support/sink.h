#pragma once
// Where generated text goes: a file being written atomically, or a string in tests.
#include <string>
#include <string_view>

namespace clpost {

class Sink {
 public:
  virtual ~Sink() = default;
  virtual void write(std::string_view text) = 0;
};

class StringSink : public Sink {
 public:
  void write(std::string_view text) override { out.append(text); }
  std::string out;
};

}  // namespace clpost

#pragma once
// Where generated text goes: a file being written atomically, or a string in tests.
//
// write() is the hot path (one call per NC block): when the sink has a buffer with room, the
// text is copied straight into it, inline, without a virtual call; otherwise (no buffer, a full
// one, or text too long) the sink's overflow() takes it.
#include <cstring>
#include <string>
#include <string_view>

namespace clpost {

class Sink {
 public:
  virtual ~Sink() = default;
  void write(std::string_view text) {
    if (text.size() <= static_cast<size_t>(limit_ - next_)) {
      if (!text.empty()) std::memcpy(next_, text.data(), text.size());
      next_ += text.size();
      return;
    }
    overflow(text);
  }

 protected:
  // Takes `text` when the buffer [next_, limit_) has no room for it; a sink without a buffer
  // (both null) gets every non-empty text here.
  virtual void overflow(std::string_view text) = 0;
  char* next_ = nullptr;
  char* limit_ = nullptr;
};

class StringSink : public Sink {
 public:
  std::string out;

 private:
  void overflow(std::string_view text) override { out.append(text); }
};

}  // namespace clpost

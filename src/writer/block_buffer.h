#pragma once
// The NC block being built: a growable character buffer written through a pointer. The writer
// asks for room once per word and writes its characters straight in, without the per-append
// checks of std::string (this is the hot path: every GOTO becomes a block).
#include <cstddef>
#include <cstring>
#include <memory>
#include <string_view>

namespace clpost {

class BlockBuffer {
 public:
  // Where to write `n` more characters (valid until the next call that changes the buffer).
  char* room(size_t n) {
    if (capacity_ - size_ < n) grow(n);
    return data_.get() + size_;
  }
  // The characters up to `end` (a pointer from room()) belong to the buffer now.
  void commit(const char* end) { size_ = static_cast<size_t>(end - data_.get()); }

  void append(std::string_view s) {
    if (s.empty()) return;  // memcpy to a buffer not yet allocated (null) is undefined
    std::memcpy(room(s.size()), s.data(), s.size());
    size_ += s.size();
  }
  void push_back(char c) {
    *room(1) = c;
    ++size_;
  }
  void clear() { size_ = 0; }
  // Takes out the first `n` characters.
  void erase_front(size_t n) {
    std::memmove(data_.get(), data_.get() + n, size_ - n);
    size_ -= n;
  }

  size_t size() const { return size_; }
  std::string_view view() const { return {data_.get(), size_}; }

 private:
  void grow(size_t n) {
    size_t capacity = capacity_ < 256 ? 256 : capacity_ * 2;
    while (capacity - size_ < n) capacity *= 2;
    auto data = std::make_unique_for_overwrite<char[]>(capacity);
    if (size_ > 0) std::memcpy(data.get(), data_.get(), size_);
    data_ = std::move(data);
    capacity_ = capacity;
  }

  std::unique_ptr<char[]> data_;
  size_t size_ = 0;
  size_t capacity_ = 0;
};

}  // namespace clpost

#pragma once
// A first-in first-out queue in one array that grows when full, its elements indexed from the
// front: the window a stream is compared in (verify/path_verify.cc), without std::deque's
// allocation and release of a block every few elements as the window slides.
#include <algorithm>
#include <cstddef>
#include <type_traits>
#include <vector>

namespace clpost {

template <typename T>
class Ring {
  // A popped element stays in the array until it is written over: nothing to destroy.
  static_assert(std::is_trivially_copyable_v<T>, "Ring holds plain values");

 public:
  // `usual`: the most elements it usually holds (a window's length; 0: not known). Growing, it
  // stops there once before it doubles on, so a full window takes no more room than it needs.
  explicit Ring(size_t usual = 0) : usual_(usual) {}
  bool empty() const { return size_ == 0; }
  size_t size() const { return size_; }
  T& operator[](size_t i) { return items_[place(i)]; }
  const T& operator[](size_t i) const { return items_[place(i)]; }
  T& front() { return items_[head_]; }
  const T& front() const { return items_[head_]; }
  void push_back(const T& v) {
    if (size_ == items_.size()) grow();
    items_[place(size_++)] = v;
  }
  void pop_front() {
    if (++head_ == items_.size()) head_ = 0;
    --size_;
  }

 private:
  size_t place(size_t i) const {
    const size_t at = head_ + i;
    return at < items_.size() ? at : at - items_.size();
  }
  void grow() {
    size_t room = std::max<size_t>(16, 2 * items_.size());
    if (items_.size() < usual_) room = std::min(room, usual_);
    std::vector<T> bigger(room);
    for (size_t i = 0; i < size_; ++i) bigger[i] = (*this)[i];
    items_.swap(bigger);
    head_ = 0;
  }
  size_t usual_;
  std::vector<T> items_;
  size_t head_ = 0;
  size_t size_ = 0;
};

}  // namespace clpost

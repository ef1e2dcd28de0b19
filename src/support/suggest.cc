#include "support/suggest.h"

#include <fmt/format.h>

#include <algorithm>

namespace clpost {

// Nothing is computed when the lengths alone say the distance is `limit` or more, and the rows
// stop as soon as every cell has reached it (a key of garbage costs a few rows per name, not the
// whole table).
size_t edit_distance(std::string_view a, std::string_view b, size_t limit) {
  const size_t gap = a.size() > b.size() ? a.size() - b.size() : b.size() - a.size();
  if (gap >= limit) return limit;
  // Two rows of b.size() + 1: on the stack for the short names compared here.
  constexpr size_t kStackRow = 64;
  size_t stack[2 * kStackRow];
  std::vector<size_t> heap;
  size_t* prev = stack;
  size_t* cur = stack + kStackRow;
  if (b.size() + 1 > kStackRow) {
    heap.resize(2 * (b.size() + 1));
    prev = heap.data();
    cur = prev + b.size() + 1;
  }
  for (size_t j = 0; j <= b.size(); ++j) prev[j] = j;
  for (size_t i = 1; i <= a.size(); ++i) {
    cur[0] = i;
    size_t row_min = i;
    for (size_t j = 1; j <= b.size(); ++j) {
      const size_t sub = prev[j - 1] + (a[i - 1] == b[j - 1] ? 0 : 1);
      cur[j] = std::min(std::min(prev[j], cur[j - 1]) + 1, sub);
      row_min = std::min(row_min, cur[j]);
    }
    if (row_min >= limit) return limit;  // the cells only grow from here on
    std::swap(prev, cur);
  }
  return std::min(prev[b.size()], limit);
}

std::string did_you_mean(std::string_view name, const std::vector<std::string_view>& valid) {
  size_t best = 3;  // at most two edits away
  std::string_view found;
  for (std::string_view v : valid) {
    const size_t d = edit_distance(name, v, best);
    if (d < best) best = d, found = v;
  }
  return found.empty() ? std::string() : fmt::format(" (did you mean '{}'?)", found);
}

std::string did_you_mean(std::string_view name, const std::vector<std::string>& valid) {
  return did_you_mean(name, std::vector<std::string_view>(valid.begin(), valid.end()));
}

}  // namespace clpost

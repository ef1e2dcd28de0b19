#include "verify/cut_alignment.h"

#include <algorithm>
#include <cstdint>
#include <limits>

namespace clpost {

namespace {

constexpr uint32_t kInf = std::numeric_limits<uint32_t>::max() / 2;
enum : uint8_t { kDiag, kUp, kLeft };  // the step a cell is reached by

// The table of the alignment, kept within a band around the diagonal: row i (0..n) covers
// columns [lo(i), hi(i)]. Cell (i, j) holds the least cost of lining up the first i of one
// sequence with the first j of the other, and the step it was reached by.
struct Band {
  size_t m = 0;
  size_t below = 0;  // columns left of the diagonal
  size_t above = 0;  // columns right of it
  std::vector<std::vector<uint32_t>> d;
  std::vector<std::vector<uint8_t>> from;

  size_t lo(size_t i) const { return i > below ? i - below : 0; }
  size_t hi(size_t i) const { return std::min(m, i + above); }
  uint32_t at(size_t i, size_t j) const {
    if (j < lo(i) || j > hi(i)) return kInf;
    return d[i][j - lo(i)];
  }
};

// Row i of the table, from the row above it and its own cells to the left.
void fill_row(Band& b, size_t i, const std::function<int(size_t, size_t)>& cost) {
  const size_t l = b.lo(i), h = b.hi(i);
  b.d[i].assign(h - l + 1, kInf);
  b.from[i].assign(h - l + 1, kDiag);
  for (size_t j = l; j <= h; ++j) {
    uint32_t best = kInf;
    uint8_t how = kDiag;
    if (i == 0 && j == 0) {
      best = 0;
    } else {
      if (i > 0 && j > 0 && b.at(i - 1, j - 1) < kInf) {
        best = b.at(i - 1, j - 1) + static_cast<uint32_t>(cost(i - 1, j - 1));
        how = kDiag;
      }
      if (i > 0 && b.at(i - 1, j) < kInf && b.at(i - 1, j) + 1 < best) {
        best = b.at(i - 1, j) + 1;
        how = kUp;
      }
      if (j > 0 && b.at(i, j - 1) < kInf && b.at(i, j - 1) + 1 < best) {
        best = b.at(i, j - 1) + 1;
        how = kLeft;
      }
    }
    b.d[i][j - l] = best;
    b.from[i][j - l] = how;
  }
}

// The pairs of the cheapest alignment, followed back from the table's last cell (n, m).
std::vector<AlignedPair> trace_back(const Band& b, size_t n, size_t m) {
  std::vector<AlignedPair> out;
  size_t i = n, j = m;
  while (i > 0 || j > 0) {
    const uint8_t how = b.from[i][j - b.lo(i)];
    if (i > 0 && j > 0 && how == kDiag) {
      out.push_back({static_cast<long>(i - 1), static_cast<long>(j - 1)});
      --i;
      --j;
    } else if (i > 0 && (how == kUp || j == 0)) {
      out.push_back({static_cast<long>(i - 1), -1});
      --i;
    } else {
      out.push_back({-1, static_cast<long>(j - 1)});
      --j;
    }
  }
  std::reverse(out.begin(), out.end());
  return out;
}

}  // namespace

std::vector<AlignedPair> align_sequences(size_t n, size_t m,
                                         const std::function<int(size_t, size_t)>& cost,
                                         size_t slack) {
  Band b;
  b.m = m;
  b.below = (n > m ? n - m : 0) + slack;
  b.above = (m > n ? m - n : 0) + slack;
  b.d.resize(n + 1);
  b.from.resize(n + 1);
  for (size_t i = 0; i <= n; ++i) fill_row(b, i, cost);
  return trace_back(b, n, m);
}

}  // namespace clpost

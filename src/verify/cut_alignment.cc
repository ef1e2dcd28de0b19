#include "verify/cut_alignment.h"

#include <algorithm>
#include <cstdint>
#include <limits>

namespace clpost {

std::vector<AlignedPair> align_sequences(size_t n, size_t m,
                                         const std::function<int(size_t, size_t)>& cost,
                                         size_t slack) {
  // Band: row i (0..n) covers columns [lo(i), hi(i)].
  const size_t below = (n > m ? n - m : 0) + slack;
  const size_t above = (m > n ? m - n : 0) + slack;
  auto lo = [&](size_t i) { return i > below ? i - below : 0; };
  auto hi = [&](size_t i) { return std::min(m, i + above); };
  constexpr uint32_t kInf = std::numeric_limits<uint32_t>::max() / 2;
  enum : uint8_t { kDiag, kUp, kLeft };
  std::vector<std::vector<uint32_t>> d(n + 1);
  std::vector<std::vector<uint8_t>> from(n + 1);
  auto at = [&](size_t i, size_t j) -> uint32_t {
    if (j < lo(i) || j > hi(i)) return kInf;
    return d[i][j - lo(i)];
  };
  for (size_t i = 0; i <= n; ++i) {
    const size_t l = lo(i), h = hi(i);
    d[i].assign(h - l + 1, kInf);
    from[i].assign(h - l + 1, kDiag);
    for (size_t j = l; j <= h; ++j) {
      uint32_t best = kInf;
      uint8_t how = kDiag;
      if (i == 0 && j == 0) {
        best = 0;
      } else {
        if (i > 0 && j > 0 && at(i - 1, j - 1) < kInf) {
          best = at(i - 1, j - 1) + static_cast<uint32_t>(cost(i - 1, j - 1));
          how = kDiag;
        }
        if (i > 0 && at(i - 1, j) < kInf && at(i - 1, j) + 1 < best) {
          best = at(i - 1, j) + 1;
          how = kUp;
        }
        if (j > 0 && at(i, j - 1) < kInf && at(i, j - 1) + 1 < best) {
          best = at(i, j - 1) + 1;
          how = kLeft;
        }
      }
      d[i][j - l] = best;
      from[i][j - l] = how;
    }
  }
  std::vector<AlignedPair> out;
  size_t i = n, j = m;
  while (i > 0 || j > 0) {
    const uint8_t how = from[i][j - lo(i)];
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

}  // namespace clpost

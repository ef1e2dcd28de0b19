#pragma once
// Lines up two sequences (the plan's cuts, the program's cuts) the way `diff` lines up files:
// the fewest insertions, deletions and substitutions. verify uses it so that one dropped pass is
// reported as that pass missing, not as every later pass being wrong.
#include <cstddef>
#include <functional>
#include <vector>

namespace clpost {

struct AlignedPair {
  long a = -1;  // index in the first sequence, -1: only in the second
  long b = -1;  // index in the second, -1: only in the first
};

// cost(i, j): 0 when a[i] and b[j] are the same, 1 when they are the same cut with different
// numbers, 2 (or more) when unrelated. A gap costs 1. Exact within a band around the diagonal
// wide enough for the length difference plus `slack`.
std::vector<AlignedPair> align_sequences(size_t n, size_t m,
                                         const std::function<int(size_t, size_t)>& cost,
                                         size_t slack = 32);

}  // namespace clpost

#pragma once
// Round numbers for grid ticks and scale bars.

namespace clpost {

// The smallest of 1, 2, 5 x 10^k that is >= `approx` (> 0; anything else gives 1).
// 0.3 -> 0.5, 7 -> 10, 2 -> 2, 0.011 -> 0.02.
double nice_step(double approx);

// The largest of 1, 2, 5 x 10^k that is <= `limit` (> 0; anything else gives 1). For scale bars
// that must fit: 0.8 -> 0.5, 30 -> 20, 5 -> 5.
double nice_floor(double limit);

}  // namespace clpost

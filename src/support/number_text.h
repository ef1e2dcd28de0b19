#pragma once
// How a number is written for people (messages, comments, the plan reports) and for the plan
// JSON, by every stage from the planner on.
#include <string>

namespace clpost {

// Fixed notation with at most 6 decimals, trailing zeros (and a bare point) trimmed, never "-0":
// 2.5 -> "2.5", 0.1 + 0.2 -> "0.3", 1.0 / 3 -> "0.333333", -1e-9 -> "0", 60 -> "60". Six decimals
// are 1 nm in mm and 1 microinch in inches, finer than any control resolution and below the 1e-6
// tolerance the planner checks sums with. Magnitudes from 1e12 up use "{:.6g}" (only hostile
// input has them).
std::string num_text(double v);

}  // namespace clpost

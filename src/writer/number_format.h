#pragma once
#include <string>

#include "machine/machine.h"

namespace clpost {

// Appends `value` written in format `f` to `out` ("12.", "0.5", "-.25", "1500", "1.500").
// Negative zero after rounding is written as zero.
void append_number(std::string& out, double value, const NumberFormat& f);

// `value` rounded to what format `f` writes (so modal suppression compares what is written).
double rounded(double value, const NumberFormat& f);

}  // namespace clpost

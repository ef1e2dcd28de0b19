#pragma once
// Numbers as the control reads them once written: a cycle's words are chosen, then expanded
// with the control's law from exactly what the NC text will say (rounding, scale), so that
// "exact or fall back" compares what the control will really cut.
#include <string_view>

#include "machine/machine.h"
#include "planner/thread_plan.h"

namespace clpost {

// `v` as the control reads it once written in the machine's format `f` (an address or a named
// format), the scale undone; never -0.
double as_read(const Machine& m, std::string_view f, double v);
// One least increment of format `f`, in unscaled units.
double least_increment(const Machine& m, std::string_view f);
// The nearest value format `f` writes that is not below (above) `v` beyond floating noise.
double read_up(const Machine& m, std::string_view f, double v);
double read_down(const Machine& m, std::string_view f, double v);
// A plan point as a positioning block writes it (X in the X format, diameter or radius).
Vec2 point_as_read(const Machine& m, Vec2 p);

}  // namespace clpost

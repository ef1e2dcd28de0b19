#pragma once
// Pieces of text the sheet's HTML and JSON share: feeds, speeds and tools as people read them,
// and a job's output as the program's fallback comment says it.
#include <string>
#include <string_view>
#include <vector>

#include "emitters/cycle_output.h"
#include "interpreter/cycle_time.h"
#include "planner/thread_plan.h"

namespace clpost {

// "0.2 mm/rev", "450 mm/min", "0.008 in/rev".
std::string feed_text(const FeedUsed& f, LengthUnit units);
// "800 rpm", "200 m/min" (constant surface speed; "ft/min" in inch programs).
std::string speed_text(const SpeedUsed& s, LengthUnit units);
// "T5", or "(none)" for the entry before the first tool change.
std::string tool_name(const ToolTime& t);
// "X24.000 to X32.000, Z-44.000 to Z2.000" as `clpost check` prints it ("" when it never moves).
std::string reach_text(const ToolTime& t, bool diameter);
// The output that wrote the job at CL line `line`, or null.
const OutputUsed* output_at(const std::vector<OutputUsed>& outputs, uint32_t line);
// "G76 not used: … ; G92 not used: …" (the reasons the outputs before it were not used).
std::string fallback_text(const OutputUsed& o);
// The tool changes of a tool list, as `clpost check` counts them.
size_t tool_changes(const CycleTime& t);

}  // namespace clpost

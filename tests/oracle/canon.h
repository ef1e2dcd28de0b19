#pragma once
// What LinuxCNC's interpreter did: `rs274 -g` canonical calls (one per line,
// "   12 N..... STRAIGHT_FEED(10.0000, 0.0000, -2.0000, …)") turned into the oracle's events, in
// mm, each motion with the interpreter's modal state at that point (docs/cl-meaning.md, "How the
// oracle reads rs274").
#include <string>
#include <string_view>
#include <vector>

#include "events.h"

namespace oracle {

// The tool table the oracle runs rs274 with gives tool n a Z offset of n × kOffsetStep inches (the
// table's unit in rs274 without an INI file), so the offset number reads back from
// USE_TOOL_LENGTH_OFFSET.
constexpr double kOffsetStepInch = 0.001;

std::vector<Event> canon_events(std::string_view canon);

}  // namespace oracle

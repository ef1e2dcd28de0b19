#pragma once
// The Fanuc control's fixed codes (machine/control.h: FixedCode): Fanuc 0i-TF Operator's Manual
// (B-64604EN), G-code system A: G20/G21 units, G32 thread cutting, G98/G99 feed per minute / per
// revolution. Haas's lathe control means the same by them (Haas Lathe Operator's Manual, G-code
// list) and uses this list.
#include "machine/control.h"

namespace clpost {

inline constexpr FixedCode kFanucCodes[] = {
    {"metric", "G21", "selects millimetres"},
    {"inch", "G20", "selects inches"},
    {"thread", "G32", "is a thread cut"},
    {"feed_per_min", "G98", "is feed per minute"},
    {"feed_per_rev", "G99", "is feed per revolution"},
};

}  // namespace clpost

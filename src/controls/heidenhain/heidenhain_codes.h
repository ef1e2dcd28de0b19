#pragma once
// HEIDENHAIN DIN's codes: G31's flank offset H values (heidenhain_law.h: g31_flank_codes),
// declared in the schema by its Control (Control::codes).
#include "machine/machine_schema.h"

namespace clpost {

inline constexpr NameSpec kHeidenhainCodes[] = {
    {"g31_h_minus", "HEIDENHAIN G31 flank offset H toward -Z (-X on a face); default 1"},
    {"g31_h_plus", "HEIDENHAIN G31 flank offset H toward +Z; default 2"},
    {"g31_h_alternating", "HEIDENHAIN G31 alternating flank offset H; default 3"}};

}  // namespace clpost

#pragma once
// The registry: every shipped control, each described by its folder's Control
// (controls/<control>/<control>_control.cc). It is, with the loop tables beside it
// (registry_output.cc, registry_readback.cc: Fanuc's G92 serves Haas too), the only place
// outside a control's folder that names one.
#include <array>
#include <string_view>

#include "machine/control.h"

namespace clpost {

// The shipped controls (registry.cc, library clpost_controls).
ControlSet shipped_controls();

// threading.cycle's values as the schema documents them (`clpost schema`, docs/machines.md):
// "none" and each shipped control's cycle, in the registry's order (registry_test.cc checks it
// against shipped_controls()).
inline constexpr std::array<std::string_view, 6> kShippedCycles = {
    "none", "cycle99", "fanuc_g76", "haas_g76", "heidenhain_g31", "linuxcnc_g76"};

}  // namespace clpost

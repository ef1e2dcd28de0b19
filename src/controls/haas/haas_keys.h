#pragma once
// The Haas control's machine keys (its settings 86, 99 and 95, haas_settings.h), declared in the
// schema by its Control (Control::keys).
#include "machine/machine_schema.h"

namespace clpost {

inline constexpr KeySpec kHaasKeys[] = {
    {"threading.haas_finish_allowance", "Control facts", KeyType::kNumber,
     static_cast<double Machine::*>(&HaasMachineSettings::haas_finish_allowance),
     "Haas setting 86 (finish allowance), machine units", 0, 10},
    {"threading.haas_min_cut", "Control facts", KeyType::kNumber,
     static_cast<double Machine::*>(&HaasMachineSettings::haas_min_cut),
     "Haas setting 99 (minimum cut), machine units", 0, 10},
    {"threading.haas_chamfer", "Control facts", KeyType::kNumber,
     static_cast<double Machine::*>(&HaasMachineSettings::haas_chamfer),
     "Haas setting 95 (chamfer size), in leads", 0, 99}};

}  // namespace clpost

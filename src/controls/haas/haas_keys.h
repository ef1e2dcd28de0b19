#pragma once
// The Haas control's machine keys: its settings 86, 99 and 95, which its G76 law reads
// (haas_law.h: haas_settings), declared in the schema by its Control (Control::keys) and kept on
// the machine by key (machine/control.h: control_value).
#include "machine/machine_schema.h"

namespace clpost {

inline constexpr KeySpec kHaasKeys[] = {
    {"threading.haas_finish_allowance", "Control facts", KeyType::kNumber, ControlSlot{},
     "Haas setting 86 (finish allowance), machine units", 0, 10},
    {"threading.haas_min_cut", "Control facts", KeyType::kNumber, ControlSlot{},
     "Haas setting 99 (minimum cut), machine units", 0, 10},
    {"threading.haas_chamfer", "Control facts", KeyType::kNumber, ControlSlot{},
     "Haas setting 95 (chamfer size), in leads", 0, 99}};

// Each setting's key.
inline constexpr const KeySpec& kHaasFinishAllowance = kHaasKeys[0];
inline constexpr const KeySpec& kHaasMinCut = kHaasKeys[1];
inline constexpr const KeySpec& kHaasChamfer = kHaasKeys[2];

}  // namespace clpost

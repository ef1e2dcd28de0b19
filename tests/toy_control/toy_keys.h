#pragma once
// The toy control's machine key: its (made-up) parameter 7, which its law reads (toy_law.h),
// declared in the schema by its Control (Control::keys) and kept on the machine by key
// (machine/control.h: control_value).
#include "machine/machine_schema.h"

namespace clpost::toy {

inline constexpr KeySpec kKeys[] = {
    {"threading.toy_run_in", "Control facts", KeyType::kNumber, ControlSlot{},
     "the toy control's parameter 7: how many leads before K its G177 starts the cut", 0, 10}};

inline constexpr const KeySpec& kRunIn = kKeys[0];

}  // namespace clpost::toy

// The registry's list of shipped controls (registry.h).
#include "controls/registry.h"

namespace clpost {

// Each defined in its folder's <control>_control.cc.
extern const Control kSinumerikControl, kFanucControl, kHaasControl, kHeidenhainControl,
    kLinuxcncControl;

namespace {

const Control* const kShipped[] = {&kSinumerikControl, &kFanucControl, &kHaasControl,
                                   &kHeidenhainControl, &kLinuxcncControl};

}  // namespace

ControlSet shipped_controls() {
  return kShipped;
}

}  // namespace clpost

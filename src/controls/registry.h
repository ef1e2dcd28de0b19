#pragma once
// The registry: every shipped control, each described by its folder's Control
// (controls/<control>/<control>_control.cc). It is the only place outside a control's folder
// that names one, and only the cli and tests name the set it makes: the stages below take the
// set they are given (machine/control.h: ControlSet).
#include "machine/control.h"

namespace clpost {

// The shipped controls (registry.cc, library clpost_controls).
ControlSet shipped_controls();

}  // namespace clpost

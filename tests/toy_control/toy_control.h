#pragma once
// A toy control, registered only in this test: proof of the path a new control takes
// (docs/adding-a-control.md) — a law, an emitter, a read-back and one Control.
#include "machine/control.h"

namespace clpost::toy {

extern const Control kControl;

}  // namespace clpost::toy

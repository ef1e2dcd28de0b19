#pragma once
// A toy control, registered only in this test: proof of the path a new control takes
// (docs/adding-a-control.md) — a law, an emitter, a read-back, templates, a machine key, a code
// and a loop block, described by one Control, with no file outside this folder.
#include "machine/control.h"

namespace clpost::toy {

extern const Control kControl;

}  // namespace clpost::toy

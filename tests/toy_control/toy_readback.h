#pragma once
// G177 read back (the simulator): each block's cut expanded with the toy's law.
#include "simulator/control_readback.h"

namespace clpost::toy {

extern const sim::ControlReadback kReadback;

}  // namespace clpost::toy

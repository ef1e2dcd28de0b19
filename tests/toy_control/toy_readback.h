#pragma once
// The toy's blocks read back (the simulator): each G177 and G178 block's cut expanded with the
// toy's law; G178's modal F kept in the toy's read-back state.
#include <memory>

#include "simulator/control_readback.h"

namespace clpost::toy {

extern const sim::ControlReadback kReadback;

// The G178 loop block (its Control's loop toy_g178).
bool g178(sim::State& s, const NcBlock& b);

// The state the toy's read-back keeps while a program runs (Control::readback_state).
std::unique_ptr<sim::ReadbackState> readback_state();

}  // namespace clpost::toy

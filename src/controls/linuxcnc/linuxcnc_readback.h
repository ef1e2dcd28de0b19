#pragma once
// LinuxCNC's G76 read back (simulator/), expanded with its law (linuxcnc_law.h). True when the
// block was the cycle (handled, errors reported).
#include "nc_reader/nc_block.h"
#include "simulator/control_readback.h"

namespace clpost::sim {

struct State;

bool linuxcnc_g76(State& s, const NcBlock& b);

// What the control contributes to the simulation (its Control's readback).
extern const ControlReadback kLinuxcncReadback;

}  // namespace clpost::sim

#pragma once
// HEIDENHAIN DIN's G31 read back (simulator/): G31, its contour blocks and G80, expanded with its
// law (heidenhain_law.h). True when the block belonged to the cycle (handled, errors reported).
#include "nc_reader/nc_block.h"
#include "simulator/control_readback.h"

namespace clpost::sim {

struct State;

bool heidenhain_g31(State& s, const NcBlock& b);

// What the control contributes to the simulation (its Control's readback).
extern const ControlReadback kHeidenhainReadback;

}  // namespace clpost::sim

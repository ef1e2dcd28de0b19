#pragma once
// SINUMERIK's thread cycle calls read back (simulator/): CYCLE99 and CYCLE98, their arguments
// read by the machine's templates and expanded with their laws (cycle99_law.h, cycle98_law.h).
// True when the block was that call (handled, errors reported).
#include "nc_reader/nc_block.h"
#include "simulator/control_readback.h"

namespace clpost::sim {

struct State;

bool cycle99_call(State& s, const NcBlock& b);
bool cycle98_call(State& s, const NcBlock& b);

// What the control contributes to the simulation (its Control's readback).
extern const ControlReadback kSinumerikReadback;

}  // namespace clpost::sim

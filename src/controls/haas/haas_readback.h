#pragma once
// Haas's one-block G76 read back (simulator/), expanded with its law (haas_law.h) and the
// machine's settings. True when the block was the cycle (handled, errors reported).
#include "nc_reader/nc_block.h"

namespace clpost::sim {

struct State;

bool haas_g76(State& s, const NcBlock& b);

}  // namespace clpost::sim

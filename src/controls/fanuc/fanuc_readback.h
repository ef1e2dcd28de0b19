#pragma once
// Fanuc's threading cycles read back (simulator/): G76 in two blocks and the G92 box cycle with
// its modal continuation blocks, expanded with their laws (fanuc_law.h). Each returns true when
// the block was its cycle (handled, errors reported).
#include <memory>
#include <string_view>

#include "nc_reader/nc_block.h"
#include "simulator/control_readback.h"

namespace clpost::sim {

struct State;

bool fanuc_g76(State& s, const NcBlock& b);
// The G92 loop block (its Control's loop g92): while it is modal, a block of only X/Z/R/Q words
// repeats it with the words it keeps (the read-back state fanuc_readback_state makes).
bool g92_cycle(State& s, const NcBlock& b);
std::unique_ptr<ReadbackState> fanuc_readback_state();
// The format of G76's P/Q depth words (µm in mm programs, 0.1 µm in inch ones); Haas's G76 too.
std::string_view g76_depth_format(const State& s);

// What the control contributes to the simulation (its Control's readback).
extern const ControlReadback kFanucReadback;

}  // namespace clpost::sim

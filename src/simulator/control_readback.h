#pragma once
// What a control contributes to the simulation (control_sim.cc): its cycles and calls read back
// with its laws, and the dialect words whose meaning is its own. Each control has one, in its
// folder (its Control's readback, machine/control.h); control_sim.cc knows no control by name.
#include <memory>
#include <span>
#include <string_view>

#include "machine/machine.h"
#include "nc_reader/nc_block.h"

namespace clpost::sim {

struct State;

// Reads a block that may be one of the control's cycles: true when it was (handled, errors
// reported), false to read it as an ordinary block.
using CycleReader = bool (*)(State& s, const NcBlock& b);

struct ControlReadback {
  // The control's G-code cycles, tried on machines that select it (threading.cycle); a cycle
  // spanning blocks keeps State::pending, and while pending.takes_blocks every block goes here.
  CycleReader cycle = nullptr;
  // Its call blocks (CYCLE99(…)): tried on every machine, each call found by the machine's
  // template of it (a machine with the template may use it whatever its threading.cycle).
  CycleReader call = nullptr;
  // The error at the program's end when a cycle that takes blocks was never closed.
  std::string_view unclosed = {};
  // The codes that switch diameter mode on and off (DIAMON, G7), when the control has them.
  std::string_view diameter_on = {}, diameter_off = {};
  // U and W are words of its cycles (G31's contour), not incremental positions.
  bool uw_are_cycle_words = false;
};

// The state a control's read-back keeps while a program runs (Fanuc's G92 modal words), each
// control its own kind, made by its Control::readback_state and found by that maker
// (sim_state.h: State::own).
struct ReadbackState {
  virtual ~ReadbackState() = default;
};
using MakeReadbackState = std::unique_ptr<ReadbackState> (*)();

}  // namespace clpost::sim

#pragma once
// The interface every control implements, below all of them (as LLVM's TargetRegistry.h is below
// its targets): a control clpost writes for and reads back is one folder of src/controls/ (its
// laws, emitters and read-back), described by one Control in its <control>_control.cc. The
// program is given a set of them (ControlSet: the cli the registry's, controls/registry.h; a test
// its own); a machine selects one with threading.cycle. Nothing below src/controls/ names a
// control. docs/adding-a-control.md walks through adding one.
#include <cstdint>
#include <memory>
#include <span>
#include <string_view>

namespace clpost {

struct Machine;
struct KeySpec;       // machine/machine_schema.h
struct NameSpec;      // machine/machine_schema.h
struct TemplateSpec;  // machine/machine_schema.h
struct ThreadPlan;
struct Undercut;
template <class Job>
class CycleOutput;
struct NcBlock;  // nc_reader/nc_block.h
namespace sim {
struct ControlReadback;  // simulator/control_readback.h
struct ReadbackState;    // simulator/control_readback.h
struct State;            // simulator/sim_state.h
}  // namespace sim

// A code whose meaning is the control's own (its manual's), not the machine builder's: G0, G99,
// M3 … A machine file may not redefine it (machine_loader.cc); builder codes (coolant, clamps,
// live tools) stay machine data.
struct FixedCode {
  std::string_view key;      // the codes: key, "spindle_cw"
  std::string_view code;     // "M3"
  std::string_view meaning;  // "starts the spindle clockwise"
};

// The codes every ISO-style lathe control of the registry shares: motion, arcs, spindle.
inline constexpr FixedCode kIsoMotionCodes[] = {
    {"rapid", "G0", "is a rapid move"},
    {"linear", "G1", "is a feed move"},
    {"arc_cw", "G2", "is a clockwise arc"},
    {"arc_ccw", "G3", "is a counter-clockwise arc"},
    {"spindle_cw", "M3", "starts the spindle clockwise"},
    {"spindle_ccw", "M4", "starts the spindle counter-clockwise"}};

// A control's single-pass loop block (threading.loop): one block per pass, written where the
// strategy or the fallback is `loop`. Any machine of the set may select it, whatever its
// threading.cycle (Haas's machines take Fanuc's G92); "g33", the G33 loop every control has,
// is none.
struct LoopBlock {
  std::string_view name;  // threading.loop's value: "g92"
  // Writes it (emitters/emitter.h).
  std::unique_ptr<CycleOutput<ThreadPlan>> (*emitter)() = nullptr;
  // Reads a block that may be it back (simulator/control_readback.h: CycleReader).
  bool (*readback)(sim::State& s, const NcBlock& b) = nullptr;
};

struct Control {
  std::string_view name;   // its folder: "fanuc"
  std::string_view cycle;  // the threading.cycle value that selects it: "fanuc_g76"
  // Its multi-pass thread cycle, written where it cuts the plan exactly (emitters/emitter.h).
  std::unique_ptr<CycleOutput<ThreadPlan>> (*cycle_emitter)() = nullptr;
  // Its cycle for chained threads on machine `m`, or null (m has not its template). Tried on
  // every machine, whatever its threading.cycle.
  std::unique_ptr<CycleOutput<ThreadPlan>> (*chain_emitter)(const Machine& m) = nullptr;
  // Its thread undercut cycle on machine `m`, or null; tried on every machine.
  std::unique_ptr<CycleOutput<Undercut>> (*undercut_cycle)(const Machine& m) = nullptr;
  // How its programs read back (simulator/control_readback.h).
  const sim::ControlReadback* readback = nullptr;
  // Its tool change stops the spindle (LinuxCNC's M6): the program starts it again.
  bool tool_change_stops_spindle = false;
  // Its fixed codes beyond kIsoMotionCodes (feed modes, units, the synchronized move).
  std::span<const FixedCode> fixed_codes = {};
  // Characters it reads as control even inside a comment (Fanuc's '%', the end of record): left
  // out of every comment, whatever comments.forbidden says.
  std::string_view comment_control = {};
  // Its least input increment of a length in an inch program (0.0001 in on IS-B controls): the
  // X, Z, I, K, R, U and W formats of an inch program have as many decimals unless the machine
  // file says formats.<a>.inch_decimals (machine_loader.cc). 0: none known (the formats decide).
  double inch_length_increment = 0;
  // It reads a whole program in one unit, set once outside the program's blocks (HEIDENHAIN DIN:
  // the PROGRAM HEAD's UNIT, else control parameter 1): a UNITS/ other than the machine's
  // `units` is an error at the CL line (interpreter/program_words.cc).
  bool one_unit_per_program = false;
  // Its feed type and its spindle mode are one G group (SINUMERIK's group 15: G96 is feed per
  // revolution at constant cutting speed, G97 feed per revolution at a constant speed, G94 and
  // G95 end constant cutting speed, and a change of feed type deletes F): the codes that set feed
  // per minute and per revolution while constant cutting speed stays on. Where they are given,
  // the writer writes them under constant surface speed in place of codes.feed_per_min and
  // feed_per_rev, and after a spindle template (G96, G97: feed per revolution) it writes the feed
  // mode and F again at the next feed that is not per revolution. Empty: the feed mode codes
  // leave the spindle alone.
  std::string_view css_feed_per_min = {}, css_feed_per_rev = {};

  // What it declares in the schema of post and machine files (machine/machine_schema.h: schema()
  // lists each control's after the program's own, in the set's order): its keys (its parameters
  // or settings a machine file states), the code names and formats it writes besides the
  // program's, and the templates its cycles are written through.
  std::span<const KeySpec> keys = {};
  std::span<const NameSpec> codes = {};
  std::span<const NameSpec> formats = {};
  std::span<const TemplateSpec* const> templates = {};
  // Its loop blocks (threading.loop's choices besides g33).
  std::span<const LoopBlock> loops = {};
  // Makes the state its read-back keeps while a program runs (a modal cycle's words), one per
  // run (simulator/sim_state.h: State::own); null: it keeps none.
  std::unique_ptr<sim::ReadbackState> (*readback_state)() = nullptr;
};

// The controls a program was given, which its machines may select: the cli gives the registry's
// (controls/registry.h), a test may give its own.
using ControlSet = std::span<const Control* const>;

// Where control `c`'s keys start among the slots of `set`'s control keys (schema() numbers each
// control's in the set's order): the number of keys the controls before it declare.
uint32_t first_slot(ControlSet set, const Control* c);

// The value of `key`, one of m.control's keys (Control::keys), on machine `m`: as its post,
// machine file or --set gave it, else its initial value (machine/machine_schema.h: ControlSlot).
// Read by the control's law through the key itself: no look-up by name.
double control_value(const Machine& m, const KeySpec& key);

// The control of `set` that threading.cycle `cycle` selects, or null ("none" selects none: plain
// ISO, G33 loops and emulation).
inline const Control* find_control(ControlSet set, std::string_view cycle) {
  for (const Control* c : set)
    if (c->cycle == cycle) return c;
  return nullptr;
}

// The loop block of `set` named `name` (threading.loop), or null ("g33" is none).
inline const LoopBlock* find_loop(ControlSet set, std::string_view name) {
  for (const Control* c : set)
    for (const LoopBlock& l : c->loops)
      if (l.name == name) return &l;
  return nullptr;
}

}  // namespace clpost

#pragma once
// The control simulation's state while it runs a program (control_sim.cc) and the controls'
// cycle read-backs that share it (src/controls/*/*_readback.cc, through control_readback.h).
#include <array>
#include <memory>
#include <optional>
#include <string>
#include <string_view>
#include <vector>

#include "laws/cut_pass.h"
#include "nc_reader/nc_block.h"
#include "planner/thread_words.h"
#include "simulator/control_readback.h"
#include "simulator/control_sim.h"

namespace clpost {
struct TemplateSpec;  // machine/machine_schema.h
}  // namespace clpost

namespace clpost::sim {

// How much of a block's text a cut keeps for its diagnostics (memory stays bounded).
constexpr size_t kKeptLineText = 256;
// The most cuts a cycle's count words may ask for: what one thread's plan may hold, so a program
// can do no more than a plan can.
constexpr int kMaxCyclePasses = kMaxPasses;

// A code of the machine (codes: / a template's first word) as address and number: "G33" is
// {"G", 33}; "DIAMON" is {"DIAMON", none}.
struct Code {
  std::string address;
  std::optional<double> number;
  bool empty() const { return address.empty(); }
};
Code parse_code(std::string_view text);
// Whether block `b` has code `c` (inline: most blocks have not the code's letter, a test of a
// bit; the machine's codes are asked for some twenty times a block).
bool has_code_in_words(const NcBlock& b, const Code& c);
inline bool has_code(const NcBlock& b, const Code& c) {
  return !c.empty() && b.may_have(c.address) && has_code_in_words(b, c);
}
// The first word of template `t`'s line `index` on machine `m` ("G76" of "G76 X{x} ..."); empty
// when absent. Named by its spec (tmpl::kDwell, ...): a misspelt template does not compile.
Code template_code(const Machine& m, const TemplateSpec& t, size_t index = 0);

// A field of a template word: "{offset:02}" is {"offset", 2} (width 0: any).
struct TemplateField {
  std::string name;
  int width = 0;
};

// One word of a template line: a constant code ("G97", "M6") or an address with fields
// ("S{rpm}", "T{tool:02}{offset:02}", "LIMS={max_rpm}"); a field alone ("{direction}") is
// neither.
struct TemplateToken {
  std::string address;
  std::vector<TemplateField> fields;
  Code code;
};
// A template line's words (template_words.cc), up to a comment.
std::vector<TemplateToken> template_tokens(const Machine& m, std::string_view line);

// How the machine's program states the modal state verify compares (modal_words.cc): the
// feed-mode and spindle codes and the words of its tool and spindle templates.
struct ModalWords {
  Code per_min, per_rev, cw, ccw, stop;
  // The control's feed types at constant surface speed (Control::css_feed_per_min: G961, G96);
  // where given, per_min and per_rev end constant surface speed.
  Code css_per_min, css_per_rev;
  Code rpm_mode, css_mode;                 // the first codes of the speed lines (G97, G96)
  std::string rpm_address, css_address;    // the words of {rpm} and {speed} ("S")
  Code limit_code;                         // a CSS limit block's code (G50), if it needs one
  std::string limit_address;               // the word of {max_rpm} ("S", "D", "LIMS=")
  std::string tool_address;                // the word of {tool} ("T")
  std::vector<TemplateField> tool_fields;  // that word's fields, in order
  std::string offset_address;              // {offset} in a word of its own ("D"), else empty
  std::vector<Code> tool_codes;            // the tool line's codes, each needed (M6 of T1 M6)
  StateReadback readback;
  // The letters of every code and word above (NcBlock::letters), and whether any has a longer
  // address ("LIMS="): a block without those letters states none of them.
  uint32_t letters = 0;
  bool longer = false;
};
ModalWords modal_words(const Machine& m);

// kCycle: a control's modal cycle is in force (Fanuc's G92): a block of its words alone repeats
// it, which its read-back reads; control_sim moves nothing for it.
enum class Motion {
  kNone,
  kRapid,
  kLinear,
  kArcCw,
  kArcCcw,
  kThread,
  kThreadInc,
  kThreadDec,
  kCycle
};

// A cycle whose words span several blocks, as its control's read-back has read it so far: the
// first block of a two-block cycle (a G76 P… Q… R…), or a cycle waiting for its contour and its
// closing block (G31 … G80), which takes every block while `takes_blocks`.
struct PendingCycle {
  bool set = false;
  bool takes_blocks = false;
  uint32_t line = 0, col = 0;
  std::string line_text;
  NcBlock block;
  std::optional<Vec2> from, to;
};

struct State {
  State(const Machine& machine, Diagnostics& d, Simulation& o, const SimOptions& so)
      : m(machine), diags(d), out(o), opt(so) {
    for (size_t i = 0; i < letter_scale.size(); ++i)
      letter_scale[i] = m.format_for(std::string(1, static_cast<char>('A' + i))).scale;
    for (const Control* c : m.controls)
      if (c->readback_state != nullptr)
        readback_states.emplace_back(c->readback_state, c->readback_state());
  }
  const Machine& m;
  // The format scale of each one-letter address ('A' first), looked up once: nearly every word
  // of a program is read through it (value()).
  std::array<double, 26> letter_scale{};
  Diagnostics& diags;
  Simulation& out;
  const SimOptions& opt;
  std::string_view line_text;
  uint32_t line = 0;
  bool ok = true;

  Vec2 pos;
  bool pos_known = false;  // before the first move the tool is somewhere unknown
  bool diameter = true;
  Motion motion = Motion::kNone;
  double f_register = 0;
  std::optional<double> lead_register;  // when the lead word is not F
  bool last_was_thread = false;         // the previous move was synchronized
  bool pullout_open = false;            // the previous move ended a synchronized cut
  PendingCycle pending;                 // a multi-block cycle being read (its control's read-back)
  // The read-back state of each control of the set that keeps one (Control::readback_state),
  // made as the run starts, with its maker.
  std::vector<std::pair<MakeReadbackState, std::unique_ptr<ReadbackState>>> readback_states;
  std::optional<double> c;  // the C axis (millturn.c_axis) as last written, degrees
  double y = 0;             // Y as last written (milling on a machine with Y)
  // Polar interpolation (codes polar_on .. polar_off, millturn.polar_interpolation): on, the C it
  // started at (angle 0 of its plane), and the tool in its plane (X and the virtual axis, radii).
  bool polar = false;
  bool polar_known = false;  // the tool's point in the plane and Z are known
  double polar_c = 0, polar_x = 0, polar_y = 0;
  bool mill_block = false;  // the block writes C, or Y is off 0 (Move::mill)
  bool hole_open = false;   // out.holes.back() is followed move by move (a "hole at" comment)
  int plane = 18;           // the plane selected last (G17, G18, G19): which axis a hole drills
  std::optional<double> live_rpm;  // the live tool's speed as last written (live_spindle_rpm)
  CutState cut;                    // feed mode, spindle and tool as the program last stated them
  // Before C is first written: the last move in X, Y, Z or C (mill_moves.cc), not yet kept.
  std::optional<SimMillMove> mill_before;
  // The machine's hole templates taken apart, once (hole_cycles.cc; null until the first block).
  std::shared_ptr<const void> hole_lines;
  // The codes of the machine's own positions (positions.cc), found at the first block.
  std::optional<std::vector<Code>> position_codes;

  // The read-back state `make` makes (a control's read-back asks for its own, of type T): the
  // one made as the run started, or, for a control outside the machine's set, one made now.
  template <class T>
  T& own(MakeReadbackState make) {
    for (auto& [maker, state] : readback_states)
      if (maker == make) return static_cast<T&>(*state);
    return static_cast<T&>(*readback_states.emplace_back(make, make()).second);
  }
  // A word's value as the control reads it: divided by the format's scale (machine formats).
  double value(const NcWord& w, std::string_view format) const;
  double value(const NcWord& w) const { return value(w, w.address); }
  // X as a radius (halved in diameter mode).
  double radius(const NcWord& x) const { return value(x) / diameter_factor(diameter); }
  void error(uint32_t col, std::string message);
  // A count or code word as a whole number in [lo, hi]; else an error naming the word and the
  // range, and nothing (a cycle asking for a billion passes is refused, not run).
  std::optional<int> whole(double v, std::string_view name, int lo, int hi, uint32_t col);
  void move(MoveKind kind, Vec2 to, Vec2 center = {}, double lead = 0);
  // A cycle's passes (its law's expansion) from `start`: cuts and their moves; the tool is left
  // at `after`.
  void cycle_cuts(const std::vector<Cut>& cuts, Vec2 start, Vec2 after, std::string_view source,
                  double lead, std::optional<double> start_angle, bool fixed_end,
                  bool keep_start_index);
};

// Holes (hole_cycles.cc): a "hole at CL line N" comment opens a hole followed move by move;
// a block of one of the machine's hole_* templates is that hole's cycle, expanded.
void hole_comment(State& s, const NcBlock& b);
// On a machine with C: a motion block's end in X, Y, Z and C into out.mill_moves (mill_moves.cc).
void mill_move(State& s, const NcBlock& b);
// In polar interpolation: a motion block's end in the plane (mill_moves.cc); the tool's radius
// and Z are then where it is.
void polar_move(State& s, const NcBlock& b);
// The feed mode, spindle and tool words of `b` into s.cut (modal_words.cc).
void read_modal_words(State& s, const NcBlock& b, const ModalWords& w);
bool hole_cycle_block(State& s, const NcBlock& b);
void follow_hole(State& s, MoveKind kind, Vec2 from, Vec2 to);
// A block of the machine's home or tool_change_position template (positions.cc): the tool goes
// to a position the program does not state.
bool machine_position_block(State& s, const NcBlock& b);

}  // namespace clpost::sim

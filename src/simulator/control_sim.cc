// The control simulation (control_sim.h): a program's blocks run through the machine's codes,
// its control's read-back and the modal state (sim_state.h; State's methods are sim_state.cc's).
#include "simulator/control_sim.h"

#include <fmt/format.h>

#include <algorithm>
#include <cmath>
#include <optional>

#include "machine/machine_schema.h"
#include "nc_reader/nc_lexer.h"
#include "simulator/control_readback.h"
#include "simulator/sim_state.h"
#include "support/angles.h"

namespace clpost {
namespace {

using sim::Code;
using sim::Motion;
using sim::State;

struct Codes {
  Code rapid, linear, cw, ccw, thread, thread_inc, thread_dec, metric, inch, dwell;
  std::string metric_line, inch_line;  // codes written as comments: "[METRIC]"
  sim::ModalWords modal;
  const sim::ControlReadback* control = nullptr;  // the machine's control (threading.cycle)
  Code diameter_on, diameter_off;                 // its diameter-mode codes, if any
  Code polar_on, polar_off;  // polar interpolation (millturn.polar_interpolation), if written
};

Codes codes_of(const Machine& m) {
  Codes c;
  c.rapid = sim::parse_code(m.code("rapid"));
  c.linear = sim::parse_code(m.code("linear"));
  c.cw = sim::parse_code(m.code("arc_cw"));
  c.ccw = sim::parse_code(m.code("arc_ccw"));
  c.thread = sim::parse_code(m.code("thread"));
  c.thread_inc = sim::parse_code(m.code("thread_increasing"));
  c.thread_dec = sim::parse_code(m.code("thread_decreasing"));
  c.metric = sim::parse_code(m.code("metric"));
  c.inch = sim::parse_code(m.code("inch"));
  c.dwell = sim::template_code(m, tmpl::kDwell);
  c.modal = sim::modal_words(m);
  static constexpr sim::ControlReadback kPlainIso{};
  c.control = m.control && m.control->readback ? m.control->readback : &kPlainIso;
  c.diameter_on = sim::parse_code(c.control->diameter_on);
  c.diameter_off = sim::parse_code(c.control->diameter_off);
  if (m.polar_interpolation) {
    c.polar_on = sim::parse_code(m.code("polar_on"));
    c.polar_off = sim::parse_code(m.code("polar_off"));
  }
  const std::string& open = m.comment_open;
  if (!open.empty() && m.code("metric").rfind(open, 0) == 0) c.metric_line = m.code("metric");
  if (!open.empty() && m.code("inch").rfind(open, 0) == 0) c.inch_line = m.code("inch");
  return c;
}

bool is_thread(Motion mo) {
  return mo == Motion::kThread || mo == Motion::kThreadInc || mo == Motion::kThreadDec;
}

void thread_move(State& s, const NcBlock& b, Vec2 to, const Code& code) {
  const Machine& m = s.m;
  const bool along_x = std::fabs(to.x - s.pos.x) > std::fabs(to.z - s.pos.z);
  const std::string& lead_addr =
      along_x && !m.thread_lead_address_x.empty() ? m.thread_lead_address_x : m.thread_lead_address;
  double lead = 0;
  double lead_change = 0;
  const NcWord* tpi = m.tpi_address.empty() ? nullptr : b.find(m.tpi_address);
  if (tpi != nullptr && tpi->value > 0) {
    lead = (s.out.units == LengthUnit::kInch ? 1.0 : 25.4) / s.value(*tpi);
  } else if (const NcWord* l = b.find(lead_addr)) {
    lead = s.value(*l);
    if (lead_addr == "F") {
      s.f_register = lead;
    } else {
      s.lead_register = lead;
    }
  } else if (lead_addr == "F") {
    lead = s.f_register;
  } else if (s.lead_register) {
    lead = *s.lead_register;
  } else {
    s.error(b.words.empty() ? 1 : b.words.front().col,
            fmt::format("synchronized move without a lead ({} word)", lead_addr));
    return;
  }
  if (s.motion != Motion::kThread && lead_addr != "F") {
    if (const NcWord* f = b.find("F")) {
      lead_change = s.value(*f, "F");
      if (s.motion == Motion::kThreadDec) lead_change = -lead_change;
    }
  }
  std::optional<double> angle;
  if (m.start_angle_word)
    if (const NcWord* q = b.find(m.start_angle_address)) angle = s.value(*q, "thread_angle");
  if (s.last_was_thread && !s.out.cuts.empty()) {
    NcCut& c = s.out.cuts.back();
    c.chain.push_back(to);
    c.end = to;
  } else {
    NcCut c;
    c.from = s.pos;
    c.to = to;
    c.end = to;
    c.chain = {to};
    c.lead = lead;
    c.lead_change = lead_change;
    c.start_angle = angle;
    c.line = s.line;
    c.line_text = std::string(s.line_text.substr(0, sim::kKeptLineText));
    c.source = code.address + (code.number ? fmt::format("{:g}", *code.number) : "");
    s.out.cuts.push_back(std::move(c));
  }
  s.move(MoveKind::kThread, to, {}, lead);
  s.last_was_thread = true;
  s.pullout_open = true;
}

// Units, diameter mode and the blocks that are not moves of the path's own: machine positions,
// dwells. True when the block is done with; refuses incremental positions.
bool settings_block(State& s, const NcBlock& b, const Codes& c) {
  if (sim::has_code(b, c.metric)) s.out.units = LengthUnit::kMm;
  if (sim::has_code(b, c.inch)) s.out.units = LengthUnit::kInch;
  if (sim::has_code(b, c.diameter_on)) s.diameter = true;
  if (sim::has_code(b, c.diameter_off)) s.diameter = false;
  if (sim::machine_position_block(s, b)) return true;
  const uint32_t incremental =
      NcBlock::letter_bit("G") | NcBlock::letter_bit("U") | NcBlock::letter_bit("W");
  for (const NcWord& w : b.words) {
    if ((b.letters & incremental) == 0) break;
    if ((w.address == "G" && w.has_value() && std::fabs(w.value - 91) < 1e-9) ||
        ((w.address == "U" || w.address == "W") && !c.control->uw_are_cycle_words)) {
      s.error(w.col, fmt::format("'{}{}': incremental positions are not supported by verify "
                                 "(absolute G90 only)",
                                 w.address, w.text));
      return true;
    }
  }
  return sim::has_code(b, c.dwell);  // G4 X/P/F is a time, not a position
}

// A canned cycle (holes, threads); true when the block was one. Calls (CYCLE99(…)) other than
// the controls' thread calls (CYCLE96 undercuts) are not simulated.
bool cycle_block(State& s, const NcBlock& b, const Codes& c) {
  if (sim::hole_cycle_block(s, b)) return true;
  if (!b.calls.empty()) {
    for (const Control* ctl : s.m.controls)
      if (ctl->readback && ctl->readback->call && ctl->readback->call(s, b)) break;
    return true;
  }
  if (c.control->cycle != nullptr && c.control->cycle(s, b)) return true;
  const LoopBlock* loop = s.m.thread_loop;  // null: G33, read as moves
  return loop != nullptr && loop->readback != nullptr && loop->readback(s, b);
}

// The block's modal motion code, if it has one (s.motion set).
const Code* motion_of(State& s, const NcBlock& b, const Codes& c) {
  struct Entry {
    const Code* code;
    Motion motion;
  };
  const Entry entries[] = {{&c.rapid, Motion::kRapid},
                           {&c.linear, Motion::kLinear},
                           {&c.cw, Motion::kArcCw},
                           {&c.ccw, Motion::kArcCcw},
                           {&c.thread, Motion::kThread},
                           {&c.thread_inc, Motion::kThreadInc},
                           {&c.thread_dec, Motion::kThreadDec}};
  const Code* found = nullptr;
  for (const Entry& e : entries)
    if (sim::has_code(b, *e.code)) {
      s.motion = e.motion;
      found = e.code;
    }
  return found;
}

// A move to `to` in the modal motion (x, z: the block's position words, one may be null).
void modal_move(State& s, const NcBlock& b, const Codes& c, const Code* motion_code, Vec2 to,
                const NcWord* at) {
  const bool was_thread = s.last_was_thread;
  const bool pullout_open = s.pullout_open;
  s.last_was_thread = false;
  s.pullout_open = false;
  switch (s.motion) {
    case Motion::kNone:
      return s.error(at->col, "a position with no motion mode (G0, G1, ...) in force");
    case Motion::kRapid:
      return s.move(MoveKind::kRapid, to);
    case Motion::kLinear:
      if (pullout_open && !s.out.cuts.empty()) s.out.cuts.back().linear_pullout = to;
      return s.move(MoveKind::kFeed, to);
    case Motion::kArcCw:
    case Motion::kArcCcw: {
      const NcWord* i = b.find("I");
      const NcWord* k = b.find("K");
      if (i == nullptr && k == nullptr) return s.error(at->col, "arc without a centre (I/K)");
      const Vec2 center{s.pos.x + (i ? s.value(*i) : 0), s.pos.z + (k ? s.value(*k) : 0)};
      return s.move(s.motion == Motion::kArcCw ? MoveKind::kArcCw : MoveKind::kArcCcw, to, center);
    }
    case Motion::kThread:
    case Motion::kThreadInc:
    case Motion::kThreadDec: {
      s.last_was_thread = was_thread;
      const Code& code = motion_code != nullptr           ? *motion_code
                         : s.motion == Motion::kThread    ? c.thread
                         : s.motion == Motion::kThreadInc ? c.thread_inc
                                                          : c.thread_dec;
      return thread_move(s, b, to, code);
    }
    case Motion::kCycle:
      return;
  }
}

// Polar interpolation's codes and the blocks between them (sim::polar_move): true when `b` is
// one of them. On, its plane's X axis is the machine's at the C then, the tool on it at its
// radius; off, C is at the angle of the tool's point in the plane.
bool polar_block(State& s, const NcBlock& b, const Codes& c) {
  if (!s.polar && has_code(b, c.polar_on)) {
    s.polar = true;
    s.polar_c = s.c.value_or(0);
    s.polar_x = s.pos.x;
    s.polar_y = 0;
    s.polar_known = s.pos_known;
    s.mill_block = true;
    return true;
  }
  if (!s.polar) return false;
  if (has_code(b, c.polar_off)) {
    s.polar = false;
    const double r = std::hypot(s.polar_x, s.polar_y);
    if (r > 1e-9) s.c = s.polar_c + degrees(std::atan2(s.polar_y, s.polar_x));
    s.pos.x = r;
    s.pos_known = s.pos_known || s.polar_known;
    return true;
  }
  motion_of(s, b, c);
  if (const NcWord* f = b.find("F")) s.f_register = s.value(*f);
  sim::polar_move(s, b);
  s.mill_block = true;
  return true;
}

void run_block(State& s, const NcBlock& b, const Codes& c) {
  // A cycle that takes the blocks up to its closing one (G31's contour and G80).
  if (s.pending.set && s.pending.takes_blocks) {
    c.control->cycle(s, b);
    return;
  }
  if (!c.metric_line.empty() && s.line_text.find(c.metric_line) != std::string_view::npos)
    s.out.units = LengthUnit::kMm;
  if (!c.inch_line.empty() && s.line_text.find(c.inch_line) != std::string_view::npos)
    s.out.units = LengthUnit::kInch;
  sim::hole_comment(s, b);
  if (b.words.empty() && b.calls.empty()) return;
  sim::read_modal_words(s, b, c.modal);
  if (polar_block(s, b, c)) return;
  if (s.m.c_axis)
    if (const NcWord* w = b.find(s.m.c_address)) s.c = s.value(*w, "C");
  if (settings_block(s, b, c) || cycle_block(s, b, c)) return;
  const Code* motion_code = motion_of(s, b, c);
  if (const NcWord* f = b.find("F"); f && !is_thread(s.motion)) s.f_register = s.value(*f);
  if (s.m.c_axis) sim::mill_move(s, b);
  s.mill_block = s.m.c_axis && (b.find(s.m.c_address) != nullptr || std::fabs(s.y) > 1e-9);
  const NcWord* x = b.find("X");
  const NcWord* z = b.find("Z");
  if (x == nullptr && z == nullptr) return;
  Vec2 to = s.pos;
  if (x) to.x = s.radius(*x);
  if (z) to.z = s.value(*z);
  modal_move(s, b, c, motion_code, to, x ? x : z);
}

}  // namespace

namespace {

// The run with block delete on (SimOptions::block_delete_too): its own options (its moves to
// on_block_delete_move), state, simulation and diagnostics; every block but the optional ones.
struct BlockDeleteRun {
  BlockDeleteRun(const Machine& m, const std::string& file, const SimOptions& o)
      : options(on_options(o)), diags(file), state(m, diags, sim, options) {
    state.diameter = m.diameter_output;
    sim.units = m.default_units == "in" ? LengthUnit::kInch : LengthUnit::kMm;
  }
  static SimOptions on_options(const SimOptions& o) {
    SimOptions on;
    on.keep_moves = o.keep_moves;
    on.on_move = o.on_block_delete_move;
    // Its milling is not compared: not kept either when the run with block delete off's is not.
    if (o.on_mill_move) on.on_mill_move = [](const SimMillMove&) {};
    return on;
  }
  SimOptions options;
  Diagnostics diags;
  Simulation sim;
  State state;
};

// Its errors that the run with block delete off has not: into `diags`, marked.
void keep_block_delete_errors(const Diagnostics& on, Diagnostics& diags) {
  const std::vector<Diagnostic> off = diags.kept();
  for (const Diagnostic& d : on.kept()) {
    if (d.severity != Severity::kError) continue;
    const bool known = std::any_of(off.begin(), off.end(), [&](const Diagnostic& o) {
      return o.loc.line == d.loc.line && o.message == d.message;
    });
    if (!known) diags.error(d.loc, d.line_text, d.message + " (block delete on)");
  }
}

// The end of a run: a cycle left open is an error; the path's units.
void finish_run(State& s, const Codes& codes) {
  if (s.pending.set && s.pending.takes_blocks) {
    s.diags.error(SourceLoc{s.pending.line, s.pending.col}, s.pending.line_text,
                  std::string(codes.control->unclosed));
    s.ok = false;
  }
  s.out.path.units = s.out.units;
}

}  // namespace

struct ControlSim::Impl {
  Impl(const Machine& m, Diagnostics& d, Simulation& out, const SimOptions& o)
      : options(o), s(m, d, out, options), syntax(nc_syntax(m)), codes(codes_of(m)) {
    if (o.block_delete_too) on.emplace(m, d.file(), o);
  }
  SimOptions options;
  State s;
  NcSyntax syntax;
  Codes codes;
  NcBlock block;
  NcLexError lex_error;
  std::optional<BlockDeleteRun> on;
  bool on_runs = true;          // false: no_optional_blocks()
  uint32_t first_optional = 0;  // the line of the first optional block
  std::string first_optional_text;
};

ControlSim::ControlSim(const Machine& m, Diagnostics& diags, Simulation& out,
                       const SimOptions& options) {
  out = Simulation{};
  out.units = m.default_units == "in" ? LengthUnit::kInch : LengthUnit::kMm;
  impl_ = std::make_unique<Impl>(m, diags, out, options);
  impl_->s.diameter = m.diameter_output;
  out.path.readback = impl_->codes.modal.readback;
  if (impl_->on) impl_->on->sim.path.readback = impl_->codes.modal.readback;
}

ControlSim::~ControlSim() = default;

void ControlSim::no_optional_blocks() {
  impl_->on_runs = false;
}

const LengthUnit& ControlSim::block_delete_units() const {
  return impl_->on ? impl_->on->sim.units : impl_->s.out.units;
}

const StateReadback& ControlSim::readback() const {
  return impl_->codes.modal.readback;
}

bool ControlSim::line(uint32_t number, std::string_view text) {
  State& s = impl_->s;
  ++s.out.blocks;
  s.line = number;
  s.line_text = text;
  if (!lex_nc_line(s.line_text, number, impl_->syntax, impl_->block, impl_->lex_error)) {
    s.diags.error(SourceLoc{number, impl_->lex_error.col}, s.line_text, impl_->lex_error.message);
    s.ok = false;
  } else {
    if (impl_->block.block_delete && s.out.deleted_blocks == 0 && impl_->options.on_first_optional)
      impl_->options.on_first_optional();
    run_block(s, impl_->block, impl_->codes);
    if (impl_->block.block_delete && s.out.deleted_blocks++ == 0)
      s.out.first_optional = {number, std::string(text)};
    if (impl_->on && impl_->on_runs && !impl_->block.block_delete) {
      State& on = impl_->on->state;
      on.line = number;
      on.line_text = s.line_text;
      run_block(on, impl_->block, impl_->codes);
    }
  }
  if (s.diags.error_count() > 100) {
    s.diags.error(SourceLoc{number, 1}, {}, "too many errors; verify stopped here");
    return false;
  }
  return true;
}

void ControlSim::unreadable() {
  impl_->s.ok = false;
}

bool ControlSim::finish() {
  State& s = impl_->s;
  finish_run(s, impl_->codes);
  if (impl_->on && impl_->on_runs && s.out.deleted_blocks > 0) {
    BlockDeleteRun& on = *impl_->on;
    finish_run(on.state, impl_->codes);
    keep_block_delete_errors(on.diags, s.diags);
    s.ok = s.ok && on.state.ok;
    s.out.with_block_delete.push_back(std::move(on.sim));
  }
  return s.ok;
}

bool read_nc_lines(reader::LineSource& src, Diagnostics& diags,
                   const std::function<bool(uint32_t, std::string_view)>& line,
                   const std::function<void()>& unreadable) {
  using Status = reader::LineSource::Status;
  constexpr size_t kMaxLine = 64 * 1024;
  while (true) {
    src.mark();
    reader::LineSource::Line l;
    const Status st = src.next_line(kMaxLine, l);
    if (st == Status::kEnd) return true;
    if (st == Status::kBinary) {
      diags.error({}, {},
                  fmt::format("not an NC text file (binary data at byte {})", src.binary_offset()));
      return false;
    }
    if (st == Status::kReadError) {
      diags.error({}, {}, src.read_error());
      return false;
    }
    if (st == Status::kTooLong) {
      diags.error(SourceLoc{l.number, 1}, {}, fmt::format("line longer than {} bytes", kMaxLine));
      src.skip_line();
      unreadable();
      continue;
    }
    if (!line(l.number, src.text(l))) return false;
  }
}

bool simulate_nc(reader::LineSource& src, const Machine& m, Diagnostics& diags, Simulation& out,
                 const SimOptions& options) {
  ControlSim sim(m, diags, out, options);
  const bool read = read_nc_lines(
      src, diags, [&sim](uint32_t number, std::string_view text) { return sim.line(number, text); },
      [&sim] { sim.unreadable(); });
  return read && sim.finish();
}

}  // namespace clpost

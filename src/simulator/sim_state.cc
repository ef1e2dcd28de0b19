// What sim_state.h declares: the machine's codes as the simulation matches them, and State's
// methods (a word's value, an error at the block, a move, a cycle's cuts), shared by control_sim.cc
// and the controls' read-backs.
#include "simulator/sim_state.h"

#include <fmt/format.h>

#include <cmath>

#include "machine/machine_schema.h"
#include "reader/number.h"

namespace clpost::sim {

Code parse_code(std::string_view text) {
  Code c;
  size_t i = 0;
  while (i < text.size() &&
         ((text[i] >= 'A' && text[i] <= 'Z') || (text[i] >= 'a' && text[i] <= 'z'))) {
    c.address += static_cast<char>(text[i] >= 'a' ? text[i] - 'a' + 'A' : text[i]);
    ++i;
  }
  if (i < text.size()) {
    double v = 0;
    if (reader::parse_number(text.substr(i), v) == reader::NumberStatus::kOk) {
      c.number = v;
    } else {
      c.address = std::string(text);  // "[METRIC]": matched against the line itself
    }
  }
  return c;
}

bool has_code_in_words(const NcBlock& b, const Code& c) {
  for (const NcWord& w : b.words) {
    // Most words differ in their first letter: that test first, without a call to memcmp.
    if (w.address.size() != c.address.size() || w.address[0] != c.address[0] ||
        w.address != c.address)
      continue;
    if (!c.number && !w.has_value()) return true;
    if (c.number && w.has_value() && std::fabs(w.value - *c.number) < 1e-9) return true;
  }
  return false;
}

Code template_code(const Machine& m, const TemplateSpec& spec, size_t index) {
  auto it = m.templates.find(std::string(spec.name));
  if (it == m.templates.end() || it->second.size() <= index) return {};
  std::string_view t = it->second[index];
  size_t end = t.find_first_of(" ({");
  return parse_code(t.substr(0, end));
}

double State::value(const NcWord& w, std::string_view format) const {
  const double scale =
      NcBlock::letter_bit(format) != 0 ? letter_scale[format[0] - 'A'] : m.format_for(format).scale;
  return scale != 0 ? w.value / scale : w.value;
}

void State::error(uint32_t col, std::string message) {
  diags.error(SourceLoc{line, col}, line_text, std::move(message));
  ok = false;
}

std::optional<int> State::whole(double v, std::string_view name, int lo, int hi, uint32_t col) {
  if (std::fabs(v - std::round(v)) < 1e-9 && v >= lo && v <= hi) return static_cast<int>(v);
  error(col, fmt::format("{} {:g}: a whole number from {} to {} expected", name, v, lo, hi));
  return std::nullopt;
}

void State::move(MoveKind kind, Vec2 to, Vec2 center, double lead) {
  // The state it is made with: a new entry when it changed.
  cut.feed = f_register;
  std::vector<CutStateAt>& states = out.path.states;
  if (opt.keep_moves && (states.empty() || !(states.back().state == cut)))
    states.push_back({cut, line});
  const uint32_t state = states.empty() ? 0 : static_cast<uint32_t>(states.size() - 1);
  // The first move starts where the tool happens to be: not drawn, not a cut's start; where it
  // ends is kept apart (verify of the path).
  if (opt.keep_moves && !pos_known) {
    Move mv;
    mv.kind = kind;
    mv.from = mv.to = to;
    mv.line = static_cast<int>(line);
    mv.state = state;
    out.path.entries.push_back({out.path.moves.size(), mv});
  }
  if (opt.on_move) {
    Move mv;
    mv.kind = kind;
    mv.from = pos_known ? pos : to;
    mv.to = to;
    mv.center = pos_known ? center : Vec2{};
    mv.line = static_cast<int>(line);
    mv.lead = pos_known ? lead : 0;
    mv.mill = mill_block && kind != MoveKind::kRapid;
    opt.on_move(mv, cut);
  }
  if (opt.keep_moves && pos_known) {
    Move mv;
    mv.kind = kind;
    mv.from = pos;
    mv.to = to;
    mv.center = center;
    mv.line = static_cast<int>(line);
    mv.lead = lead;
    mv.state = state;
    mv.mill = mill_block && kind != MoveKind::kRapid;
    out.path.moves.push_back(mv);
  }
  if (hole_open) sim::follow_hole(*this, kind, pos, to);
  pos = to;
  pos_known = true;
}

void State::cycle_cuts(const std::vector<Cut>& cuts, Vec2 start, Vec2 after,
                       std::string_view source, double lead, std::optional<double> start_angle,
                       bool fixed_end, bool keep_start_index) {
  const int call = out.calls++;
  pos = start;
  for (const Cut& c : cuts) {
    NcCut n;
    n.from = c.from;
    n.to = c.to;
    n.end = c.end;
    n.chain = c.corners;  // a chained cycle's segments (CYCLE98)
    n.chain.push_back(c.to);
    if (c.end.x != c.to.x || c.end.z != c.to.z) n.chain.push_back(c.end);
    n.lead = lead;
    n.start = keep_start_index ? c.start : -1;
    n.start_angle = start_angle;
    n.line = line;
    n.line_text = std::string(line_text.substr(0, kKeptLineText));
    n.source = std::string(source);
    n.call = call;
    n.fixed_end = fixed_end;
    out.cuts.push_back(std::move(n));
    // The cycle's own moves, as its figure draws them: along the start line to the pass, in,
    // the cut, out to the start line, back.
    move(MoveKind::kRapid, {start.x, c.from.z});
    move(MoveKind::kRapid, c.from);
    for (const Vec2& corner : c.corners) move(MoveKind::kThread, corner, {}, lead);
    move(MoveKind::kThread, c.to, {}, lead);
    if (c.end.x != c.to.x || c.end.z != c.to.z) move(MoveKind::kThread, c.end, {}, lead);
    move(MoveKind::kRapid, {start.x, pos.z});
    move(MoveKind::kRapid, start);
  }
  pos = after;
  if (after.x != start.x || after.z != start.z) move(MoveKind::kRapid, after);
  last_was_thread = false;
  pullout_open = false;
  motion = Motion::kNone;
}

}  // namespace clpost::sim

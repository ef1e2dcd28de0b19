#include "controls/heidenhain/heidenhain_readback.h"

#include <fmt/format.h>

#include <cmath>
#include <optional>

#include "controls/heidenhain/heidenhain_law.h"
#include "controls/heidenhain/heidenhain_templates.h"
#include "simulator/cycle_words.h"
#include "simulator/sim_state.h"

namespace clpost::sim {

namespace {

// Holds the G31 block until its contour and G80 have been read.
void hold_cycle(State& s, const NcBlock& b) {
  PendingCycle& g = s.pending;
  g = PendingCycle{};
  g.set = true;
  g.takes_blocks = true;
  g.line = s.line;
  g.col = first_col(b);
  g.line_text = std::string(s.line_text);
  g.block = b;
}

// Collects the contour: the first position a block gives (G0 X Z) is its start, the last (G1 X Z)
// its end.
void collect_contour(State& s, const NcBlock& b) {
  PendingCycle& g = s.pending;
  const NcWord* x = b.find("X");
  const NcWord* z = b.find("Z");
  if (x != nullptr || z != nullptr) {
    Vec2 p = g.to.value_or(g.from.value_or(s.pos));
    if (x) p.x = s.radius(*x);
    if (z) p.z = s.value(*z);
    if (!g.from) {
      g.from = p;
    } else {
      g.to = p;
    }
  }
}

// The G31 block's words and its contour as the control reads them; none when a whole-number word
// is out of range (every such word is named in an error).
std::optional<HeidenhainG31> g31_words(State& s, const PendingCycle& g) {
  const NcBlock& c = g.block;
  bool bad = false;
  auto whole = [&](double v, const char* name, int lo, int hi) {
    const std::optional<int> r = s.whole(v, name, lo, hi, g.col);
    bad = bad || !r;
    return r.value_or(lo);
  };
  HeidenhainG31 w;
  w.f = word_or(s, c, "F", "F", 0);
  w.u = word_or(s, c, "U", "U", 0);
  w.ic = whole(word_or(s, c, "IC", "IC", 1), "IC", 1, kMaxCyclePasses);
  w.v = whole(word_or(s, c, "V", "V", 0), "V", 0, 6);
  w.h = whole(word_or(s, c, "H", "H", 0), "H", 0, 9);
  w.a = word_or(s, c, "A", "A", 30);
  w.d = whole(word_or(s, c, "D", "D", 1), "D", 1, 100);
  w.q = whole(word_or(s, c, "Q", "Q", 0), "Q", 0, kMaxCyclePasses);
  w.c = word_or(s, c, "C", "C", 0);
  w.bd = whole(word_or(s, c, "BD", "BD", 0), "BD", 0, 1);
  w.b = word_or(s, c, "B", "B", 0);
  w.p = word_or(s, c, "P", "P", 0);
  w.k = word_or(s, c, "K", "K", 0);
  w.from = *g.from;
  w.to = *g.to;
  if (bad) return std::nullopt;
  return w;
}

// Runs the held cycle: its cuts from where the tool is, or the reason there are none.
void run_cycle(State& s, const PendingCycle& g) {
  if (!g.from || !g.to) {
    s.error(g.col, "G31's contour needs a start (G0 X Z) and an end (G1 X Z) before G80");
    return;
  }
  const std::optional<HeidenhainG31> w = g31_words(s, g);
  if (!w) return;  // the word is named above
  std::string refused;
  const std::vector<Cut> cuts = expand_heidenhain_g31(*w, g31_flank_codes(s.m), &refused);
  if (!refused.empty()) {
    s.error(g.col, "G31: " + refused);
    return;
  }
  const Vec2 start = s.pos;
  s.cycle_cuts(cuts, start, start, "G31", w->f, std::nullopt, false, false);
}

// Closes the cycle at G80: runs it with its messages pointing at the G31 block's line.
void close_cycle(State& s) {
  PendingCycle& g = s.pending;
  const uint32_t line = s.line;
  s.line = g.line;
  const std::string line_text = g.line_text;
  const std::string_view saved_text = s.line_text;
  s.line_text = line_text;
  g.set = false;
  run_cycle(s, g);
  s.line = line;
  s.line_text = saved_text;
}

}  // namespace

bool heidenhain_g31(State& s, const NcBlock& b) {
  const auto lines = s.m.templates.find(std::string(tmpl::kHeidenhainG31.name));
  if (lines == s.m.templates.end() || lines->second.empty()) return false;
  PendingCycle& g = s.pending;
  if (!g.set) {
    if (!has_code(b, template_code(s.m, tmpl::kHeidenhainG31))) return false;
    hold_cycle(s, b);
    return true;
  }
  // The contour (G0 to its start, G1 to its end) and the closing G80.
  const Code end = template_code(s.m, tmpl::kHeidenhainG31, lines->second.size() - 1);
  collect_contour(s, b);
  if (!has_code(b, end)) return true;
  close_cycle(s);
  return true;
}

const ControlReadback kHeidenhainReadback{
    .cycle = heidenhain_g31,
    .unclosed = "G31 has no G80: the thread cycle's contour is not closed",
    .uw_are_cycle_words = true};

}  // namespace clpost::sim

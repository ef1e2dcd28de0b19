#include "controls/heidenhain/heidenhain_readback.h"

#include <fmt/format.h>

#include <cmath>

#include "controls/heidenhain/heidenhain_law.h"
#include "simulator/cycle_words.h"
#include "simulator/sim_state.h"

namespace clpost::sim {

bool heidenhain_g31(State& s, const NcBlock& b) {
  const auto& tmpl = s.m.templates.find("heidenhain_g31");
  if (tmpl == s.m.templates.end() || tmpl->second.empty()) return false;
  PendingCycle& g = s.pending;
  if (!g.set) {
    if (!has_code(b, template_code(s.m, "heidenhain_g31"))) return false;
    g = PendingCycle{};
    g.set = true;
    g.takes_blocks = true;
    g.line = s.line;
    g.col = first_col(b);
    g.line_text = std::string(s.line_text);
    g.block = b;
    return true;
  }
  // The contour (G0 to its start, G1 to its end) and the closing G80.
  const Code end = template_code(s.m, "heidenhain_g31", tmpl->second.size() - 1);
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
  if (!has_code(b, end)) return true;
  const NcBlock& c = g.block;
  const uint32_t line = s.line;
  s.line = g.line;
  const std::string line_text = g.line_text;
  const std::string_view saved_text = s.line_text;
  s.line_text = line_text;
  g.set = false;
  if (!g.from || !g.to) {
    s.error(g.col, "G31's contour needs a start (G0 X Z) and an end (G1 X Z) before G80");
  } else {
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
    std::string refused;
    const std::vector<Cut> cuts =
        bad ? std::vector<Cut>{} : expand_heidenhain_g31(w, g31_flank_codes(s.m), &refused);
    if (bad) {
      // the word is named above
    } else if (!refused.empty()) {
      s.error(g.col, "G31: " + refused);
    } else {
      const Vec2 start = s.pos;
      s.cycle_cuts(cuts, start, start, "G31", w.f, std::nullopt, false, false);
    }
  }
  s.line = line;
  s.line_text = saved_text;
  return true;
}

const ControlReadback kHeidenhainReadback{
    .cycle = heidenhain_g31,
    .unclosed = "G31 has no G80: the thread cycle's contour is not closed",
    .uw_are_cycle_words = true};

}  // namespace clpost::sim

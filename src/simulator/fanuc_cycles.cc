// Fanuc-style threading cycles read back: G76 in two blocks (Fanuc), G76 in one block (Haas),
// and the G92 box cycle with its modal continuation blocks. Laws: emitters/fanuc_law.h,
// emitters/haas_law.h.
#include <fmt/format.h>

#include <cmath>

#include "emitters/fanuc_law.h"
#include "emitters/haas_emitter.h"
#include "emitters/haas_law.h"
#include "simulator/sim_state.h"

namespace clpost::sim {

namespace {

// The format of G76's P/Q depth words (µm in mm programs, 0.1 µm in inch ones).
std::string_view depth_format(const State& s) {
  return s.out.units == LengthUnit::kInch ? "g76_depth_in" : "g76_depth";
}

bool missing(State& s, const NcBlock& b, const Code& code, const char* words) {
  for (const char* w = words; *w != 0; ++w) {
    if (b.find(std::string(1, *w)) == nullptr) {
      s.error(b.words.empty() ? 1 : b.words.front().col,
              fmt::format("{}{:g} without its {} word", code.address, code.number.value_or(0), *w));
      return true;
    }
  }
  return false;
}

}  // namespace

bool fanuc_g76(State& s, const NcBlock& b) {
  const Code code = template_code(s.m, "fanuc_g76");
  if (!has_code(b, code)) return false;
  const bool second = b.find("X") != nullptr || b.find("Z") != nullptr;
  if (!second) {
    if (missing(s, b, code, "PQR")) return true;
    s.fanuc_first.set = true;
    s.fanuc_first.p = b.find("P")->text;
    s.fanuc_first.q = s.value(*b.find("Q"), depth_format(s));
    s.fanuc_first.r = s.value(*b.find("R"), "g76_allowance");
    return true;
  }
  if (!s.fanuc_first.set) {
    s.error(b.words.front().col, "G76 with X/Z but no first G76 block (P mmrraa Q R) before it");
    return true;
  }
  if (missing(s, b, code, "XZPQF")) return true;
  const std::string& p = s.fanuc_first.p;
  if (p.size() != 6 || p.find('.') != std::string::npos) {
    s.error(b.words.front().col, fmt::format("first G76 block's P{} is not six digits mmrraa", p));
    return true;
  }
  FanucG76Words w;
  w.finish_passes = std::stoi(p.substr(0, 2));
  w.chamfer = std::stoi(p.substr(2, 2));
  w.tool_angle = std::stoi(p.substr(4, 2));
  w.min_cut = s.fanuc_first.q;
  w.allowance = s.fanuc_first.r;
  w.x = s.value(*b.find("X"));
  w.z = s.value(*b.find("Z"));
  if (const NcWord* r = b.find("R")) w.taper = s.value(*r);
  w.height = s.value(*b.find("P"), depth_format(s));
  w.first_cut = s.value(*b.find("Q"), depth_format(s));
  w.lead = s.value(*b.find("F"));
  if (!s.diameter) w.x *= 2;  // the law reads X as written with CycleLaw::diameter
  const CycleLaw law{true, s.m.cycle_shifted_end, s.m.chamfer_angle};
  const std::vector<Cut> cuts = expand_fanuc_g76(w, s.pos, law);
  if (cuts.empty()) {
    s.error(b.words.front().col,
            fmt::format("G76 cuts nothing from Z{:g} to Z{:g}: height P {:g}, first cut Q {:g}, "
                        "minimum cut {:g}",
                        s.pos.z, w.z, w.height, w.first_cut, w.min_cut));
    return true;
  }
  const Vec2 start = s.pos;
  s.cycle_cuts(cuts, start, start, "G76", w.lead, std::nullopt, !s.m.cycle_shifted_end, false);
  return true;
}

bool haas_g76(State& s, const NcBlock& b) {
  const Code code = template_code(s.m, "haas_g76");
  if (!has_code(b, code)) return false;
  if (missing(s, b, code, "XZKDF")) return true;
  HaasG76Words w;
  w.x = s.value(*b.find("X"));
  w.z = s.value(*b.find("Z"));
  if (const NcWord* i = b.find("I")) w.taper = s.value(*i);
  w.height = s.value(*b.find("K"));
  w.first_cut = s.value(*b.find("D"));
  if (const NcWord* a = b.find("A")) {
    const std::optional<int> v = s.whole(a->value, "A", 0, 120, a->col);
    if (!v) return true;
    w.tool_angle = *v;
  }
  if (const NcWord* p = b.find("P")) {
    const std::optional<int> v = s.whole(p->value, "P", 1, 4, p->col);
    if (!v) return true;
    w.mode = *v;
  }
  if (const NcWord* q = b.find("Q")) w.start_angle = s.value(*q, "thread_angle");
  w.lead = s.value(*b.find("F"));
  if (!s.diameter) w.x *= 2;
  const HaasSettings settings = haas_settings(s.m, s.out.units);
  const CycleLaw law{true, s.m.cycle_shifted_end, settings.chamfer_angle};
  const std::vector<Cut> cuts = expand_haas_g76(w, s.pos, settings, law, 1);
  if (cuts.empty()) {
    s.error(b.words.front().col,
            fmt::format("G76 cuts nothing from Z{:g} to Z{:g}: height K {:g}, first cut D {:g}",
                        s.pos.z, w.z, w.height, w.first_cut));
    return true;
  }
  const Vec2 start = s.pos;
  s.cycle_cuts(cuts, start, start, "G76", w.lead, w.start_angle, !s.m.cycle_shifted_end, false);
  return true;
}

bool g92_cycle(State& s, const NcBlock& b) {
  const Code code = template_code(s.m, "g92");
  const bool starts = has_code(b, code);
  if (!starts) {
    // A continuation block repeats G92 while it is the modal motion: only X/Z/R/Q words.
    if (s.motion != Motion::kG92) return false;
    for (const NcWord& w : b.words)
      if (w.address == "G") {
        s.motion = Motion::kNone;
        return false;
      }
    if (b.find("X") == nullptr && b.find("Z") == nullptr) return false;
  }
  G92Modal& g = s.g92;
  if (starts) {
    if (missing(s, b, code, "XZF")) return true;
    g = G92Modal{};
  }
  if (const NcWord* x = b.find("X")) g.x = s.radius(*x);
  if (const NcWord* z = b.find("Z")) g.z = s.value(*z);
  if (const NcWord* r = b.find("R")) g.r = s.value(*r);  // X, Z, R, F are modal
  if (const NcWord* f = b.find("F")) g.f = s.value(*f);
  g.q.reset();  // Q is one-shot
  if (const NcWord* q = b.find("Q")) g.q = s.value(*q, "thread_angle");
  s.motion = Motion::kG92;
  // The box: in to X (+R at the start), the cut to X Z, out to the start's X, back to the start.
  const Vec2 start = s.pos;
  NcCut c;
  c.from = {g.x + g.r, start.z};
  c.to = {g.x, g.z};
  c.end = c.to;
  c.chain = {c.to};
  c.lead = g.f;
  c.start_angle = g.q;
  c.line = s.line;
  c.line_text = std::string(s.line_text.substr(0, kKeptLineText));
  c.source = "G92";
  s.out.cuts.push_back(c);
  s.move(MoveKind::kRapid, c.from);
  s.move(MoveKind::kThread, c.to, {}, g.f);
  s.move(MoveKind::kRapid, {start.x, c.to.z});
  s.move(MoveKind::kRapid, start);
  s.last_was_thread = false;
  s.pullout_open = false;
  return true;
}

}  // namespace clpost::sim

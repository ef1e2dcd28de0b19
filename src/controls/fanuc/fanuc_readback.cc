#include "controls/fanuc/fanuc_readback.h"

#include <fmt/format.h>

#include <cmath>

#include "controls/fanuc/fanuc_law.h"
#include "controls/fanuc/fanuc_templates.h"
#include "simulator/cycle_words.h"
#include "simulator/sim_state.h"

namespace clpost::sim {

namespace {

// G92's modal words: a block of only X/Z/R/Q repeats the cycle with them.
struct G92Words {
  double x = 0, z = 0, r = 0, f = 0;
  std::optional<double> q;
};

struct FanucState : ReadbackState {
  G92Words g92;
};

}  // namespace

std::unique_ptr<ReadbackState> fanuc_readback_state() {
  return std::make_unique<FanucState>();
}

std::string_view g76_depth_format(const State& s) {
  return s.out.units == LengthUnit::kInch ? "g76_depth_in" : "g76_depth";
}

bool fanuc_g76(State& s, const NcBlock& b) {
  const Code code = template_code(s.m, tmpl::kFanucG76);
  if (!has_code(b, code)) return false;
  const bool second = b.find("X") != nullptr || b.find("Z") != nullptr;
  if (!second) {
    if (missing(s, b, code, "PQR")) return true;
    s.pending = PendingCycle{};
    s.pending.set = true;
    s.pending.line = s.line;
    s.pending.block = b;
    return true;
  }
  if (!s.pending.set) {
    s.error(b.words.front().col, "G76 with X/Z but no first G76 block (P mmrraa Q R) before it");
    return true;
  }
  if (missing(s, b, code, "XZPQF")) return true;
  const NcBlock& first = s.pending.block;
  const std::string& p = first.find("P")->text;
  if (p.size() != 6 || p.find('.') != std::string::npos) {
    s.error(b.words.front().col, fmt::format("first G76 block's P{} is not six digits mmrraa", p));
    return true;
  }
  FanucG76Words w;
  w.finish_passes = std::stoi(p.substr(0, 2));
  w.chamfer = std::stoi(p.substr(2, 2));
  w.tool_angle = std::stoi(p.substr(4, 2));
  w.min_cut = s.value(*first.find("Q"), g76_depth_format(s));
  w.allowance = s.value(*first.find("R"), "g76_allowance");
  w.x = s.value(*b.find("X"));
  w.z = s.value(*b.find("Z"));
  if (const NcWord* r = b.find("R")) w.taper = s.value(*r);
  w.height = s.value(*b.find("P"), g76_depth_format(s));
  w.first_cut = s.value(*b.find("Q"), g76_depth_format(s));
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

bool g92_cycle(State& s, const NcBlock& b) {
  const Code code = template_code(s.m, tmpl::kG92);
  const bool starts = has_code(b, code);
  if (!starts) {
    // A continuation block repeats G92 while it is the modal motion: only X/Z/R/Q words.
    if (s.motion != Motion::kCycle) return false;
    for (const NcWord& w : b.words)
      if (w.address == "G") {
        s.motion = Motion::kNone;
        return false;
      }
    if (b.find("X") == nullptr && b.find("Z") == nullptr) return false;
  }
  G92Words& g = s.own<FanucState>(fanuc_readback_state).g92;
  if (starts) {
    if (missing(s, b, code, "XZF")) return true;
    g = G92Words{};
  }
  if (const NcWord* x = b.find("X")) g.x = s.radius(*x);
  if (const NcWord* z = b.find("Z")) g.z = s.value(*z);
  if (const NcWord* r = b.find("R")) g.r = s.value(*r);  // X, Z, R, F are modal
  if (const NcWord* f = b.find("F")) g.f = s.value(*f);
  g.q.reset();  // Q is one-shot
  if (const NcWord* q = b.find("Q")) g.q = s.value(*q, "thread_angle");
  s.motion = Motion::kCycle;
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

const ControlReadback kFanucReadback{.cycle = fanuc_g76};

}  // namespace clpost::sim

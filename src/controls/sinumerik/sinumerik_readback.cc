#include "controls/sinumerik/sinumerik_readback.h"

#include <fmt/format.h>

#include <cmath>

#include "controls/sinumerik/cycle98_law.h"
#include "controls/sinumerik/cycle99_law.h"
#include "controls/sinumerik/sinumerik_templates.h"
#include "simulator/cycle_words.h"
#include "simulator/sim_state.h"

namespace clpost::sim {

namespace {

// A CYCLE99 / CYCLE98 field by its name in the declared template (machine_schema.h): a name the
// template does not declare does not compile.
consteval const char* cycle99_field(const char* name) {
  (void)tmpl::kCycle99.field(name, FieldKind::kText);
  return name;
}
consteval const char* cycle98_field(const char* name) {
  (void)tmpl::kCycle98.field(name, FieldKind::kText);
  return name;
}

constexpr std::string_view kDepth = "cycle99_depth", kAngle = "cycle99_angle",
                           kLead = "cycle99_lead";

}  // namespace

bool cycle99_call(State& s, const NcBlock& b) {
  std::optional<CallArgs> c = CallArgs::find(s, b, tmpl::kCycle99);
  if (!c) return false;
  Cycle99Words w;
  w.spl = c->arg(cycle99_field("spl"), "Z", 0);
  w.dm1 = c->arg(cycle99_field("dm1"), "X", 0);
  w.fpl = c->arg(cycle99_field("fpl"), "Z", 0);
  w.dm2 = c->arg(cycle99_field("dm2"), "X", 0);
  w.app = c->arg(cycle99_field("app"), kDepth, 0);
  w.rop = c->arg(cycle99_field("rop"), kDepth, 0);
  w.tdep = c->arg(cycle99_field("tdep"), kDepth, 0);
  w.fal = c->arg(cycle99_field("fal"), kDepth, 0);
  w.iang = c->arg(cycle99_field("iang"), kAngle, 0);
  w.nsp = c->arg(cycle99_field("nsp"), kAngle, 0);
  w.nrc = c->whole(c->arg(cycle99_field("nrc"), "", 1), "NRC", 1, kMaxCyclePasses);
  w.nid = c->whole(c->arg(cycle99_field("nid"), "", 0), "NID", 0, kMaxCyclePasses);
  w.pit = c->arg(cycle99_field("pit"), kLead, 0);
  w.vari =
      c->whole(c->arg(cycle99_field("vari"), "", kVariExternalConstantInfeed), "VARI", 0, 999999);
  w.numth = c->whole(c->arg(cycle99_field("numth"), "", 0), "NUMTH", 0, 100);
  w.vrt = c->arg(cycle99_field("vrt"), kDepth, 0);
  w.pita = c->whole(c->arg(cycle99_field("pita"), "", 1), "PITA", 1, 4);
  w.psys = c->whole(c->arg(cycle99_field("psys"), "", 0), "PSYS", 0, 99);
  if (!c->ok()) return true;
  if (!s.diameter) {
    s.error(c->col(), "CYCLE99 in radius programming (DIAMOF) is not expanded");
    return true;
  }
  const Cycle99Expansion e = expand_cycle99(w);
  if (!e.alarm.empty()) {
    s.error(c->col(), "CYCLE99 alarm: " + e.alarm);
    return true;
  }
  const Vec2 start = s.pos;
  const double lead = cycle99_lead(w, s.out.units == LengthUnit::kInch);
  s.cycle_cuts(e.cuts, start, start, "CYCLE99", lead, std::nullopt, false, w.numth > 1);
  return true;
}

bool cycle98_call(State& s, const NcBlock& b) {
  std::optional<CallArgs> c = CallArgs::find(s, b, tmpl::kCycle98);
  if (!c) return false;
  Cycle98Words w;
  constexpr const char* kPo[] = {cycle98_field("po1"), cycle98_field("po2"), cycle98_field("po3"),
                                 cycle98_field("po4")};
  constexpr const char* kDm[] = {cycle98_field("dm1"), cycle98_field("dm2"), cycle98_field("dm3"),
                                 cycle98_field("dm4")};
  constexpr const char* kPp[] = {cycle98_field("pp1"), cycle98_field("pp2"), cycle98_field("pp3")};
  for (int j = 0; j < 4; ++j) {
    w.po[j] = c->arg(kPo[j], "Z", 0);
    w.dm[j] = c->arg(kDm[j], "X", 0);
  }
  for (int j = 0; j < 3; ++j) w.pp[j] = c->arg(kPp[j], kLead, 0);
  w.app = c->arg(cycle98_field("app"), kDepth, 0);
  w.rop = c->arg(cycle98_field("rop"), kDepth, 0);
  w.tdep = c->arg(cycle98_field("tdep"), kDepth, 0);
  w.fal = c->arg(cycle98_field("fal"), kDepth, 0);
  w.iang = c->arg(cycle98_field("iang"), kAngle, 0);
  w.nsp = c->arg(cycle98_field("nsp"), kAngle, 0);
  w.nrc = c->whole(c->arg(cycle98_field("nrc"), "", 1), "NRC", 1, kMaxCyclePasses);
  w.nid = c->whole(c->arg(cycle98_field("nid"), "", 0), "NID", 0, kMaxCyclePasses);
  w.vari = c->whole(c->arg(cycle98_field("vari"), "", 1), "VARI", 0, 99);
  w.numth = c->whole(c->arg(cycle98_field("numth"), "", 0), "NUMTH", 0, 100);
  w.vrt = c->arg(cycle98_field("vrt"), kDepth, 0);
  if (!c->ok()) return true;
  if (!s.diameter) {
    s.error(c->col(), "CYCLE98 in radius programming (DIAMOF) is not expanded");
    return true;
  }
  const Cycle98Expansion e = expand_cycle98(w);
  if (!e.alarm.empty()) {
    s.error(c->col(), "CYCLE98 is not expanded: " + e.alarm);
    return true;
  }
  const Vec2 start = s.pos;
  s.cycle_cuts(e.cuts, start, start, "CYCLE98", w.pp[0], std::nullopt, false, w.numth > 1);
  return true;
}

namespace {

bool sinumerik_call(State& s, const NcBlock& b) {
  return cycle99_call(s, b) || cycle98_call(s, b);
}

}  // namespace

const ControlReadback kSinumerikReadback{
    .call = sinumerik_call, .diameter_on = "DIAMON", .diameter_off = "DIAMOF"};

}  // namespace clpost::sim

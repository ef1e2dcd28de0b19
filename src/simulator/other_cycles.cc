// Threading cycles read back: LinuxCNC G76, HEIDENHAIN G31 ... G80 and SINUMERIK CYCLE99 and
// CYCLE98.
// Laws: emitters/linuxcnc_law.h, emitters/heidenhain_law.h, emitters/siemens_law.h.
#include <fmt/format.h>

#include <cmath>
#include <map>
#include <optional>
#include <string>
#include <utility>

#include "emitters/cycle98_law.h"
#include "emitters/heidenhain_emitter.h"
#include "emitters/heidenhain_law.h"
#include "emitters/linuxcnc_law.h"
#include "emitters/siemens_law.h"
#include "machine/machine_schema.h"
#include "reader/number.h"
#include "simulator/sim_state.h"

namespace clpost::sim {

namespace {

uint32_t first_col(const NcBlock& b) {
  return b.words.empty() ? 1 : b.words.front().col;
}

double word_or(const State& s, const NcBlock& b, const char* address, std::string_view format,
               double fallback) {
  const NcWord* w = b.find(address);
  return w != nullptr ? s.value(*w, format) : fallback;
}

}  // namespace

bool linuxcnc_g76(State& s, const NcBlock& b) {
  Code code = template_code(s.m, "linuxcnc_g76");
  if (!has_code(b, code)) return false;
  for (const char* a : {"P", "Z", "I", "J", "K"})
    if (b.find(a) == nullptr) {
      s.error(first_col(b), fmt::format("G76 without its {} word", a));
      return true;
    }
  LinuxcncG76 w;
  w.p = word_or(s, b, "P", "g76_lead", 0);
  w.z = word_or(s, b, "Z", "Z", 0);
  w.i = word_or(s, b, "I", "g76_depth", 0);
  w.j = word_or(s, b, "J", "g76_depth", 0);
  w.k = word_or(s, b, "K", "g76_depth", 0);
  w.r = word_or(s, b, "R", "R", 1);
  w.q = word_or(s, b, "Q", "g76_angle", 0);
  bool bad = false;
  auto whole = [&](double v, const char* name, int lo, int hi) {
    const std::optional<int> r = s.whole(v, name, lo, hi, first_col(b));
    bad = bad || !r;
    return r.value_or(lo);
  };
  w.h = whole(word_or(s, b, "H", "H", 0), "H", 0, kMaxCyclePasses);
  w.e = word_or(s, b, "E", "g76_taper", 0);
  w.l = whole(word_or(s, b, "L", "L", 0), "L", 0, 3);
  if (bad) return true;
  // The depths J n^(1/R) reach K after (K/J)^R passes: no more than a plan can hold.
  if (w.j > 0 && w.k > w.j && std::pow(w.k / w.j, std::max(w.r, 1.0)) > kMaxCyclePasses + 1) {
    s.error(first_col(b), fmt::format("G76 J{:g} K{:g} R{:g}: more than {} passes", w.j, w.k, w.r,
                                      kMaxCyclePasses));
    return true;
  }
  std::string refused;
  const std::vector<Cut> cuts = expand_linuxcnc_g76(w, s.pos, s.diameter, &refused);
  if (!refused.empty()) {
    s.error(first_col(b), refused);
    return true;
  }
  const Vec2 start = s.pos;
  s.cycle_cuts(cuts, start, {start.x, w.z}, "G76", w.p, std::nullopt, false, false);
  return true;
}

bool heidenhain_g31(State& s, const NcBlock& b) {
  const auto& tmpl = s.m.templates.find("heidenhain_g31");
  if (tmpl == s.m.templates.end() || tmpl->second.empty()) return false;
  PendingG31& g = s.g31;
  if (!g.set) {
    if (!has_code(b, template_code(s.m, "heidenhain_g31"))) return false;
    g = PendingG31{};
    g.set = true;
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
        bad ? std::vector<Cut>{}
            : expand_heidenhain_g31(w, HeidenhainG31Emitter::flank_codes(s.m), &refused);
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

namespace {

// Where each {field} of a call template sits among its arguments: "spl" -> 0, ...
std::map<std::string, size_t> call_fields(std::string_view t) {
  std::map<std::string, size_t> out;
  size_t open = t.find('(');
  if (open == std::string_view::npos) return out;
  size_t index = 0;
  bool quoted = false;
  size_t arg = open + 1;
  for (size_t i = open + 1; i < t.size(); ++i) {
    if (t[i] == '"') quoted = !quoted;
    if (quoted || (t[i] != ',' && t[i] != ')')) continue;
    std::string_view a = t.substr(arg, i - arg);
    size_t b = a.find('{'), e = a.find_first_of(":}", b == std::string_view::npos ? 0 : b);
    if (b != std::string_view::npos && e != std::string_view::npos)
      out[std::string(a.substr(b + 1, e - b - 1))] = index;
    ++index;
    arg = i + 1;
    if (t[i] == ')') break;
  }
  return out;
}

}  // namespace

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

// The arguments of a call the machine's template `spec` writes, read by field name; an argument
// that is not a number is reported once and makes ok() false.
class CallArgs {
 public:
  // Null when the block has no such call (or the machine no such template).
  static std::optional<CallArgs> find(State& s, const NcBlock& b, const TemplateSpec& spec) {
    const auto tmpl = s.m.templates.find(std::string(spec.name));
    if (tmpl == s.m.templates.end() || tmpl->second.empty()) return std::nullopt;
    std::string_view t = tmpl->second.front();
    const std::string name(t.substr(0, t.find('(')));
    for (const NcCall& c : b.calls)
      if (c.name == name) return CallArgs(s, c, name, call_fields(t));
    return std::nullopt;
  }

  double arg(const char* field, std::string_view format, double fallback) {
    auto it = fields_.find(field);
    if (it == fields_.end() || it->second >= call_->args.size() || !ok_) return fallback;
    const std::string& a = call_->args[it->second];
    if (a.empty()) return fallback;
    double v = 0;
    if (reader::parse_number(a, v) != reader::NumberStatus::kOk) {
      s_->error(call_->cols[it->second], fmt::format("{} argument {} ({}): invalid number '{}'",
                                                     name_, it->second + 1, field, a));
      ok_ = false;
      return fallback;
    }
    const double scale = s_->m.format_for(format).scale;
    return scale != 0 ? v / scale : v;
  }
  int whole(double v, const char* n, int lo, int hi) {
    if (!ok_) return lo;
    const std::optional<int> r = s_->whole(v, n, lo, hi, call_->col);
    ok_ = ok_ && r.has_value();
    return r.value_or(lo);
  }
  bool ok() const { return ok_; }
  uint32_t col() const { return call_->col; }

 private:
  CallArgs(State& s, const NcCall& c, std::string name, std::map<std::string, size_t> fields)
      : s_(&s), call_(&c), name_(std::move(name)), fields_(std::move(fields)) {}
  State* s_;
  const NcCall* call_;
  std::string name_;
  std::map<std::string, size_t> fields_;
  bool ok_ = true;
};

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

}  // namespace clpost::sim

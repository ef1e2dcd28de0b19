// Holes along the spindle axis (at their X and C) as the control drills them. A block is a hole
// cycle when it is the line of one of the machine's hole_* templates that holds {z}: the template's
// cycle code (the last code before its first field word, or its call's name) is in the block, and
// the block has exactly the template's addresses (Fanuc's G83 drills without Q and pecks with it).
// Its words are read back by field and the hole expanded with hole_feed_ends, the definition the
// emitter writes moves by (emitters/hole_output.h): the machine file is the only source, as for
// threads.
#include <fmt/format.h>

#include <algorithm>
#include <cctype>
#include <cmath>
#include <map>
#include <set>

#include "laws/hole_law.h"
#include "reader/number.h"
#include "simulator/sim_state.h"
#include "support/text.h"

namespace clpost::sim {

namespace {

// A hole template's cycle line, taken apart.
struct HoleLine {
  HoleKind kind = HoleKind::kDrill;
  bool radial = false;                         // a hole_radial_* template: X is the drilling axis
  bool live = false;                           // a live tool's tap: its feed per minute / live rpm
  std::string call;                            // a call's name ("CYCLE83"), else empty
  Code code;                                   // the cycle code of a word line
  std::map<std::string, std::string> by_addr;  // word lines: address -> field
  std::set<std::string> addresses;             // word lines: every non-G/M address
  std::map<std::string, size_t> by_arg;        // calls: field -> argument index
  int plane = 0;  // the plane (17, 18, 19) a line of the template selects before it (0: none)
};

// The plane ISO code `b` selects (G17, G18, G19), or 0.
int plane_of(const NcBlock& b) {
  if (!b.may_have("G")) return 0;  // most blocks
  for (const NcWord& w : b.words)
    if (w.address == "G" && w.has_value())
      for (int p : {17, 18, 19})
        if (std::fabs(w.value - p) < 1e-9) return p;
  return 0;
}

// The plane a template line selects when it is one plane code alone ("G19"), or 0.
int plane_line(std::string_view line) {
  for (int p : {17, 18, 19})
    if (line == fmt::format("G{}", p)) return p;
  return 0;
}

struct HoleTemplate {
  const TemplateSpec* spec;
  HoleKind kind;
  bool radial = false;
  bool live = false;  // synchronised with the live spindle (a live tool's tap)
};
// A live tool's taps first: Fanuc's face tap is the centre-line rigid tap's G84 line, read as the
// live tool's (its lead F / the live rpm) when written per minute, F itself per revolution.
constexpr HoleTemplate kHoleTemplates[] = {
    {&tmpl::kHoleLiveTap, HoleKind::kTap, false, true},
    {&tmpl::kHoleRadialTap, HoleKind::kTap, true, true},
    {&tmpl::kHoleLiveTapLeft, HoleKind::kTap, false, true},
    {&tmpl::kHoleRadialTapLeft, HoleKind::kTap, true, true},
    {&tmpl::kHoleDrill, HoleKind::kDrill},
    {&tmpl::kHoleDwell, HoleKind::kDrill},
    {&tmpl::kHolePeck, HoleKind::kDeep},
    {&tmpl::kHoleChipBreak, HoleKind::kChipBreak},
    {&tmpl::kHoleTap, HoleKind::kTap},
    {&tmpl::kHoleTapRigid, HoleKind::kTap},
    {&tmpl::kHoleBore, HoleKind::kBore},
    {&tmpl::kHoleRadialDrill, HoleKind::kDrill, true},
    {&tmpl::kHoleRadialDwell, HoleKind::kDrill, true},
    {&tmpl::kHoleRadialPeck, HoleKind::kDeep, true},
    {&tmpl::kHoleRadialChipBreak, HoleKind::kChipBreak, true},
    {&tmpl::kHoleRadialBore, HoleKind::kBore, true}};

// The field named in `token` ("{peck}" or "{dwell_ms:04}"), or "".
std::string field_in(std::string_view token) {
  const size_t b = token.find('{');
  if (b == std::string_view::npos) return {};
  const size_t e = token.find_first_of(":}", b);
  return e == std::string_view::npos ? std::string() : std::string(token.substr(b + 1, e - b - 1));
}

bool parse_call_line(std::string_view line, HoleLine& h) {
  const size_t open = line.find('(');
  h.call = std::string(line.substr(0, open));
  size_t index = 0, arg = open + 1;
  for (size_t i = open + 1; i < line.size(); ++i) {
    if (line[i] != ',' && line[i] != ')') continue;
    if (std::string f = field_in(line.substr(arg, i - arg)); !f.empty()) h.by_arg[f] = index;
    ++index, arg = i + 1;
  }
  return h.by_arg.count("z") > 0;
}

bool parse_word_line(const Machine& m, std::string_view line, HoleLine& h) {
  bool fields_begun = false;
  for (const TemplateToken& w : template_tokens(m, line)) {
    if (!w.fields.empty()) {
      fields_begun = true;
      h.by_addr[w.address] = w.fields.front().name;
      h.addresses.insert(w.address);
    } else if (w.code.address == "G" || w.code.address == "M") {
      if (!fields_begun) h.code = w.code;
    } else {
      h.addresses.insert(w.code.address);  // a constant word ("Y0")
    }
  }
  return !h.code.empty();
}

// The cycle line of hole template `t` on machine `m`.
std::optional<HoleLine> hole_line(const Machine& m, const HoleTemplate& t) {
  auto it = m.templates.find(std::string(t.spec->name));
  if (it == m.templates.end()) return std::nullopt;
  int plane = 0;
  for (const std::string& line : it->second) {
    if (int p = plane_line(line); p != 0) plane = p;
    if (line.find("{z") == std::string::npos) continue;
    HoleLine h;
    h.kind = t.kind;
    h.radial = t.radial;
    h.live = t.live;
    h.plane = plane;
    const size_t open = line.find('(');
    const bool call = open != std::string::npos && open > 0 &&
                      std::all_of(line.begin(), line.begin() + static_cast<long>(open), [](char c) {
                        return std::isalnum(static_cast<unsigned char>(c));
                      });
    if (call ? parse_call_line(line, h) : parse_word_line(m, line, h)) return h;
  }
  return std::nullopt;
}

bool matches(const HoleLine& h, const NcBlock& b, int plane) {
  if (h.plane != 0 && h.plane != plane) return false;
  if (!h.call.empty())
    return std::any_of(b.calls.begin(), b.calls.end(),
                       [&](const NcCall& c) { return c.name == h.call; });
  if (!has_code(b, h.code)) return false;
  std::set<std::string> addrs;
  for (const NcWord& w : b.words)
    if (w.address != "G" && w.address != "M") addrs.insert(w.address);
  return addrs == h.addresses;
}

std::string_view format_of(const std::string& field) {
  if (field == "x") return "X";
  if (field == "peck") return "hole_peck";
  if (field == "dwell") return "dwell";
  if (field == "feed" || field == "lead") return "F";
  if (field == "rpm") return "S";
  return "Z";
}

// The value of field `f` of `h` in word `w`: X positions as radii.
double field_value(State& s, const HoleLine& h, const std::string& f, const NcWord& w) {
  if (f == "x") return s.radius(w);
  if (!h.radial) return s.value(w, format_of(f));
  if (f == "r" || f == "top" || f == "start") return s.radius(w);
  if (f == "z" || f == "peck" || f == "dwell" || f == "feed" || f == "lead" || f == "rpm")
    return s.value(w, format_of(f));
  return s.value(w, "X");  // r_radius, r_inc, safety, depth: radii
}

// The block's value of every field of `h` (X as a radius); false (reported) on a bad number.
bool read_fields(State& s, const HoleLine& h, const NcBlock& b, std::map<std::string, double>& v) {
  if (h.call.empty()) {
    for (const NcWord& w : b.words) {
      auto it = h.by_addr.find(w.address);
      if (it == h.by_addr.end()) continue;
      v[it->second] = field_value(s, h, it->second, w);
    }
    return true;
  }
  const NcCall* call = nullptr;
  for (const NcCall& c : b.calls)
    if (c.name == h.call) call = &c;
  for (const auto& [field, index] : h.by_arg) {
    if (index >= call->args.size() || call->args[index].empty()) continue;
    double x = 0;
    if (reader::parse_number(call->args[index], x) != reader::NumberStatus::kOk) {
      s.error(call->cols[index], fmt::format("{} argument {} ({}): invalid number '{}'", h.call,
                                             index + 1, field, call->args[index]));
      return false;
    }
    const double scale = s.m.format_for(format_of(field)).scale;
    v[field] = scale != 0 ? x / scale : x;
  }
  return true;
}

// The hole the fields describe, from where the tool is (`at`).
Hole hole_of(const HoleLine& h, const std::map<std::string, double>& v, double at) {
  auto has = [&](const char* f) { return v.count(f) > 0; };
  Hole hole;
  hole.kind = h.kind;
  hole.radial = h.radial;
  hole.start = has("start") ? v.at("start") : at;
  hole.bottom = v.at(h.radial ? "x" : "z");
  hole.dir = hole.bottom < hole.start ? -1 : 1;
  hole.r = has("r")                      ? v.at("r")
           : has("r_radius")             ? v.at("r_radius")
           : has("r_inc")                ? hole.start + v.at("r_inc")
           : has("top") && has("safety") ? v.at("top") - hole.dir * v.at("safety")
                                         : at;
  hole.top = has("top") ? v.at("top") : hole.r;
  hole.peck = has("peck") ? v.at("peck") : 0;
  hole.dwell = has("dwell") ? v.at("dwell") : has("dwell_ms") ? v.at("dwell_ms") / 1000 : 0;
  hole.retract = hole.start;
  if (has("lead")) {
    hole.lead = v.at("lead");
  } else if (h.kind == HoleKind::kTap && has("feed")) {
    hole.lead = v.at("feed");
  }
  return hole;
}

}  // namespace

void hole_comment(State& s, const NcBlock& b) {
  static constexpr std::string_view kMarker = "hole at cl line ";
  for (const std::string& c : b.comments) {
    std::string lower(c);
    for (char& ch : lower) ch = static_cast<char>(std::tolower(static_cast<unsigned char>(ch)));
    // The post's marker starts its comment; the words anywhere else are somebody's text.
    const size_t at = lower.find_first_not_of(' ');
    if (at == std::string::npos || lower.compare(at, kMarker.size(), kMarker) != 0) continue;
    uint32_t n = 0;
    for (size_t i = at + kMarker.size(); i < lower.size() && is_digit(lower[i]) && n < 100000000;
         ++i)
      n = n * 10 + static_cast<uint32_t>(lower[i] - '0');
    SimHole h;
    h.cl_line = n;
    h.line = s.line;
    h.line_text = std::string(s.line_text.substr(0, kKeptLineText));
    h.source = "moves";
    s.out.holes.push_back(std::move(h));
    s.hole_open = true;
  }
}

namespace {
// How the machine writes the live tool's speed (live_spindle_rpm "{direction} $1 S{rpm}"): a
// block with its direction code, its constant words and the {rpm} word.
struct LiveRpmLine {
  Code cw, ccw;
  std::vector<Code> constants;  // "$1"
  std::string rpm_address;      // "S", Haas "P"
};

// Every hole template's cycle line, taken apart once per program (State::hole_lines).
struct HoleLines {
  std::optional<HoleLine> lines[std::size(kHoleTemplates)];
  // The letters of the word lines' cycle codes (NcBlock::letters), and whether one has a longer
  // address: a block without those letters and without a call is no hole cycle.
  uint32_t letters = 0;
  bool longer = false;
  LiveRpmLine live;
};

LiveRpmLine live_rpm_line(const Machine& m) {
  LiveRpmLine l;
  auto it = m.templates.find(std::string(tmpl::kLiveSpindleRpm.name));
  if (!m.live_tools || it == m.templates.end() || it->second.empty()) return l;
  l.cw = parse_code(m.code("live_spindle_cw"));
  l.ccw = parse_code(m.code("live_spindle_ccw"));
  for (const TemplateToken& w : template_tokens(m, it->second.front())) {
    if (!w.fields.empty() && w.fields.front().name == "rpm") l.rpm_address = w.address;
    if (w.fields.empty() && !w.code.empty()) l.constants.push_back(w.code);
  }
  return l;
}

const HoleLines& hole_lines(State& s) {
  if (!s.hole_lines) {
    auto h = std::make_shared<HoleLines>();
    for (size_t i = 0; i < std::size(kHoleTemplates); ++i) {
      h->lines[i] = hole_line(s.m, kHoleTemplates[i]);
      if (!h->lines[i] || !h->lines[i]->call.empty() || h->lines[i]->code.empty()) continue;
      const uint32_t bit = NcBlock::letter_bit(h->lines[i]->code.address);
      h->letters |= bit;
      h->longer = h->longer || bit == 0;
    }
    h->live = live_rpm_line(s.m);
    s.hole_lines = h;
  }
  return *static_cast<const HoleLines*>(s.hole_lines.get());
}

// The live tool's speed, when block `b` writes it.
void read_live_rpm(State& s, const LiveRpmLine& l, const NcBlock& b) {
  if (l.rpm_address.empty() || !(has_code(b, l.cw) || has_code(b, l.ccw))) return;
  for (const Code& c : l.constants)
    if (!has_code(b, c)) return;
  if (const NcWord* w = b.find(l.rpm_address)) s.live_rpm = s.value(*w, "S");
}

// A live tool's tap written per minute (F = lead x the live tool's rpm): its lead is F over the
// live tool's speed as the program last wrote it.
std::optional<double> live_tap_lead(const State& s, const std::map<std::string, double>& v) {
  if (v.count("lead")) return v.at("lead");
  if (!v.count("feed")) return std::nullopt;
  if (s.cut.per_rev != 0) return v.at("feed");
  if (!s.live_rpm || !(*s.live_rpm > 0)) return std::nullopt;
  return v.at("feed") / *s.live_rpm;
}
// A radial hole's moves at Z `z`: to the hole's Z at the tool's X, then along X.
void radial_moves(State& s, SimHole& sh, const Hole& hole, double z) {
  sh.radial = true;
  sh.z = z;
  sh.x = hole.start;
  s.move(MoveKind::kRapid, {s.pos.x, z});
  s.move(MoveKind::kRapid, {hole.r, z});
  for (double x : sh.feed_ends) s.move(MoveKind::kFeed, {x, z});
  s.move(MoveKind::kRapid, {hole.retract, z});
  ++s.out.calls;
}

}  // namespace

bool hole_cycle_block(State& s, const NcBlock& b) {
  const HoleLines& lines = hole_lines(s);
  if (int p = plane_of(b); p != 0) s.plane = p;
  read_live_rpm(s, lines.live, b);  // before the test: M133 P1000 is no hole cycle
  if (b.calls.empty() && !lines.longer && (b.letters & lines.letters) == 0) return false;
  for (const std::optional<HoleLine>& h : lines.lines) {
    if (!h || !matches(*h, b, s.plane)) continue;
    std::map<std::string, double> v;
    if (!read_fields(s, *h, b, v)) return true;
    if (v.count("z") == 0 || (h->radial && v.count("x") == 0)) continue;
    const Hole hole = hole_of(*h, v, h->radial ? s.pos.x : s.pos.z);
    if (const NcWord* f = b.find("F")) s.f_register = s.value(*f, "F");  // F is modal
    const bool marked = s.hole_open && s.out.holes.back().feed_ends.empty();
    if (!marked) s.out.holes.emplace_back();
    s.hole_open = false;
    SimHole& sh = s.out.holes.back();
    sh.line = s.line;
    sh.line_text = std::string(s.line_text.substr(0, kKeptLineText));
    sh.source = h->call.empty() ? h->code.address + fmt::format("{:g}", h->code.number.value_or(0))
                                : h->call;
    sh.r = hole.r;
    sh.dir = hole.dir;
    sh.feed_ends = hole_feed_ends(hole);
    sh.left = true;
    sh.out = hole.r;
    if (hole.lead > 0) sh.lead = hole.lead;
    if (h->live) sh.lead = live_tap_lead(s, v);
    sh.c = s.c;
    if (h->radial) {
      radial_moves(s, sh, hole, v.at("z"));
      return true;
    }
    const double x = v.count("x") ? v.at("x") : s.pos.x;
    sh.x = x;
    s.move(MoveKind::kRapid, {x, hole.r});
    for (double z : sh.feed_ends) s.move(MoveKind::kFeed, {x, z});
    s.move(MoveKind::kRapid, {x, hole.retract});
    ++s.out.calls;
    return true;
  }
  return false;
}

void follow_hole(State& s, MoveKind kind, Vec2 from, Vec2 to) {
  SimHole& h = s.out.holes.back();
  // Along the hole's axis (Z, or X for a radial hole of a live tool) and across it.
  const auto along = [&](Vec2 v) { return h.radial ? v.x : v.z; };
  const auto across = [&](Vec2 v) { return h.radial ? v.z : v.x; };
  // On the centre line; off it only on a machine that drills face holes there
  // (millturn.face_holes) or radial holes (live tools), and after the first feed on the hole's
  // line.
  const bool at_hole = h.feed_ends.empty()
                           ? std::fabs(to.x) <= 1e-6 || s.m.face_holes || s.m.live_tools
                           : std::fabs(across(to) - (h.radial ? h.z : h.x)) <= 1e-6;
  if (!at_hole || (kind != MoveKind::kRapid && kind != MoveKind::kFeed)) {
    s.hole_open = false;
    return;
  }
  if (kind == MoveKind::kFeed && h.feed_ends.empty()) {
    // The first feed says which way the hole goes: along Z, or along X at one Z (radial).
    h.radial =
        s.m.live_tools && std::fabs(to.z - from.z) <= 1e-9 && std::fabs(to.x - from.x) > 1e-9;
  }
  if (kind == MoveKind::kFeed && std::fabs(along(to) - along(from)) > 1e-9 &&
      std::fabs(across(to) - across(from)) <= 1e-6) {
    if (h.feed_ends.empty()) {
      h.x = h.radial ? from.x : to.x;
      h.z = to.z;
      h.c = s.c;
      h.dir = along(to) < along(from) ? -1 : 1;
      h.r = along(from);
      h.line = s.line;
      h.line_text = std::string(s.line_text.substr(0, kKeptLineText));
    }
    if (h.feed_ends.empty() || (along(to) - h.feed_ends.back()) * h.dir > 1e-9) {
      if (h.feed_ends.size() < kMaxHolePecks) h.feed_ends.push_back(along(to));
      h.left = false;
      h.out.reset();
      return;
    }
  }
  if (h.feed_ends.empty()) return;
  if (!h.out || (along(to) - *h.out) * h.dir < 0) h.out = along(to);
  if ((along(to) - h.r) * h.dir <= 1e-9) h.left = true;
}

}  // namespace clpost::sim

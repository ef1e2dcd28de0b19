// The modal state verify compares besides the path (CutState: feed mode, spindle, tool), read
// from a program through the machine file as the control would read it: the feed-mode and
// spindle codes, and the words of the templates tool_change, spindle_rpm, spindle_css and
// spindle_stop taken apart ("T{tool:02}{offset:02}" reads T0303 as tool 3, offset 3; "G50
// S{max_rpm}" makes S a speed limit in a G50 block). The machine file is the only source.
#include <fmt/format.h>

#include <algorithm>
#include <cctype>

#include "machine/machine_schema.h"
#include "simulator/sim_state.h"
#include "support/text.h"

namespace clpost::sim {

namespace {

const std::vector<std::string>* lines_of(const Machine& m, const TemplateSpec& t) {
  auto it = m.templates.find(std::string(t.name));
  return it == m.templates.end() ? nullptr : &it->second;
}

// The line of template `t` whose word holds field `field`: its words, which one, and the line's
// first code.
struct FieldLine {
  std::vector<TemplateToken> tokens;
  size_t at = 0;
  Code first_code;
  const TemplateToken& word() const { return tokens[at]; }
};
std::optional<FieldLine> field_line(const Machine& m, const TemplateSpec& t,
                                    std::string_view field) {
  const std::vector<std::string>* lines = lines_of(m, t);
  if (lines == nullptr) return std::nullopt;
  for (const std::string& line : *lines) {
    FieldLine fl;
    fl.tokens = template_tokens(m, line);
    bool found = false;
    for (size_t k = 0; k < fl.tokens.size(); ++k) {
      const TemplateToken& tok = fl.tokens[k];
      if (fl.first_code.empty() && !tok.code.empty()) fl.first_code = tok.code;
      for (const TemplateField& f : tok.fields)
        if (f.name == field && !found) found = true, fl.at = k;
    }
    if (found) return fl;
  }
  return std::nullopt;
}

void learn_spindle(const Machine& m, ModalWords& w) {
  w.cw = parse_code(m.code("spindle_cw"));
  w.ccw = parse_code(m.code("spindle_ccw"));
  if (const std::vector<std::string>* stop = lines_of(m, tmpl::kSpindleStop);
      stop != nullptr && !stop->empty())
    w.stop = template_code(m, tmpl::kSpindleStop);
  if (auto rpm = field_line(m, tmpl::kSpindleRpm, "rpm")) {
    w.rpm_address = rpm->word().address;
    w.rpm_mode = rpm->first_code;
  }
  if (auto css = field_line(m, tmpl::kSpindleCss, "speed")) {
    w.css_address = css->word().address;
    w.css_mode = css->first_code;
  }
  if (auto limit = field_line(m, tmpl::kSpindleCss, "max_rpm")) {
    w.limit_address = limit->word().address;
    // A limit block is told by its line's code (G50 S, G96 D), unless its word is a setting of
    // its own (LIMS=).
    if (w.limit_address.back() != '=') w.limit_code = limit->first_code;
  }
  StateReadback& r = w.readback;
  r.spindle = !w.cw.empty() && !w.ccw.empty() && !w.stop.empty() && !w.rpm_address.empty();
  r.css = r.spindle && !w.rpm_mode.empty() && !w.css_mode.empty() && !w.css_address.empty();
  r.max_rpm = r.css && !w.limit_address.empty();
}

void learn_tool(const Machine& m, ModalWords& w) {
  auto tool = field_line(m, tmpl::kToolChange, "tool");
  if (!tool) return;
  const std::vector<TemplateField>& f = tool->word().fields;
  // Fields after the first in one word are told apart by their widths only.
  const bool split =
      std::all_of(f.begin() + 1, f.end(), [](const TemplateField& x) { return x.width > 0; });
  if (!split || f.front().name != "tool") return;
  w.tool_address = tool->word().address;
  w.tool_fields = f;
  for (size_t k = 0; k < tool->tokens.size(); ++k) {
    const TemplateToken& t = tool->tokens[k];
    if (!t.code.empty()) w.tool_codes.push_back(t.code);
    if (k != tool->at)
      for (const TemplateField& x : t.fields)
        if (x.name == "offset" && t.fields.size() == 1) w.offset_address = t.address;
  }
  w.readback.tool = true;
  w.readback.offset =
      !w.offset_address.empty() ||
      std::any_of(f.begin(), f.end(), [](const TemplateField& x) { return x.name == "offset"; });
}

// A tool or offset number as clpost writes them (0..9999, as LOADTL takes them); else an error
// at the word and nothing.
std::optional<int> tool_number(State& s, double v, const std::string& field, const NcWord& w) {
  return s.whole(v, field, 0, 9999, w.col);
}

// T0303 with fields {tool,2},{offset,2}: tool 3, offset 3 (widths taken from the right).
void read_tool_word(State& s, const NcWord& w, const ModalWords& mw) {
  std::string_view digits = w.text;
  const bool all_digits = !digits.empty() && std::all_of(digits.begin(), digits.end(), is_digit);
  if (mw.tool_fields.size() == 1 || !all_digits) {
    if (std::optional<int> t = tool_number(s, w.value, "the tool", w)) s.cut.tool = *t;
    return;
  }
  for (size_t k = mw.tool_fields.size(); k-- > 0;) {
    const TemplateField& f = mw.tool_fields[k];
    const size_t n = k == 0 ? digits.size() : std::min<size_t>(f.width, digits.size());
    double v = 0;  // no overflow on a long word: tool_number refuses it
    for (char c : digits.substr(digits.size() - n)) v = v * 10 + (c - '0');
    digits.remove_suffix(n);
    const std::optional<int> number = tool_number(s, v, "the " + f.name, w);
    if (number && f.name == "tool") s.cut.tool = *number;
    if (number && f.name == "offset") s.cut.offset = *number;
  }
}

void read_spindle(State& s, const NcBlock& b, const ModalWords& w) {
  const NcWord* limit = w.limit_address.empty() ? nullptr : b.find(w.limit_address);
  if (limit != nullptr && !w.limit_code.empty() && !has_code(b, w.limit_code)) limit = nullptr;
  if (limit != nullptr && limit->has_value()) s.cut.max_rpm = s.value(*limit, "S");
  if (has_code(b, w.css_mode)) s.cut.css = true;
  if (has_code(b, w.rpm_mode)) s.cut.css = false;
  const std::string& speed_address = s.cut.css ? w.css_address : w.rpm_address;
  const NcWord* speed = speed_address.empty() ? nullptr : b.find(speed_address);
  if (speed != nullptr && speed != limit && speed->has_value()) s.cut.speed = s.value(*speed, "S");
  if (has_code(b, w.cw)) s.cut.spindle = SpindleRun::kCw;
  if (has_code(b, w.ccw)) s.cut.spindle = SpindleRun::kCcw;
  if (has_code(b, w.stop)) s.cut.spindle = SpindleRun::kOff;
}

// ModalWords::letters and longer, from its codes and words.
void learn_letters(ModalWords& w) {
  const auto add = [&w](const std::string& address) {
    if (address.empty()) return;
    const uint32_t bit = NcBlock::letter_bit(address);
    w.letters |= bit;
    w.longer = w.longer || bit == 0;
  };
  for (const Code* c : {&w.per_min, &w.per_rev, &w.css_per_min, &w.css_per_rev, &w.cw, &w.ccw,
                        &w.stop, &w.rpm_mode, &w.css_mode, &w.limit_code})
    add(c->address);
  for (const Code& c : w.tool_codes) add(c.address);
  for (const std::string* a :
       {&w.rpm_address, &w.css_address, &w.limit_address, &w.tool_address, &w.offset_address})
    add(*a);
}

}  // namespace

ModalWords modal_words(const Machine& m) {
  ModalWords w;
  w.per_min = parse_code(m.code("feed_per_min"));
  w.per_rev = parse_code(m.code("feed_per_rev"));
  if (m.control != nullptr && !m.control->css_feed_per_rev.empty()) {
    w.css_per_min = parse_code(m.control->css_feed_per_min);
    w.css_per_rev = parse_code(m.control->css_feed_per_rev);
  }
  w.readback.feed_mode = !w.per_min.empty() && !w.per_rev.empty();
  learn_spindle(m, w);
  learn_tool(m, w);
  learn_letters(w);
  return w;
}

void read_modal_words(State& s, const NcBlock& b, const ModalWords& w) {
  if (!w.longer && (b.letters & w.letters) == 0) return;  // most blocks: X and Z alone
  if (has_code(b, w.per_min)) s.cut.per_rev = 0;
  if (has_code(b, w.per_rev)) s.cut.per_rev = 1;
  if (!w.css_per_min.empty()) {
    if (has_code(b, w.per_min) || has_code(b, w.per_rev)) s.cut.css = false;
    if (has_code(b, w.css_per_min)) s.cut.per_rev = 0, s.cut.css = true;
    if (has_code(b, w.css_per_rev)) s.cut.per_rev = 1;
  }
  if (!w.tool_address.empty())
    if (const NcWord* t = b.find(w.tool_address); t != nullptr && t->has_value()) {
      const bool all = std::all_of(w.tool_codes.begin(), w.tool_codes.end(),
                                   [&](const Code& c) { return has_code(b, c); });
      if (all) {
        read_tool_word(s, *t, w);
        if (const NcWord* d = w.offset_address.empty() ? nullptr : b.find(w.offset_address))
          if (std::optional<int> o = tool_number(s, d->value, "the offset", *d)) s.cut.offset = *o;
      }
    }
  read_spindle(s, b, w);
}

}  // namespace clpost::sim

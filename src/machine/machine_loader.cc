#include "machine/machine_loader.h"

#include <fmt/format.h>
#include <yaml-cpp/depthguard.h>
#include <yaml-cpp/yaml.h>

#include <algorithm>
#include <charconv>
#include <cmath>
#include <filesystem>
#include <fstream>
#include <set>
#include <span>
#include <sstream>
#include <type_traits>

#include "machine/machine_schema.h"
#include "machine/template_values.h"
#include "machine/yaml_text.h"
#include "support/diagnostics.h"
#include "support/suggest.h"

namespace clpost {
namespace {

namespace fs = std::filesystem;

// The loader's view of one YAML file: diagnostics with the file's own line text.
struct Ctx {
  Diagnostics diags;
  YamlText text;
  bool is_post;
  // Addresses the machine's keys name (threading.lead_address, …): formats.<address> for them
  // is known too.
  std::vector<std::string> addresses = {};
  KeyOrigins* origins = nullptr;  // where each key was set, when asked for
  Schema spec = {};               // the keys, codes, formats and templates of m.controls

  SourceLoc loc(const YAML::Node& n) const {
    const YAML::Mark m = n.Mark();
    if (m.is_null()) return {};
    return SourceLoc{static_cast<uint32_t>(m.line + 1), static_cast<uint32_t>(m.column + 1)};
  }
  void error(const YAML::Node& n, std::string msg) {
    SourceLoc l = loc(n);
    diags.error(l, text.line(l.line), std::move(msg));
  }
  // Key `path` was set from node `n` (its key) of this file.
  void set_from(const std::string& path, const YAML::Node& n) {
    if (!origins) return;
    const std::string& file = diags.file();
    (*origins)[path] =
        file.starts_with("--set ") ? std::string("--set") : fmt::format("{}:{}", file, loc(n).line);
  }
};

// What node `n` holds, for "must be …, not X": 'fast', an empty value, nothing, a map, a list.
std::string shown_value(const YAML::Node& n) {
  if (!n.IsDefined() || n.IsNull()) return "nothing";
  if (n.IsScalar()) return n.Scalar().empty() ? "an empty value" : "'" + n.Scalar() + "'";
  return n.IsMap() ? "a map" : "a list";
}

bool get_string(Ctx& c, const YAML::Node& n, std::string_view key, std::string& out) {
  if (!n.IsScalar()) {
    c.error(n, fmt::format("'{}' must be a string", key));
    return false;
  }
  out = n.Scalar();
  return true;
}

bool get_bool(Ctx& c, const YAML::Node& n, std::string_view key, bool& out) {
  if (n.IsScalar()) {
    const std::string& s = n.Scalar();
    if (s == "true" || s == "yes" || s == "on") return out = true, true;
    if (s == "false" || s == "no" || s == "off") return out = false, true;
  }
  c.error(n, fmt::format("'{}' must be true or false, not {}", key, shown_value(n)));
  return false;
}

bool get_number(Ctx& c, const YAML::Node& n, std::string_view key, double lo, double hi,
                double& out) {
  double v = 0;
  bool ok = n.IsScalar();
  if (ok) {
    const std::string& s = n.Scalar();
    auto [p, ec] = std::from_chars(s.data(), s.data() + s.size(), v);
    ok = ec == std::errc() && p == s.data() + s.size() && std::isfinite(v);
  }
  if (!ok) {
    c.error(n, fmt::format("'{}' must be a number, not {}", key, shown_value(n)));
    return false;
  }
  if (v < lo || v > hi) {
    c.error(n, fmt::format("'{}' is {} but must be between {} and {}", key, v, lo, hi));
    return false;
  }
  out = v;
  return true;
}

// A number in [lo, hi] or the word `auto`.
bool get_number_or_auto(Ctx& c, const YAML::Node& n, std::string_view key, double lo, double hi,
                        LengthOrAuto& out) {
  if (n.IsScalar() && n.Scalar() == "auto") return out = {true, 0}, true;
  double v = 0;
  bool number = n.IsScalar();
  if (number) {
    const std::string& s = n.Scalar();
    auto [p, ec] = std::from_chars(s.data(), s.data() + s.size(), v);
    number = ec == std::errc() && p == s.data() + s.size();
  }
  if (!number) {
    const std::string text = n.IsScalar() ? n.Scalar() : "a collection";
    c.error(n, fmt::format("'{}' must be a number or auto, not '{}'{}", key, text,
                           did_you_mean(text, std::vector<std::string_view>{"auto"})));
    return false;
  }
  if (!get_number(c, n, key, lo, hi, v)) return false;
  out = {false, v};
  return true;
}

bool get_int(Ctx& c, const YAML::Node& n, std::string_view key, double lo, double hi, int& out) {
  double v = 0;
  if (!get_number(c, n, key, lo, hi, v)) return false;
  if (v != std::floor(v)) {
    c.error(n, fmt::format("'{}' must be a whole number, not {}", key, shown_value(n)));
    return false;
  }
  out = static_cast<int>(v);
  return true;
}

// The index of the choice `n` names, or -1 after an error.
int get_choice(Ctx& c, const YAML::Node& n, std::string_view key, std::span<const Choice> choices) {
  std::vector<std::string_view> names;
  for (size_t i = 0; i < choices.size(); ++i) {
    if (n.IsScalar() && n.Scalar() == choices[i].name) return static_cast<int>(i);
    names.push_back(choices[i].name);
  }
  std::string list;
  for (std::string_view s : names) list += fmt::format("{}{}", list.empty() ? "" : ", ", s);
  c.error(n, fmt::format("'{}' must be one of {}, not {}{}", key, list, shown_value(n),
                         n.IsScalar() ? did_you_mean(n.Scalar(), names) : ""));
  return -1;
}

bool get_list(Ctx& c, const YAML::Node& n, std::string_view key, std::vector<std::string>& out) {
  if (!n.IsSequence()) return c.error(n, fmt::format("'{}' must be a list", key)), false;
  out.clear();
  bool ok = true;
  for (const auto& item : n) ok &= get_string(c, item, key, out.emplace_back());
  return ok;
}

// Sets key `k` of `obj` (a Machine or a NumberFormat) from `n`: the member it names, by type.
template <typename Obj, typename Member>
bool set_member(Ctx& c, const YAML::Node& n, std::string_view path, KeyType type, double lo,
                double hi, std::span<const Choice> choices, Obj& obj, Member member) {
  auto& v = obj.*member;
  using V = std::decay_t<decltype(v)>;
  if constexpr (std::is_same_v<V, std::vector<std::string>>) {
    return get_list(c, n, path, v);
  } else if constexpr (std::is_same_v<V, double>) {
    return get_number(c, n, path, lo, hi, v);
  } else if constexpr (std::is_same_v<V, LengthOrAuto>) {
    return get_number_or_auto(c, n, path, lo, hi, v);
  } else if constexpr (std::is_same_v<V, int>) {
    return get_int(c, n, path, lo, hi, v);
  } else {
    if (type != KeyType::kChoice) {
      if constexpr (std::is_same_v<V, std::string>) return get_string(c, n, path, v);
      if constexpr (std::is_same_v<V, bool>) return get_bool(c, n, path, v);
      return false;
    }
    const int i = get_choice(c, n, path, choices);
    if (i < 0) return false;
    if constexpr (std::is_same_v<V, std::string>) {
      v = std::string(choices[i].stored);
    } else if constexpr (std::is_same_v<V, const Control*>) {  // "none", then the set's cycles
      v = i == 0 ? nullptr : obj.controls[i - 1];
      obj.own_keys_at = first_slot(obj.controls, v);
    } else if constexpr (std::is_same_v<V, const LoopBlock*>) {  // "g33", then the set's loops
      v = i == 0 ? nullptr : find_loop(obj.controls, choices[i].name);
    } else {
      v = static_cast<V>(i);  // enums in choice order; bool: the second choice is true
    }
    return true;
  }
}

bool set_key(Ctx& c, const YAML::Node& n, const KeySpec& k, Machine& m) {
  return std::visit(
      [&](auto member) {
        if constexpr (std::is_same_v<decltype(member), ControlSlot>)
          return get_number(c, n, k.path, k.lo, k.hi, m.control_values[member.index]);
        else
          return set_member(c, n, k.path, k.type, k.lo, k.hi, k.choices, m, member);
      },
      k.member);
}

bool check_template(Ctx& c, const YAML::Node& n, const TemplateSpec& spec,
                    const std::string& line) {
  size_t offset = 0;
  const std::string problem = check_template_line(spec, line, offset);
  if (problem.empty()) return true;
  SourceLoc l = c.loc(n);
  // Point at the field when it is found on the node's line (a quoted or plain scalar).
  const std::string_view text = c.text.line(l.line);
  if (offset > 0 && l.col >= 1) {
    const std::string_view from =
        std::string_view(line).substr(offset, line.find('}', offset) - offset);
    const size_t at = text.find(from, l.col - 1);
    if (at != std::string_view::npos) l.col = static_cast<uint32_t>(at + 1);
  }
  c.diags.error(l, text,
                fmt::format("bad template line '{}' in '{}': {}", line, spec.name, problem));
  return false;
}

bool apply_format(Ctx& c, const YAML::Node& key, const YAML::Node& node, NumberFormat& f) {
  const std::string addr = key.Scalar();
  if (!find_format(c.spec, addr) &&
      std::find(c.addresses.begin(), c.addresses.end(), addr) == c.addresses.end()) {
    std::vector<std::string_view> names;
    for (const NameSpec& s : c.spec.formats) names.push_back(s.name);
    c.error(key, fmt::format("unknown format 'formats.{}'{}: a format is an address the machine "
                             "writes or a named format (docs/machines.md)",
                             addr, did_you_mean(addr, names)));
    return false;
  }
  if (!node.IsMap()) {
    c.error(node, fmt::format("'formats.{}' must be a map", addr));
    return false;
  }
  bool ok = true;
  for (const auto& kv : node) {
    const std::string name = kv.first.Scalar();
    const std::string path = "formats." + addr + "." + name;
    if (const FormatKeySpec* k = find_format_key(name)) {
      c.set_from(path, kv.first);
      ok &= std::visit(
          [&](auto member) {
            return set_member(c, kv.second, path, k->type, k->lo, k->hi, {}, f, member);
          },
          k->member);
      continue;
    }
    std::vector<std::string_view> names;
    for (const FormatKeySpec& s : format_keys()) names.push_back(s.name);
    c.error(kv.first, fmt::format("unknown key '{}'{}", path, did_you_mean(name, names)));
    ok = false;
  }
  return ok;
}

bool apply_codes(Ctx& c, const YAML::Node& value, Machine& m) {
  if (!value.IsMap()) return c.error(value, "'codes' must be a map of name: code"), false;
  bool ok = true;
  for (const auto& kv : value) {
    const std::string name = kv.first.Scalar();
    if (!find_code(c.spec, name)) {
      std::vector<std::string_view> names;
      for (const NameSpec& s : c.spec.codes) names.push_back(s.name);
      c.error(kv.first, fmt::format("unknown code 'codes.{}'{}", name, did_you_mean(name, names)));
      ok = false;
      continue;
    }
    c.set_from("codes." + name, kv.first);
    ok &= get_string(c, kv.second, "codes." + name, m.codes[name]);
  }
  return ok;
}

// One template: a line, a list of lines, or nothing (null or []: the integrator's choice to
// write nothing for it).
bool apply_template(Ctx& c, const YAML::Node& key, const YAML::Node& value, Machine& m) {
  const std::string tname = key.Scalar();
  const TemplateSpec* spec = find_template(c.spec, tname);
  if (!spec) {
    std::vector<std::string_view> names;
    for (const TemplateSpec* t : c.spec.templates) names.push_back(t->name);
    c.error(key,
            fmt::format("unknown template 'templates.{}'{}", tname, did_you_mean(tname, names)));
    return false;
  }
  std::vector<std::string> lines;
  std::vector<YAML::Node> nodes;
  if (value.IsScalar()) {
    lines.push_back(value.Scalar());
    nodes.push_back(value);
  } else if (value.IsSequence()) {
    for (const auto& line : value) {
      if (!line.IsScalar()) {
        c.error(line, fmt::format("'templates.{}' lines must be strings", tname));
        return false;
      }
      lines.push_back(line.Scalar());
      nodes.push_back(line);
    }
  } else if (!value.IsNull()) {
    c.error(value, fmt::format("'templates.{}' must be a line or a list of lines", tname));
    return false;
  }
  bool ok = true;
  for (size_t i = 0; i < lines.size(); ++i) ok &= check_template(c, nodes[i], *spec, lines[i]);
  c.set_from("templates." + tname, key);
  m.templates[tname] = std::move(lines);
  return ok;
}

bool apply_templates(Ctx& c, const YAML::Node& value, Machine& m) {
  if (!value.IsMap()) return c.error(value, "'templates' must be a map of name: [lines]"), false;
  bool ok = true;
  for (const auto& kv : value) ok &= apply_template(c, kv.first, kv.second, m);
  return ok;
}

// Keys whose value is a map of declared names.
const std::vector<std::string>& map_keys() {
  static const std::vector<std::string> kMaps = {"formats", "codes", "templates"};
  return kMaps;
}

std::vector<std::string> valid_children(const Schema& s, const std::string& prefix) {
  std::set<std::string> out;
  for (const KeySpec& k : s.keys) {
    if (!k.path.starts_with(prefix)) continue;
    std::string_view rest = k.path.substr(prefix.size());
    out.insert(std::string(rest.substr(0, rest.find('.'))));
  }
  if (prefix.empty())
    for (const std::string& m : map_keys()) out.insert(m);
  return {out.begin(), out.end()};
}

// Whether keys start with `prefix` ("limits."): `prefix` names a section, not a scalar.
bool has_children(const Schema& s, const std::string& prefix) {
  for (const KeySpec& k : s.keys)
    if (k.path.starts_with(prefix)) return true;
  return false;
}

bool apply_map(Ctx& c, const YAML::Node& node, const std::string& prefix, Machine& m);

bool apply_key(Ctx& c, const YAML::Node& key, const YAML::Node& value, const std::string& prefix,
               Machine& m) {
  const std::string name = key.Scalar();
  const std::string path = prefix + name;
  if (prefix.empty() && name == "formats") {
    if (!value.IsMap())
      return c.error(value, "'formats' must be a map of address: {decimals: ...}"), false;
    bool ok = true;
    for (const auto& kv : value)
      ok &= apply_format(c, kv.first, kv.second, m.formats[kv.first.Scalar()]);
    return ok;
  }
  if (prefix.empty() && name == "codes") return apply_codes(c, value, m);
  if (prefix.empty() && name == "templates") return apply_templates(c, value, m);
  if (const KeySpec* k = find_key(c.spec, path)) {
    if (k->machine_only && c.is_post) {
      c.error(key, fmt::format("a post cannot '{}' another post", path));
      return false;
    }
    c.set_from(path, key);
    return set_key(c, value, *k, m);
  }
  if (has_children(c.spec, path + ".")) {
    if (!value.IsMap()) return c.error(value, fmt::format("'{}' must be a map", path)), false;
    return apply_map(c, value, path + ".", m);
  }
  c.error(key, fmt::format("unknown key '{}'{}", path,
                           did_you_mean(name, valid_children(c.spec, prefix))));
  return false;
}

bool apply_map(Ctx& c, const YAML::Node& node, const std::string& prefix, Machine& m) {
  bool ok = true;
  for (const auto& kv : node) {
    if (!kv.first.IsScalar()) {
      c.error(kv.first, "keys must be plain names");
      ok = false;
      continue;
    }
    ok &= apply_key(c, kv.first, kv.second, prefix, m);
  }
  return ok;
}

// The addresses machine keys name, from `m` and from the `threading` map of the document being
// read (a file may give a format for the address it sets further down).
std::vector<std::string> named_addresses(const Machine& m, const YAML::Node& root) {
  std::vector<std::string> out = {m.thread_lead_address, m.thread_lead_address_x, m.tpi_address,
                                  m.start_angle_address};
  const YAML::Node t = root["threading"];
  if (t && t.IsMap())
    for (const char* k : {"lead_address", "lead_address_x", "tpi_address", "start_angle_address"})
      if (t[k] && t[k].IsScalar()) out.push_back(t[k].Scalar());
  return out;
}

bool read_file(const std::string& path, std::string& out) {
  std::ifstream in(path, std::ios::binary);
  if (!in) return false;
  std::ostringstream ss;
  ss << in.rdbuf();
  out = ss.str();
  return true;
}

bool looks_like_path(std::string_view s) {
  return s.find('/') != std::string_view::npos || s.ends_with(".yaml") || s.ends_with(".yml");
}

// A control's own codes (machine/control.h: FixedCode) are its meaning, not machine data: a post,
// machine file or --set that redefines one is an error at the key (docs/cl-meaning.md).
bool check_fixed_code(const Machine& m, const FixedCode& f, const KeyOrigins& origins,
                      const YamlText& machine_text, std::string& errors) {
  if (m.code(std::string(f.key)) == f.code) return true;
  const std::string key = fmt::format("codes.{}", f.key);
  const std::string message = fmt::format(
      "{} is '{}', but on the {} control {} {}: a control's own codes are its meaning, not "
      "machine data",
      key, m.code(std::string(f.key)), m.control->name, f.code, f.meaning);
  const auto o = origins.find(key);
  const std::string where = o == origins.end() ? m.source : o->second;
  const size_t colon = where.rfind(':');
  Diagnostics d(colon == std::string::npos ? where : where.substr(0, colon));
  const uint32_t line =
      colon == std::string::npos ? 0 : static_cast<uint32_t>(std::atoi(where.c_str() + colon + 1));
  // The line is shown when it is the machine file's (a post's key names the post file and line).
  const bool own = d.file() == m.source;
  const std::string_view text = own ? machine_text.line(line) : std::string_view();
  const size_t indent = text.find_first_not_of(' ');
  const uint32_t col = line == 0 ? 0 : static_cast<uint32_t>(indent == text.npos ? 0 : indent) + 1;
  d.error(SourceLoc{line, col}, text, message);
  errors += d.render_all();
  return false;
}

bool check_fixed_codes(const Machine& m, const KeyOrigins& origins, std::string_view text,
                       std::string& errors) {
  if (m.control == nullptr) return true;
  const YamlText t(text);
  bool ok = true;
  for (const FixedCode& f : kIsoMotionCodes) ok &= check_fixed_code(m, f, origins, t, errors);
  for (const FixedCode& f : m.control->fixed_codes)
    ok &= check_fixed_code(m, f, origins, t, errors);
  return ok;
}

// The inch decimals the machine file leaves out: a length address takes the control's least
// input increment in inch where it is finer than its decimals (Control::inch_length_increment),
// every other format its decimals.
void resolve_inch_decimals(Machine& m) {
  constexpr std::string_view kLengths[] = {"X", "Z", "I", "K", "R", "U", "W"};
  const double inc = m.control ? m.control->inch_length_increment : 0;
  const int digits = inc > 0 ? static_cast<int>(std::lround(-std::log10(inc))) : 0;
  for (auto& [address, f] : m.formats) {
    if (f.inch_decimals >= 0) continue;
    const bool length =
        std::find(std::begin(kLengths), std::end(kLengths), address) != std::end(kLengths);
    f.inch_decimals = length && f.scale == 1 ? std::max(f.decimals, digits) : f.decimals;
  }
}

}  // namespace

bool apply_machine_yaml(std::string_view file, std::string_view text, bool is_post, Machine& m,
                        std::string& errors, KeyOrigins* origins) {
  Ctx c{Diagnostics(std::string(file)), YamlText(text), is_post};
  c.origins = origins;
  c.spec = schema(m.controls);
  // The control keys' slots m has not yet (a machine made in code): their initial values.
  for (size_t i = m.control_values.size(); i < c.spec.control_defaults.size(); ++i)
    m.control_values.push_back(c.spec.control_defaults[i]);
  YAML::Node root;
  try {
    root = YAML::Load(std::string(text));
  } catch (const YAML::ParserException& e) {
    SourceLoc l{static_cast<uint32_t>(e.mark.line + 1), static_cast<uint32_t>(e.mark.column + 1)};
    // yaml-cpp says "bad file" when it stops recursing (at a depth of 2000): say what it means.
    const bool too_deep = dynamic_cast<const YAML::DeepRecursion*>(&e) != nullptr;
    c.diags.error(l, c.text.line(l.line),
                  too_deep ? "invalid YAML: nested too deeply (a machine or post file needs a "
                             "few levels, the YAML reader stops at 2000)"
                           : "invalid YAML: " + e.msg);
    errors += c.diags.render_all();
    return false;
  }
  if (root.IsNull()) return true;  // an empty file changes nothing
  if (!root.IsMap()) {
    c.error(root, "a machine or post file must be a map of keys");
    errors += c.diags.render_all();
    return false;
  }
  c.addresses = named_addresses(m, root);
  bool ok = apply_map(c, root, "", m);
  errors += c.diags.render_all();
  return ok && !c.diags.has_errors();
}

namespace {

bool check_required(const std::string& path, const std::string& text, const Machine& m,
                    std::string& errors) {
  const Schema s = schema(m.controls);
  std::vector<std::string> missing;
  for (const NameSpec& c : s.codes)
    if (c.required && m.code(std::string(c.name)).empty())
      missing.push_back(fmt::format("codes.{}", c.name));
  std::vector<const TemplateSpec*> selected;  // required by a setting
  for (const TemplateSpec* t : s.templates) {
    if (!template_required(s, *t, m) || m.templates.count(std::string(t->name))) continue;
    if (t->need == Need::kAlways)
      missing.push_back(fmt::format("templates.{}", t->name));
    else
      selected.push_back(t);
  }
  if (missing.empty() && selected.empty()) return true;
  YamlText t(text);
  uint32_t line = m.post.empty() ? 1 : t.find_key_line("extends");
  Diagnostics d(path);
  std::string list;
  for (const std::string& k : missing) list += (list.empty() ? "'" : ", '") + k + "'";
  if (!missing.empty())
    d.error(SourceLoc{line, 1}, t.line(line),
            m.post.empty()
                ? fmt::format("missing required {} {} (a machine file normally 'extends' a post "
                              "from posts/ that defines them)",
                              missing.size() == 1 ? "key" : "keys", list)
                : fmt::format("missing required {} {}: empty or absent in this machine and its "
                              "post '{}'",
                              missing.size() == 1 ? "key" : "keys", list, m.post));
  for (const TemplateSpec* s : selected)
    d.error(
        SourceLoc{line, 1}, t.line(line),
        fmt::format("{} is '{}', which writes template 'templates.{}': absent in this machine{}",
                    s->setting, s->choice, s->name,
                    m.post.empty() ? std::string() : fmt::format(" and its post '{}'", m.post)));
  errors += d.render_all();
  return false;
}

}  // namespace

namespace {

// The machine file of a name (machines/NAME.yaml in the first data dir that has it) or a path.
bool find_machine_file(std::string_view name_or_path, const std::vector<std::string>& data_dirs,
                       std::string& path, std::string& errors) {
  if (looks_like_path(name_or_path)) {
    path = std::string(name_or_path);
    return true;
  }
  for (const std::string& dir : data_dirs) {
    std::string p = dir + "/machines/" + std::string(name_or_path) + ".yaml";
    if (fs::exists(p)) {
      path = p;
      return true;
    }
  }
  std::vector<std::string> names;
  for (const MachineInfo& mi : list_machines(data_dirs)) names.push_back(mi.name);
  std::string list;
  for (const std::string& n : names) list += (list.empty() ? "" : ", ") + n;
  errors +=
      fmt::format("clpost: error: unknown machine '{}'{}; shipped machines: {}\n", name_or_path,
                  did_you_mean(name_or_path, names), list.empty() ? "none found" : list);
  return false;
}

// Applies post `post`, which the machine file `path` (text `machine_text`) extends, to `m`.
// Posts live in posts/ beside the machines/ folder of the machine file, or in a data dir.
bool apply_post(const std::string& path, const std::string& machine_text, const std::string& post,
                const std::vector<std::string>& data_dirs, Machine& m, std::string& errors,
                KeyOrigins* origins) {
  std::vector<std::string> candidates = {
      (fs::path(path).parent_path() / ".." / "posts" / (post + ".yaml"))
          .lexically_normal()
          .string(),
      (fs::path(path).parent_path() / (post + ".yaml")).string()};
  for (const std::string& dir : data_dirs) candidates.push_back(dir + "/posts/" + post + ".yaml");
  std::string post_path;
  for (const std::string& cand : candidates)
    if (fs::exists(cand)) {
      post_path = cand;
      break;
    }
  if (post_path.empty()) {
    YamlText t(machine_text);
    uint32_t line = t.find_key_line("extends");
    Diagnostics d(path);
    d.error(SourceLoc{line, 1}, t.line(line),
            fmt::format("post '{}' not found (looked in posts/ beside the machine file and in "
                        "the data directories)",
                        post));
    errors += d.render_all();
    return false;
  }
  std::string post_text;
  if (!read_file(post_path, post_text)) {
    errors += fmt::format("{}: error: cannot read post file\n", post_path);
    return false;
  }
  return apply_machine_yaml(post_path, post_text, true, m, errors, origins);
}

// Applies one `--set key.path=value` to `m`.
bool apply_override(const std::string& ov, Machine& m, std::string& errors, KeyOrigins* origins) {
  size_t eq = ov.find('=');
  if (eq == std::string::npos || eq == 0) {
    errors += ov.empty() ? std::string("--set: error: expected key.path=value, got nothing\n")
                         : fmt::format("--set: error: expected key.path=value, got '{}'\n", ov);
    return false;
  }
  // Turn "a.b.c=v" into the YAML document "a: {b: {c: v}}" and apply it like a file.
  std::string key = ov.substr(0, eq), value = ov.substr(eq + 1);
  std::string doc;
  size_t depth = 0, start = 0;
  for (size_t dot; (dot = key.find('.', start)) != std::string::npos; start = dot + 1, ++depth)
    doc += key.substr(start, dot - start) + ": {";
  doc += key.substr(start) + ": " + (value.empty() ? "''" : value) + std::string(depth, '}');
  std::string set_errors;
  if (apply_machine_yaml("--set " + ov, doc, false, m, set_errors, origins)) return true;
  // The YAML document was made here, so its line, column and text mean nothing to the user:
  // keep only `--set key=value: error: message`.
  std::string prefix = "--set " + ov + ":1:";
  start = 0;
  while (start < set_errors.size()) {
    size_t end = set_errors.find('\n', start);
    std::string line = set_errors.substr(start, end - start);
    if (line.starts_with(prefix)) {
      size_t colon = line.find(':', prefix.size());
      errors += "--set " + ov + line.substr(colon) + "\n";
    }
    start = end == std::string::npos ? set_errors.size() : end + 1;
  }
  return false;
}

}  // namespace

bool load_machine(std::string_view name_or_path, const std::vector<std::string>& data_dirs,
                  const std::vector<std::string>& overrides, ControlSet controls, Machine& out,
                  std::string& errors, KeyOrigins* origins) {
  KeyOrigins own_origins;  // where each key came from, for the errors of check_fixed_codes
  if (origins == nullptr) origins = &own_origins;
  std::string path;
  if (!find_machine_file(name_or_path, data_dirs, path, errors)) return false;
  std::string machine_text;
  if (!read_file(path, machine_text)) {
    errors += fmt::format("{}: error: cannot read machine file\n", path);
    return false;
  }
  // The machine file names its post; read that first so the machine's keys override it.
  Machine probe;
  probe.controls = controls;
  std::string probe_errors;
  if (!apply_machine_yaml(path, machine_text, false, probe, probe_errors)) {
    errors += probe_errors;
    return false;
  }
  Machine m;
  m.controls = controls;
  m.name = fs::path(path).stem().string();
  m.source = path;
  if (!probe.post.empty() &&
      !apply_post(path, machine_text, probe.post, data_dirs, m, errors, origins))
    return false;
  if (!apply_machine_yaml(path, machine_text, false, m, errors, origins)) return false;
  for (const std::string& ov : overrides)
    if (!apply_override(ov, m, errors, origins)) return false;
  if (!check_required(path, machine_text, m, errors)) return false;
  resolve_inch_decimals(m);
  if (!check_fixed_codes(m, *origins, machine_text, errors)) return false;
  out = std::move(m);
  return true;
}

std::vector<MachineInfo> list_machines(const std::vector<std::string>& data_dirs) {
  std::map<std::string, MachineInfo> found;
  for (const std::string& dir : data_dirs) {
    std::error_code ec;
    for (const auto& entry : fs::directory_iterator(dir + "/machines", ec)) {
      if (entry.path().extension() != ".yaml") continue;
      std::string name = entry.path().stem().string();
      if (found.count(name)) continue;
      MachineInfo info{name, "", entry.path().string()};
      std::string text;
      if (read_file(info.path, text)) {
        try {
          YAML::Node root = YAML::Load(text);
          if (root.IsMap() && root["description"] && root["description"].IsScalar())
            info.description = root["description"].Scalar();
        } catch (const YAML::Exception&) {
          info.description = "(machine file does not parse)";
        }
      }
      found[name] = info;
    }
  }
  std::vector<MachineInfo> out;
  for (auto& [name, info] : found) out.push_back(std::move(info));
  return out;
}

}  // namespace clpost

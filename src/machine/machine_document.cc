// Applying one YAML document (a post, a machine file, a --set) to a machine: its keys, formats,
// codes and templates, each checked against the schema of the machine's controls
// (machine_loader.h: apply_machine_yaml).
#include <fmt/format.h>
#include <yaml-cpp/depthguard.h>
#include <yaml-cpp/yaml.h>

#include <algorithm>
#include <set>

#include "machine/machine_loader.h"
#include "machine/template_values.h"
#include "machine/yaml_getters.h"
#include "support/suggest.h"

namespace clpost {
namespace {

bool check_template(YamlDoc& c, const YAML::Node& n, const TemplateSpec& spec,
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

bool apply_format(YamlDoc& c, const YAML::Node& key, const YAML::Node& node, NumberFormat& f) {
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
      ok &= set_format_key(c, kv.second, path, *k, f);
      continue;
    }
    std::vector<std::string_view> names;
    for (const FormatKeySpec& s : format_keys()) names.push_back(s.name);
    c.error(kv.first, fmt::format("unknown key '{}'{}", path, did_you_mean(name, names)));
    ok = false;
  }
  return ok;
}

bool apply_codes(YamlDoc& c, const YAML::Node& value, Machine& m) {
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
bool apply_template(YamlDoc& c, const YAML::Node& key, const YAML::Node& value, Machine& m) {
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

bool apply_templates(YamlDoc& c, const YAML::Node& value, Machine& m) {
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

bool apply_map(YamlDoc& c, const YAML::Node& node, const std::string& prefix, Machine& m);

bool apply_key(YamlDoc& c, const YAML::Node& key, const YAML::Node& value,
               const std::string& prefix, Machine& m) {
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

bool apply_map(YamlDoc& c, const YAML::Node& node, const std::string& prefix, Machine& m) {
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

}  // namespace

bool apply_machine_yaml(std::string_view file, std::string_view text, bool is_post, Machine& m,
                        std::string& errors, KeyOrigins* origins) {
  YamlDoc c{Diagnostics(std::string(file)), YamlText(text), is_post};
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

}  // namespace clpost

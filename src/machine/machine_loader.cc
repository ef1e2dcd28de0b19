// Loading a machine: finding its file (a name or a path), the post it extends, the --set
// overrides, then what the whole must have (required codes and templates, the control's fixed
// codes, inch decimals); and listing the shipped machines. Each document is applied by
// machine_document.cc.
#include "machine/machine_loader.h"

#include <fmt/format.h>
#include <yaml-cpp/yaml.h>

#include <algorithm>
#include <cmath>
#include <filesystem>
#include <fstream>
#include <sstream>

#include "machine/fixed_code_check.h"
#include "machine/machine_schema.h"
#include "machine/yaml_text.h"
#include "support/diagnostics.h"
#include "support/suggest.h"

namespace clpost {
namespace {

namespace fs = std::filesystem;

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

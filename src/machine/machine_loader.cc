#include "machine/machine_loader.h"

#include <fmt/args.h>
#include <fmt/format.h>
#include <yaml-cpp/depthguard.h>
#include <yaml-cpp/yaml.h>

#include <algorithm>
#include <charconv>
#include <cmath>
#include <filesystem>
#include <fstream>
#include <functional>
#include <set>
#include <sstream>

#include "machine/yaml_text.h"
#include "support/diagnostics.h"

namespace clpost {
namespace {

namespace fs = std::filesystem;

// Edit distance for "did you mean" suggestions.
// The edit distance between `a` and `b`, or `limit` when it is `limit` or more: nothing is
// computed when the lengths alone say so, and the rows stop as soon as every cell has reached
// it (a key of garbage costs a few rows per name, not the whole table).
size_t edit_distance(std::string_view a, std::string_view b, size_t limit) {
  // The distance is at least the difference in length: a long garbage key costs nothing.
  const size_t gap = a.size() > b.size() ? a.size() - b.size() : b.size() - a.size();
  if (gap >= limit) return limit;
  // Two rows of b.size() + 1: on the stack for the short names compared here.
  constexpr size_t kStackRow = 64;
  size_t stack[2 * kStackRow];
  std::vector<size_t> heap;
  size_t* prev = stack;
  size_t* cur = stack + kStackRow;
  if (b.size() + 1 > kStackRow) {
    heap.resize(2 * (b.size() + 1));
    prev = heap.data();
    cur = prev + b.size() + 1;
  }
  for (size_t j = 0; j <= b.size(); ++j) prev[j] = j;
  for (size_t i = 1; i <= a.size(); ++i) {
    cur[0] = i;
    size_t row_min = i;
    for (size_t j = 1; j <= b.size(); ++j) {
      const size_t sub = prev[j - 1] + (a[i - 1] == b[j - 1] ? 0 : 1);
      cur[j] = std::min(std::min(prev[j], cur[j - 1]) + 1, sub);
      row_min = std::min(row_min, cur[j]);
    }
    if (row_min >= limit) return limit;  // the cells only grow from here on
    std::swap(prev, cur);
  }
  return std::min(prev[b.size()], limit);
}

std::string suggestion(std::string_view key, const std::vector<std::string>& valid) {
  size_t best = 3;  // at most two edits away
  std::string found;
  for (const std::string& v : valid) {
    size_t d = edit_distance(key, v, best);
    if (d < best) best = d, found = v;
  }
  return found.empty() ? std::string() : fmt::format(" (did you mean '{}'?)", found);
}

// The loader's view of one YAML file: diagnostics with the file's own line text.
struct Ctx {
  Diagnostics diags;
  YamlText text;
  bool is_post;

  SourceLoc loc(const YAML::Node& n) const {
    const YAML::Mark m = n.Mark();
    if (m.is_null()) return {};
    return SourceLoc{static_cast<uint32_t>(m.line + 1), static_cast<uint32_t>(m.column + 1)};
  }
  void error(const YAML::Node& n, std::string msg) {
    SourceLoc l = loc(n);
    diags.error(l, text.line(l.line), std::move(msg));
  }
};

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
  c.error(
      n, fmt::format("'{}' must be true or false, not '{}'", key,
                     n.IsScalar() ? n.Scalar() : std::string("a ") + (n.IsMap() ? "map" : "list")));
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
    c.error(n, fmt::format("'{}' must be a number, not '{}'", key,
                           n.IsScalar() ? n.Scalar() : "a collection"));
    return false;
  }
  if (v < lo || v > hi) {
    c.error(n, fmt::format("'{}' is {} but must be between {} and {}", key, v, lo, hi));
    return false;
  }
  out = v;
  return true;
}

bool get_int(Ctx& c, const YAML::Node& n, std::string_view key, int lo, int hi, int& out) {
  double v = 0;
  if (!get_number(c, n, key, lo, hi, v)) return false;
  if (v != std::floor(v)) {
    c.error(n, fmt::format("'{}' must be a whole number, not '{}'", key, n.Scalar()));
    return false;
  }
  out = static_cast<int>(v);
  return true;
}

template <typename E>
bool get_choice(Ctx& c, const YAML::Node& n, std::string_view key,
                const std::vector<std::pair<std::string, E>>& choices, E& out) {
  std::vector<std::string> names;
  for (const auto& [name, value] : choices) {
    if (n.IsScalar() && n.Scalar() == name) return out = value, true;
    names.push_back(name);
  }
  std::string list;
  for (const std::string& s : names) list += (list.empty() ? "" : ", ") + s;
  c.error(n, fmt::format("'{}' must be one of {}, not '{}'{}", key, list,
                         n.IsScalar() ? n.Scalar() : "a collection",
                         n.IsScalar() ? suggestion(n.Scalar(), names) : ""));
  return false;
}

// Template lines are fmt format strings with named fields; these are the fields each template
// may use (checked at load time so that a typo fails here, not in the middle of a batch).
const std::map<std::string, std::vector<std::string>>& template_fields() {
  static const std::map<std::string, std::vector<std::string>> kFields = {
      {"program_start", {"program_number", "program_name", "units_code", "machine", "file"}},
      {"program_end", {"program_number", "program_name"}},
      {"tool_change", {"tool", "offset", "tool_name"}},
      {"spindle_rpm", {"rpm", "direction"}},
      {"spindle_css", {"speed", "max_rpm", "direction"}},
      {"spindle_stop", {}},
      {"dwell", {"seconds", "revolutions"}},
      {"cycle99",
       {"spl", "dm1", "fpl", "dm2", "app", "rop", "tdep", "fal", "iang", "nsp", "nrc", "nid", "pit",
        "vari", "numth", "vrt", "pita", "psys"}},
      {"cycle96", {"diath", "axsa", "form"}},
      {"fanuc_g76",
       {"m", "chamfer", "angle", "min_cut", "allowance", "x", "z", "taper", "height", "first_cut",
        "lead"}},
      {"haas_g76",
       {"x", "z", "taper", "height", "first_cut", "angle", "mode", "start_angle", "lead"}},
      {"g92", {"x", "z", "taper", "lead", "start_angle"}},
      {"g92_next", {"x", "z", "taper", "lead", "start_angle"}},
      {"linuxcnc_g76", {"p", "z", "i", "j", "k", "r", "q", "h"}},
      {"linuxcnc_g76_taper", {"p", "z", "i", "j", "k", "r", "q", "h", "e", "l"}},
      {"heidenhain_g31",
       {"f", "u", "ic", "v", "h", "a", "d", "q", "c", "bd", "b", "p", "k", "x1", "z1", "x2", "z2"}},
  };
  return kFields;
}

// fmt writes as many characters as a field's width or precision says: `{tool:>1000000000}`
// would make a 1 GB line. Widths and precisions are kept to two digits, and never taken from a
// field (`{tool:{offset}}`). Returns what is wrong, or nothing.
std::string oversized_field(std::string_view line) {
  constexpr unsigned kMaxWidth = 99;
  for (size_t i = 0; i < line.size(); ++i) {
    if (line[i] != '{') continue;
    if (i + 1 < line.size() && line[i + 1] == '{') {
      ++i;
      continue;
    }
    const size_t end = line.find('}', i);
    if (end == std::string_view::npos) return {};  // fmt says what is wrong
    const std::string_view field = line.substr(i + 1, end - i - 1);
    i = end;
    const size_t colon = field.find(':');
    if (colon == std::string_view::npos) continue;
    const std::string_view spec = field.substr(colon + 1);
    if (spec.find('{') != std::string_view::npos)
      return "a width or precision cannot be taken from a field";
    for (size_t k = 0; k < spec.size();) {
      if (spec[k] < '0' || spec[k] > '9') {
        ++k;
        continue;
      }
      unsigned value = 0;
      size_t j = k;
      for (; j < spec.size() && spec[j] >= '0' && spec[j] <= '9'; ++j)
        value = std::min(value * 10 + static_cast<unsigned>(spec[j] - '0'), kMaxWidth + 1);
      if (value > kMaxWidth)
        return fmt::format("width or precision {} is too large (at most {})", spec.substr(k, j - k),
                           kMaxWidth);
      k = j;
    }
  }
  return {};
}

bool check_template(Ctx& c, const YAML::Node& n, const std::string& name, const std::string& line) {
  if (std::string problem = oversized_field(line); !problem.empty()) {
    c.error(n, fmt::format("bad template line '{}' in '{}': {}", line, name, problem));
    return false;
  }
  fmt::dynamic_format_arg_store<fmt::format_context> args;
  for (const std::string& f : template_fields().at(name)) {
    // Whole numbers are passed as numbers (so "{tool:02}" works); the rest as formatted text.
    if (f == "program_number" || f == "tool" || f == "offset")
      args.push_back(fmt::arg(f.c_str(), 0));
    else
      args.push_back(fmt::arg(f.c_str(), std::string("0")));
  }
  try {
    (void)fmt::vformat(line, args);
  } catch (const fmt::format_error& e) {
    std::string fields;
    for (const std::string& f : template_fields().at(name))
      fields += (fields.empty() ? "{" : ", {") + f + "}";
    c.error(n, fmt::format("bad template line '{}' in '{}': {} (fields: {})", line, name, e.what(),
                           fields.empty() ? "none" : fields));
    return false;
  }
  return true;
}

bool apply_format(Ctx& c, const YAML::Node& node, const std::string& addr, NumberFormat& f) {
  if (!node.IsMap()) {
    c.error(node, fmt::format("'formats.{}' must be a map", addr));
    return false;
  }
  static const std::vector<std::string> kKeys = {"decimals", "trailing_zeros", "decimal_point",
                                                 "leading_zero", "scale"};
  bool ok = true;
  for (const auto& kv : node) {
    const std::string key = kv.first.Scalar();
    const std::string path = "formats." + addr + "." + key;
    if (key == "decimals")
      ok &= get_int(c, kv.second, path, 0, 9, f.decimals);
    else if (key == "trailing_zeros")
      ok &= get_bool(c, kv.second, path, f.trailing_zeros);
    else if (key == "decimal_point")
      ok &= get_bool(c, kv.second, path, f.decimal_point);
    else if (key == "leading_zero")
      ok &= get_bool(c, kv.second, path, f.leading_zero);
    else if (key == "scale")
      ok &= get_number(c, kv.second, path, 1e-6, 1e6, f.scale);
    else {
      c.error(kv.first, fmt::format("unknown key '{}'{}", path, suggestion(key, kKeys)));
      ok = false;
    }
  }
  return ok;
}

using Setter = std::function<bool(Ctx&, const YAML::Node&, Machine&)>;

// Every scalar key a post or machine file may hold, by dotted path.
const std::map<std::string, Setter>& scalar_keys() {
  static const std::map<std::string, Setter> kKeys = [] {
    std::map<std::string, Setter> k;
    k["description"] = [](Ctx& c, const YAML::Node& n, Machine& m) {
      return get_string(c, n, "description", m.description);
    };
    k["units"] = [](Ctx& c, const YAML::Node& n, Machine& m) {
      return get_choice<std::string>(c, n, "units", {{"mm", "mm"}, {"in", "in"}}, m.default_units);
    };
    k["cl.radial_axis"] = [](Ctx& c, const YAML::Node& n, Machine& m) {
      return get_choice<ClAxis>(c, n, "cl.radial_axis",
                                {{"x", ClAxis::kX}, {"y", ClAxis::kY}, {"z", ClAxis::kZ}},
                                m.cl_radial);
    };
    k["cl.axial_axis"] = [](Ctx& c, const YAML::Node& n, Machine& m) {
      return get_choice<ClAxis>(c, n, "cl.axial_axis",
                                {{"x", ClAxis::kX}, {"y", ClAxis::kY}, {"z", ClAxis::kZ}},
                                m.cl_axial);
    };
    k["cl.radial_is_diameter"] = [](Ctx& c, const YAML::Node& n, Machine& m) {
      return get_bool(c, n, "cl.radial_is_diameter", m.cl_x_is_diameter);
    };
    k["output.diameter"] = [](Ctx& c, const YAML::Node& n, Machine& m) {
      return get_bool(c, n, "output.diameter", m.diameter_output);
    };
    k["output.extension"] = [](Ctx& c, const YAML::Node& n, Machine& m) {
      return get_string(c, n, "output.extension", m.extension);
    };
    k["output.line_ending"] = [](Ctx& c, const YAML::Node& n, Machine& m) {
      return get_choice<std::string>(c, n, "output.line_ending", {{"lf", "\n"}, {"crlf", "\r\n"}},
                                     m.line_ending);
    };
    k["output.program_number"] = [](Ctx& c, const YAML::Node& n, Machine& m) {
      return get_int(c, n, "output.program_number", 0, 99999999, m.program_number);
    };
    k["output.modal_codes"] = [](Ctx& c, const YAML::Node& n, Machine& m) {
      return get_bool(c, n, "output.modal_codes", m.modal_codes);
    };
    k["output.modal_words"] = [](Ctx& c, const YAML::Node& n, Machine& m) {
      return get_bool(c, n, "output.modal_words", m.modal_words);
    };
    k["comments.open"] = [](Ctx& c, const YAML::Node& n, Machine& m) {
      return get_string(c, n, "comments.open", m.comment_open);
    };
    k["comments.close"] = [](Ctx& c, const YAML::Node& n, Machine& m) {
      return get_string(c, n, "comments.close", m.comment_close);
    };
    k["comments.upper_case"] = [](Ctx& c, const YAML::Node& n, Machine& m) {
      return get_bool(c, n, "comments.upper_case", m.comment_upper);
    };
    k["comments.forbidden"] = [](Ctx& c, const YAML::Node& n, Machine& m) {
      return get_string(c, n, "comments.forbidden", m.comment_forbidden);
    };
    k["block_numbers.enabled"] = [](Ctx& c, const YAML::Node& n, Machine& m) {
      return get_bool(c, n, "block_numbers.enabled", m.block_numbers);
    };
    k["block_numbers.address"] = [](Ctx& c, const YAML::Node& n, Machine& m) {
      return get_string(c, n, "block_numbers.address", m.block_address);
    };
    k["block_numbers.start"] = [](Ctx& c, const YAML::Node& n, Machine& m) {
      return get_int(c, n, "block_numbers.start", 0, 99999999, m.block_start);
    };
    k["block_numbers.step"] = [](Ctx& c, const YAML::Node& n, Machine& m) {
      return get_int(c, n, "block_numbers.step", 1, 1000, m.block_step);
    };
    k["block_numbers.max"] = [](Ctx& c, const YAML::Node& n, Machine& m) {
      return get_int(c, n, "block_numbers.max", 1, 99999999, m.block_max);
    };
    k["limits.max_rpm"] = [](Ctx& c, const YAML::Node& n, Machine& m) {
      return get_number(c, n, "limits.max_rpm", 0, 1e6, m.max_rpm);
    };
    k["limits.max_feed"] = [](Ctx& c, const YAML::Node& n, Machine& m) {
      return get_number(c, n, "limits.max_feed", 0, 1e7, m.max_feed);
    };
    k["limits.max_feed_x"] = [](Ctx& c, const YAML::Node& n, Machine& m) {
      return get_number(c, n, "limits.max_feed_x", 0, 1e7, m.max_feed_x);
    };
    k["limits.max_feed_z"] = [](Ctx& c, const YAML::Node& n, Machine& m) {
      return get_number(c, n, "limits.max_feed_z", 0, 1e7, m.max_feed_z);
    };
    k["threading.strategy"] = [](Ctx& c, const YAML::Node& n, Machine& m) {
      return get_choice<ThreadStrategy>(c, n, "threading.strategy",
                                        {{"cycle", ThreadStrategy::kCycle},
                                         {"loop", ThreadStrategy::kLoop},
                                         {"emulate", ThreadStrategy::kEmulate}},
                                        m.thread_strategy);
    };
    k["threading.fallback"] = [](Ctx& c, const YAML::Node& n, Machine& m) {
      return get_choice<ThreadFallback>(c, n, "threading.fallback",
                                        {{"loop", ThreadFallback::kLoop},
                                         {"emulate", ThreadFallback::kEmulate},
                                         {"error", ThreadFallback::kError}},
                                        m.thread_fallback);
    };
    k["threading.option"] = [](Ctx& c, const YAML::Node& n, Machine& m) {
      return get_int(c, n, "threading.option", 0, 4, m.default_option);
    };
    k["threading.tool_angle"] = [](Ctx& c, const YAML::Node& n, Machine& m) {
      return get_number(c, n, "threading.tool_angle", 1e-9, 179.999999, m.default_tool_angle);
    };
    k["threading.start_angle_word"] = [](Ctx& c, const YAML::Node& n, Machine& m) {
      return get_bool(c, n, "threading.start_angle_word", m.start_angle_word);
    };
    k["threading.variable_lead"] = [](Ctx& c, const YAML::Node& n, Machine& m) {
      return get_bool(c, n, "threading.variable_lead", m.variable_lead);
    };
    k["threading.lead_address"] = [](Ctx& c, const YAML::Node& n, Machine& m) {
      return get_string(c, n, "threading.lead_address", m.thread_lead_address);
    };
    k["threading.start_angle_address"] = [](Ctx& c, const YAML::Node& n, Machine& m) {
      return get_string(c, n, "threading.start_angle_address", m.start_angle_address);
    };
    k["threading.cycle"] = [](Ctx& c, const YAML::Node& n, Machine& m) {
      return get_choice<ThreadCycle>(c, n, "threading.cycle",
                                     {{"none", ThreadCycle::kNone},
                                      {"cycle99", ThreadCycle::kCycle99},
                                      {"fanuc_g76", ThreadCycle::kFanucG76},
                                      {"haas_g76", ThreadCycle::kHaasG76},
                                      {"heidenhain_g31", ThreadCycle::kHeidenhainG31},
                                      {"linuxcnc_g76", ThreadCycle::kLinuxcncG76}},
                                     m.thread_cycle);
    };
    k["threading.loop"] = [](Ctx& c, const YAML::Node& n, Machine& m) {
      return get_choice<ThreadLoop>(c, n, "threading.loop",
                                    {{"g33", ThreadLoop::kG33}, {"g92", ThreadLoop::kG92}},
                                    m.thread_loop);
    };
    k["threading.lead_address_x"] = [](Ctx& c, const YAML::Node& n, Machine& m) {
      return get_string(c, n, "threading.lead_address_x", m.thread_lead_address_x);
    };
    k["threading.tpi_address"] = [](Ctx& c, const YAML::Node& n, Machine& m) {
      return get_string(c, n, "threading.tpi_address", m.tpi_address);
    };
    k["threading.run_in"] = [](Ctx& c, const YAML::Node& n, Machine& m) {
      return get_number(c, n, "threading.run_in", 0, 1000, m.run_in);
    };
    k["threading.extra_spring_passes"] = [](Ctx& c, const YAML::Node& n, Machine& m) {
      return get_bool(c, n, "threading.extra_spring_passes", m.extra_spring_passes);
    };
    k["threading.tolerance"] = [](Ctx& c, const YAML::Node& n, Machine& m) {
      return get_number(c, n, "threading.tolerance", 0, 1, m.thread_tolerance);
    };
    k["threading.cycle_pass_end"] = [](Ctx& c, const YAML::Node& n, Machine& m) {
      return get_choice<bool>(c, n, "threading.cycle_pass_end",
                              {{"fixed", false}, {"shifted", true}}, m.cycle_shifted_end);
    };
    k["threading.accept_pass_end"] = [](Ctx& c, const YAML::Node& n, Machine& m) {
      return get_bool(c, n, "threading.accept_pass_end", m.accept_pass_end);
    };
    k["threading.chamfer_angle"] = [](Ctx& c, const YAML::Node& n, Machine& m) {
      return get_number(c, n, "threading.chamfer_angle", 1, 89, m.chamfer_angle);
    };
    k["threading.haas_finish_allowance"] = [](Ctx& c, const YAML::Node& n, Machine& m) {
      return get_number(c, n, "threading.haas_finish_allowance", 0, 10, m.haas_finish_allowance);
    };
    k["threading.haas_min_cut"] = [](Ctx& c, const YAML::Node& n, Machine& m) {
      return get_number(c, n, "threading.haas_min_cut", 0, 10, m.haas_min_cut);
    };
    k["threading.haas_chamfer"] = [](Ctx& c, const YAML::Node& n, Machine& m) {
      return get_number(c, n, "threading.haas_chamfer", 0, 99, m.haas_chamfer);
    };
    return k;
  }();
  return kKeys;
}

// Keys whose value is a map of free names.
const std::vector<std::string>& map_keys() {
  static const std::vector<std::string> kMaps = {"formats", "codes", "templates"};
  return kMaps;
}

std::vector<std::string> valid_children(const std::string& prefix) {
  std::set<std::string> out;
  for (const auto& [path, setter] : scalar_keys()) {
    if (path.compare(0, prefix.size(), prefix) != 0) continue;
    std::string rest = path.substr(prefix.size());
    out.insert(rest.substr(0, rest.find('.')));
  }
  if (prefix == "block_numbers.") out.insert("skip");
  if (prefix.empty()) {
    for (const std::string& m : map_keys()) out.insert(m);
    out.insert("extends");
  }
  return {out.begin(), out.end()};
}

// Whether keys start with `prefix` ("limits."): `prefix` names a section, not a scalar. The
// same as !valid_children(prefix).empty() for a non-empty prefix, without building the list.
bool has_children(const std::string& prefix) {
  auto it = scalar_keys().lower_bound(prefix);
  return it != scalar_keys().end() && it->first.starts_with(prefix);
}

bool apply_map(Ctx& c, const YAML::Node& node, const std::string& prefix, Machine& m);

bool apply_key(Ctx& c, const YAML::Node& key, const YAML::Node& value, const std::string& prefix,
               Machine& m) {
  const std::string name = key.Scalar();
  const std::string path = prefix + name;
  if (prefix.empty() && name == "extends") {
    if (c.is_post) {
      c.error(key, "a post cannot 'extends' another post");
      return false;
    }
    return get_string(c, value, "extends", m.post);
  }
  if (prefix.empty() && name == "formats") {
    if (!value.IsMap())
      return c.error(value, "'formats' must be a map of address: {decimals: ...}"), false;
    bool ok = true;
    for (const auto& kv : value)
      ok &= apply_format(c, kv.second, kv.first.Scalar(), m.formats[kv.first.Scalar()]);
    return ok;
  }
  if (path == "block_numbers.skip") {
    if (!value.IsSequence())
      return c.error(value, "'block_numbers.skip' must be a list of block prefixes"), false;
    m.block_skip.clear();
    bool ok = true;
    for (const auto& item : value) ok &= get_string(c, item, path, m.block_skip.emplace_back());
    return ok;
  }
  if (prefix.empty() && name == "codes") {
    if (!value.IsMap()) return c.error(value, "'codes' must be a map of name: code"), false;
    bool ok = true;
    for (const auto& kv : value)
      ok &= get_string(c, kv.second, "codes." + kv.first.Scalar(), m.codes[kv.first.Scalar()]);
    return ok;
  }
  if (prefix.empty() && name == "templates") {
    if (!value.IsMap()) return c.error(value, "'templates' must be a map of name: [lines]"), false;
    bool ok = true;
    std::vector<std::string> names;
    for (const auto& [n, f] : template_fields()) names.push_back(n);
    for (const auto& kv : value) {
      const std::string tname = kv.first.Scalar();
      if (!template_fields().count(tname)) {
        c.error(kv.first,
                fmt::format("unknown template 'templates.{}'{}", tname, suggestion(tname, names)));
        ok = false;
        continue;
      }
      std::vector<std::string> lines;
      if (kv.second.IsScalar()) {
        lines.push_back(kv.second.Scalar());
      } else if (kv.second.IsSequence()) {
        for (const auto& line : kv.second) {
          if (!line.IsScalar()) {
            c.error(line, fmt::format("'templates.{}' lines must be strings", tname));
            ok = false;
            continue;
          }
          lines.push_back(line.Scalar());
        }
      } else if (!kv.second.IsNull()) {
        c.error(kv.second, fmt::format("'templates.{}' must be a line or a list of lines", tname));
        ok = false;
        continue;
      }
      for (size_t i = 0; i < lines.size(); ++i)
        ok &= check_template(c, kv.second.IsSequence() ? kv.second[i] : kv.second, tname, lines[i]);
      m.templates[tname] = std::move(lines);
    }
    return ok;
  }
  auto it = scalar_keys().find(path);
  if (it != scalar_keys().end()) return it->second(c, value, m);
  if (has_children(path + ".")) {
    if (!value.IsMap()) return c.error(value, fmt::format("'{}' must be a map", path)), false;
    return apply_map(c, value, path + ".", m);
  }
  c.error(key, fmt::format("unknown key '{}'{}", path, suggestion(name, valid_children(prefix))));
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

}  // namespace

bool apply_machine_yaml(std::string_view file, std::string_view text, bool is_post, Machine& m,
                        std::string& errors) {
  Ctx c{Diagnostics(std::string(file)), YamlText(text), is_post};
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
  bool ok = apply_map(c, root, "", m);
  errors += c.diags.render_all();
  return ok && !c.diags.has_errors();
}

namespace {

// What every machine must define, through its post or itself: without these the program would
// silently lack its motion codes or its start and end.
const std::vector<std::string>& required_codes() {
  static const std::vector<std::string> k = {"rapid",   "linear",     "arc_cw",
                                             "arc_ccw", "thread",     "metric",
                                             "inch",    "spindle_cw", "spindle_ccw"};
  return k;
}
const std::vector<std::string>& required_templates() {
  static const std::vector<std::string> k = {"program_start", "program_end", "tool_change",
                                             "spindle_rpm", "spindle_stop"};
  return k;
}

bool check_required(const std::string& path, const std::string& text, const Machine& m,
                    std::string& errors) {
  std::vector<std::string> missing;
  for (const std::string& c : required_codes())
    if (m.code(c).empty()) missing.push_back("codes." + c);
  for (const std::string& t : required_templates())
    if (!m.templates.count(t)) missing.push_back("templates." + t);
  if (missing.empty()) return true;
  YamlText t(text);
  uint32_t line = m.post.empty() ? 1 : t.find_key_line("extends");
  Diagnostics d(path);
  std::string list;
  for (const std::string& k : missing) list += (list.empty() ? "'" : ", '") + k + "'";
  d.error(SourceLoc{line, 1}, t.line(line),
          m.post.empty()
              ? fmt::format("missing required {} {} (a machine file normally 'extends' a post "
                            "from posts/ that defines them)",
                            missing.size() == 1 ? "key" : "keys", list)
              : fmt::format("missing required {} {}: empty or absent in this machine and its "
                            "post '{}'",
                            missing.size() == 1 ? "key" : "keys", list, m.post));
  errors += d.render_all();
  return false;
}

}  // namespace

bool load_machine(std::string_view name_or_path, const std::vector<std::string>& data_dirs,
                  const std::vector<std::string>& overrides, Machine& out, std::string& errors) {
  std::string path;
  if (looks_like_path(name_or_path)) {
    path = std::string(name_or_path);
  } else {
    for (const std::string& dir : data_dirs) {
      std::string p = dir + "/machines/" + std::string(name_or_path) + ".yaml";
      if (fs::exists(p)) {
        path = p;
        break;
      }
    }
    if (path.empty()) {
      std::vector<std::string> names;
      for (const MachineInfo& mi : list_machines(data_dirs)) names.push_back(mi.name);
      std::string list;
      for (const std::string& n : names) list += (list.empty() ? "" : ", ") + n;
      errors +=
          fmt::format("clpost: error: unknown machine '{}'{}; shipped machines: {}\n", name_or_path,
                      suggestion(name_or_path, names), list.empty() ? "none found" : list);
      return false;
    }
  }
  std::string machine_text;
  if (!read_file(path, machine_text)) {
    errors += fmt::format("{}: error: cannot read machine file\n", path);
    return false;
  }
  // The machine file names its post; read that first so the machine's keys override it.
  Machine probe;
  std::string probe_errors;
  if (!apply_machine_yaml(path, machine_text, false, probe, probe_errors)) {
    errors += probe_errors;
    return false;
  }
  Machine m;
  m.name = fs::path(path).stem().string();
  m.source = path;
  if (!probe.post.empty()) {
    // Posts live in posts/ beside the machines/ folder of the machine file, or in a data dir.
    std::vector<std::string> candidates = {
        (fs::path(path).parent_path() / ".." / "posts" / (probe.post + ".yaml"))
            .lexically_normal()
            .string(),
        (fs::path(path).parent_path() / (probe.post + ".yaml")).string()};
    for (const std::string& dir : data_dirs)
      candidates.push_back(dir + "/posts/" + probe.post + ".yaml");
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
                          probe.post));
      errors += d.render_all();
      return false;
    }
    std::string post_text;
    if (!read_file(post_path, post_text)) {
      errors += fmt::format("{}: error: cannot read post file\n", post_path);
      return false;
    }
    if (!apply_machine_yaml(post_path, post_text, true, m, errors)) return false;
  }
  if (!apply_machine_yaml(path, machine_text, false, m, errors)) return false;
  for (const std::string& ov : overrides) {
    size_t eq = ov.find('=');
    if (eq == std::string::npos || eq == 0) {
      errors += fmt::format("--set: error: expected key.path=value, got '{}'\n", ov);
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
    if (!apply_machine_yaml("--set " + ov, doc, false, m, set_errors)) {
      // The YAML document was made here, so its line, column and text mean nothing to the user:
      // keep only `--set key=value: error: message`.
      std::string prefix = "--set " + ov + ":1:";
      size_t start = 0;
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
  }
  if (!check_required(path, machine_text, m, errors)) return false;
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

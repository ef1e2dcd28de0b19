#pragma once
// The machine loader's typed getters: a YAML node of a post or machine file read as the type its
// key declares (machine_schema.h: a string, a bool, a number in a range, a whole number, one of
// the choices, a list, a number or `auto`), each problem a diagnostic at the node
// ("'limits.max_rpm' must be a number, not 'fast'"). The document being read (YamlDoc) carries the
// diagnostics.
#include <fmt/format.h>
#include <yaml-cpp/yaml.h>

#include <string>
#include <string_view>
#include <vector>

#include "machine/machine_loader.h"
#include "machine/machine_schema.h"
#include "machine/yaml_text.h"
#include "support/diagnostics.h"

namespace clpost {

// The loader's view of one YAML document (a post, a machine file, a --set): diagnostics with the
// document's own line text, and the schema of the machine's controls.
struct YamlDoc {
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

// Node `n` as text (the value of key `key`).
bool get_string(YamlDoc& c, const YAML::Node& n, std::string_view key, std::string& out);

// Sets key `k` of machine `m` from `n`: the member it names, or its control's slot, by type.
bool set_key(YamlDoc& c, const YAML::Node& n, const KeySpec& k, Machine& m);
// Sets format key `k` (its dotted path `path`) of format `f` from `n`.
bool set_format_key(YamlDoc& c, const YAML::Node& n, std::string_view path, const FormatKeySpec& k,
                    NumberFormat& f);

}  // namespace clpost

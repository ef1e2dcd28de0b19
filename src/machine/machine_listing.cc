#include "machine/machine_listing.h"

#include <charconv>

#include "machine/machine_schema.h"
#include "support/json_text.h"

namespace clpost {
namespace {

bool reads_as_other_type(const std::string& s) {
  for (const char* word : {"true", "false", "yes", "no", "on", "off", "null", "~"})
    if (s == word) return true;
  double v = 0;
  auto [p, ec] = std::from_chars(s.data(), s.data() + s.size(), v);
  return ec == std::errc() && p == s.data() + s.size();
}

}  // namespace

std::string yaml_scalar(const std::string& s) {
  const bool plain = !s.empty() && s.front() != ' ' && s.back() != ' ' &&
                     s.find_first_of(":#{}[],&*!|>'\"%@`\\") == std::string::npos &&
                     s.front() != '-' && s.front() != '?' && !reads_as_other_type(s);
  return plain ? s : json_string(s);
}

std::vector<MachineValue> machine_values(const Machine& m) {
  std::vector<MachineValue> out;
  const Schema s = schema(m.controls);
  for (const KeySpec& k : s.keys) {
    std::string v = key_value_text(k, m);
    if (k.type == KeyType::kString) v = yaml_scalar(v);
    out.push_back({std::string(k.path), std::move(v)});
  }
  for (const auto& [name, f] : m.formats)
    for (const FormatKeySpec& k : format_keys())
      out.push_back({"formats." + name + "." + std::string(k.name), format_key_value_text(k, f)});
  for (const auto& [name, code] : m.codes) out.push_back({"codes." + name, yaml_scalar(code)});
  for (const auto& [name, lines] : m.templates)
    out.push_back({"templates." + name, text_list(lines)});
  return out;
}

}  // namespace clpost

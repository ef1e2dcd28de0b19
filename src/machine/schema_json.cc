#include "machine/schema_json.h"

#include <fmt/format.h>

#include <algorithm>
#include <utility>
#include <vector>

#include "machine/machine_schema.h"
#include "support/json_text.h"

namespace clpost {
namespace {

using Members = std::vector<std::pair<std::string, std::string>>;  // name, rendered JSON value

// An object at `indent`, one member a line; the values are rendered already.
std::string object(size_t indent, const Members& members) {
  std::string out = "{\n";
  for (size_t i = 0; i < members.size(); ++i)
    out += fmt::format("{:{}}{}: {}{}\n", "", indent + 2, json_string(members[i].first),
                       members[i].second, i + 1 < members.size() ? "," : "");
  return out + fmt::format("{:{}}}}", "", indent);
}

std::string str(std::string_view s) {
  return json_string(s);
}
std::string num(double v) {
  return fmt::format("{}", v);
}

constexpr const char* kScalar = R"(["string", "number", "boolean"])";
constexpr const char* kBool = R"([true, false, "yes", "no", "on", "off"])";

// The schema of key `k` (`indent`: where its object starts).
std::string key_schema(const KeySpec& k, size_t indent) {
  const Machine defaults;
  const std::string def = key_value_text(k, defaults);
  Members m = {{"description", str(k.doc)}};
  switch (k.type) {
    case KeyType::kString:
      m.push_back({"type", kScalar});
      m.push_back({"default", str(def)});
      break;
    case KeyType::kBool:
      m.push_back({"enum", kBool});
      m.push_back({"default", def});
      break;
    case KeyType::kNumber:
    case KeyType::kInt:
      m.push_back({"type", str(k.type == KeyType::kInt ? "integer" : "number")});
      m.push_back({"minimum", num(k.lo)});
      m.push_back({"maximum", num(k.hi)});
      m.push_back({"default", def});
      break;
    case KeyType::kNumberOrAuto:
      m.push_back({"anyOf", fmt::format(R"([{{"type": "number", "minimum": {}, "maximum": {}}}, )"
                                        R"({{"const": "auto"}}])",
                                        num(k.lo), num(k.hi))});
      m.push_back({"default", def});
      break;
    case KeyType::kChoice: {
      std::string e;
      for (const Choice& c : k.choices) e += (e.empty() ? "" : ", ") + str(c.name);
      m.push_back({"enum", "[" + e + "]"});
      m.push_back({"default", str(def)});
      break;
    }
    case KeyType::kList:
      m.push_back({"type", str("array")});
      m.push_back({"items", fmt::format(R"({{"type": {}}})", kScalar)});
      m.push_back({"default", def});
      break;
  }
  return object(indent, m);
}

// The keys under `prefix` ("" or "threading."), as properties, nested sections as objects.
Members key_properties(const Schema& s, size_t indent) {
  Members props;
  std::vector<std::string> sections;
  for (const KeySpec& k : s.keys) {
    const size_t dot = k.path.find('.');
    if (dot == std::string_view::npos) {
      props.push_back({std::string(k.path), key_schema(k, indent)});
      continue;
    }
    const std::string section(k.path.substr(0, dot));
    if (std::find(sections.begin(), sections.end(), section) != sections.end()) continue;
    sections.push_back(section);
    Members inner;
    for (const KeySpec& in : s.keys)
      if (in.path.starts_with(section + "."))
        inner.push_back({std::string(in.path.substr(dot + 1)), key_schema(in, indent + 4)});
    props.push_back({section, object(indent, {{"type", str("object")},
                                              {"additionalProperties", "false"},
                                              {"properties", object(indent + 2, inner)}})});
  }
  return props;
}

std::string formats_schema(const Schema& s, size_t indent) {
  Members props;
  for (const NameSpec& f : s.formats)
    props.push_back(
        {std::string(f.name), object(indent + 4, {{"$ref", str("#/$defs/number_format")},
                                                  {"description", str(f.doc)}})});
  return object(
      indent,
      {{"type", str("object")},
       {"description", str("Number formats by address or named format; an address a key of the "
                           "machine names (threading.*_address) may have one too")},
       {"properties", object(indent + 2, props)},
       {"patternProperties",
        object(indent + 2, {{"^[A-Z]{1,3}=?$", R"({"$ref": "#/$defs/number_format"})"}})},
       {"additionalProperties", "false"}});
}

std::string number_format_schema(size_t indent) {
  const NumberFormat defaults;
  Members props;
  for (const FormatKeySpec& k : format_keys()) {
    Members m = {{"description", str(k.doc)}};
    if (k.type == KeyType::kBool) {
      m.push_back({"enum", kBool});
    } else {
      m.push_back({"type", str(k.type == KeyType::kInt ? "integer" : "number")});
      m.push_back({"minimum", num(k.lo)});
      m.push_back({"maximum", num(k.hi)});
    }
    if (k.default_text.empty()) m.push_back({"default", format_key_value_text(k, defaults)});
    props.push_back({std::string(k.name), object(indent + 4, m)});
  }
  return object(indent, {{"type", str("object")},
                         {"additionalProperties", "false"},
                         {"properties", object(indent + 2, props)}});
}

std::string codes_schema(const Schema& s, size_t indent) {
  Members props;
  for (const NameSpec& c : s.codes)
    props.push_back({std::string(c.name),
                     fmt::format(R"({{"type": {}, "description": {}}})", kScalar,
                                 str(std::string(c.doc) + (c.required ? " (required)" : "")))});
  return object(indent, {{"type", str("object")},
                         {"additionalProperties", "false"},
                         {"properties", object(indent + 2, props)}});
}

// A template line may use only the template's fields: {name}, {name:spec}, {{ and }}.
std::string line_pattern(const TemplateSpec& t) {
  std::string names;
  for (const TemplateField& f : t.fields) names += (names.empty() ? "" : "|") + std::string(f.name);
  const std::string field = names.empty() ? "" : "|\\{(?:" + names + ")(?:[:!][^{}]*)?\\}";
  return "^(?:[^{}]|\\{\\{|\\}\\}" + field + ")*$";
}

std::string templates_schema(const Schema& s, size_t indent) {
  Members props;
  for (const TemplateSpec* t : s.templates) {
    const std::string line =
        fmt::format(R"({{"type": "string", "pattern": {}}})", str(line_pattern(*t)));
    std::string fields;
    for (const TemplateField& f : t->fields)
      fields += (fields.empty() ? "" : ", ") + std::string(f.name);
    props.push_back(
        {std::string(t->name),
         object(
             indent + 4,
             {{"description",
               str(fmt::format("{}; fields: {}", t->doc, fields.empty() ? "none" : fields))},
              {"anyOf", fmt::format(R"([{{"type": "null"}}, {}, {{"type": "array", "items": {}}}])",
                                    line, line)}})});
  }
  return object(indent, {{"type", str("object")},
                         {"additionalProperties", "false"},
                         {"properties", object(indent + 2, props)}});
}

}  // namespace

std::string schema_json(const Schema& s) {
  Members props = key_properties(s, 4);
  props.push_back({"formats", formats_schema(s, 4)});
  props.push_back({"codes", codes_schema(s, 4)});
  props.push_back({"templates", templates_schema(s, 4)});
  return object(
             0,
             {{"$schema", str("https://json-schema.org/draft/2020-12/schema")},
              {"title", str("clpost machine or post file")},
              {"description",
               str("A clpost post (posts/*.yaml) or machine (machines/*.yaml) file; 'extends' is "
                   "for machine files only. Generated by `clpost schema` from the loader's "
                   "declared schema (docs/machines.md).")},
              {"type", str("object")},
              {"additionalProperties", "false"},
              {"properties", object(2, props)},
              {"$defs", object(2, {{"number_format", number_format_schema(4)}})}}) +
         "\n";
}

}  // namespace clpost

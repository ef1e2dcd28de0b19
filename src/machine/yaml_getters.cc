#include "machine/yaml_getters.h"

#include <charconv>
#include <cmath>
#include <type_traits>

#include "machine/control.h"
#include "support/suggest.h"

namespace clpost {
namespace {

// What node `n` holds, for "must be …, not X": 'fast', an empty value, nothing, a map, a list.
std::string shown_value(const YAML::Node& n) {
  if (!n.IsDefined() || n.IsNull()) return "nothing";
  if (n.IsScalar()) return n.Scalar().empty() ? "an empty value" : "'" + n.Scalar() + "'";
  return n.IsMap() ? "a map" : "a list";
}

}  // namespace

bool get_string(YamlDoc& c, const YAML::Node& n, std::string_view key, std::string& out) {
  if (!n.IsScalar()) {
    c.error(n, fmt::format("'{}' must be a string", key));
    return false;
  }
  out = n.Scalar();
  return true;
}

namespace {

// The index of the choice `n` names, or -1 after an error.
int get_choice(YamlDoc& c, const YAML::Node& n, std::string_view key,
               std::span<const Choice> choices) {
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

bool get_bool(YamlDoc& c, const YAML::Node& n, std::string_view key, bool& out) {
  if (n.IsScalar()) {
    const std::string& s = n.Scalar();
    if (s == "true" || s == "yes" || s == "on") return out = true, true;
    if (s == "false" || s == "no" || s == "off") return out = false, true;
  }
  c.error(n, fmt::format("'{}' must be true or false, not {}", key, shown_value(n)));
  return false;
}

bool get_number(YamlDoc& c, const YAML::Node& n, std::string_view key, double lo, double hi,
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
bool get_number_or_auto(YamlDoc& c, const YAML::Node& n, std::string_view key, double lo, double hi,
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

bool get_int(YamlDoc& c, const YAML::Node& n, std::string_view key, double lo, double hi,
             int& out) {
  double v = 0;
  if (!get_number(c, n, key, lo, hi, v)) return false;
  if (v != std::floor(v)) {
    c.error(n, fmt::format("'{}' must be a whole number, not {}", key, shown_value(n)));
    return false;
  }
  out = static_cast<int>(v);
  return true;
}

bool get_list(YamlDoc& c, const YAML::Node& n, std::string_view key,
              std::vector<std::string>& out) {
  if (!n.IsSequence()) return c.error(n, fmt::format("'{}' must be a list", key)), false;
  out.clear();
  bool ok = true;
  for (const auto& item : n) ok &= get_string(c, item, key, out.emplace_back());
  return ok;
}

// Sets key `k` of `obj` (a Machine or a NumberFormat) from `n`: the member it names, by type.
template <typename Obj, typename Member>
bool set_member(YamlDoc& c, const YAML::Node& n, std::string_view path, KeyType type, double lo,
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

}  // namespace

bool set_key(YamlDoc& c, const YAML::Node& n, const KeySpec& k, Machine& m) {
  return std::visit(
      [&](auto member) {
        if constexpr (std::is_same_v<decltype(member), ControlSlot>)
          return get_number(c, n, k.path, k.lo, k.hi, m.control_values[member.index]);
        else
          return set_member(c, n, k.path, k.type, k.lo, k.hi, k.choices, m, member);
      },
      k.member);
}

bool set_format_key(YamlDoc& c, const YAML::Node& n, std::string_view path, const FormatKeySpec& k,
                    NumberFormat& f) {
  return std::visit(
      [&](auto member) { return set_member(c, n, path, k.type, k.lo, k.hi, {}, f, member); },
      k.member);
}

}  // namespace clpost

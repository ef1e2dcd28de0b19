#include "machine/template_values.h"

#include <fmt/args.h>
#include <fmt/format.h>

#include <algorithm>

#include "support/suggest.h"
#include "support/text.h"

namespace clpost {

void TemplateValues::set_stand_ins() {
  for (size_t i = 0; i < values_.size(); ++i) {
    // Whole numbers are numbers (so "{tool:02}" works); the rest formatted text.
    if (spec_->fields[i].kind == FieldKind::kWhole)
      values_[i] = 0LL;
    else
      values_[i] = std::string("0");
  }
}

namespace {

// Fields written one after another with nothing between ("T{tool:02}{offset:02}") are told apart
// by their widths alone: a whole number after the first wider than its width makes the word read
// as other numbers (tool 7 offset 700 as T07700: tool 77, offset 0). What is wrong, or "".
std::string adjacent_overflow(std::string_view line, const TemplateSpec& spec,
                              const std::vector<TemplateValues::Value>& values) {
  for (const FieldUse& u : field_uses(line)) {
    if (u.offset == 0 || line[u.offset - 1] != '}') continue;
    const size_t close = line.find('}', u.offset);
    const std::string_view inner = line.substr(u.offset + 1, close - u.offset - 1);
    const size_t colon = inner.find(':');
    const std::string format =
        fmt::format("{{{}}}", colon == std::string_view::npos ? "" : inner.substr(colon));
    for (size_t i = 0; i < values.size(); ++i) {
      const long long* n = std::get_if<long long>(&values[i]);
      if (spec.fields[i].name != u.name || n == nullptr) continue;
      const size_t width = fmt::vformat(format, fmt::make_format_args(0LL)).size();
      const std::string text = fmt::vformat(format, fmt::make_format_args(*n));
      if (text.size() > width)
        return fmt::format(
            "{{{}}} {} is {} digits where '{}' gives it {}: the word would read as other "
            "numbers",
            u.name, *n, text.size(), line, width);
    }
  }
  return {};
}

}  // namespace

TemplateValues::Line TemplateValues::format(std::string_view line) const {
  Line out;
  for (const FieldUse& u : field_uses(line)) {
    for (size_t i = 0; i < values_.size(); ++i)
      if (spec_->fields[i].name == u.name && std::holds_alternative<std::monostate>(values_[i])) {
        out.missing = spec_->fields[i].name;
        return out;
      }
  }
  fmt::dynamic_format_arg_store<fmt::format_context> args;
  for (size_t i = 0; i < values_.size(); ++i) {
    const char* name = spec_->fields[i].name.data();  // string literals: NUL-terminated
    if (const long long* n = std::get_if<long long>(&values_[i]))
      args.push_back(fmt::arg(name, *n));
    else if (const std::string* s = std::get_if<std::string>(&values_[i]))
      args.push_back(fmt::arg(name, *s));
  }
  try {
    out.text = fmt::vformat(line, args);
    out.error = adjacent_overflow(line, *spec_, values_);
    out.ok = out.error.empty();
  } catch (const fmt::format_error& e) {
    out.error = e.what();
  }
  return out;
}

bool template_has_field(const Machine& m, const TemplateSpec& spec, std::string_view field) {
  auto it = m.templates.find(std::string(spec.name));
  if (it == m.templates.end()) return false;
  for (const std::string& line : it->second)
    for (const FieldUse& u : field_uses(line))
      if (u.name == field) return true;
  return false;
}

std::vector<FieldUse> field_uses(std::string_view line) {
  std::vector<FieldUse> out;
  for (size_t i = 0; i < line.size(); ++i) {
    if (line[i] != '{') continue;
    if (i + 1 < line.size() && line[i + 1] == '{') {
      ++i;
      continue;
    }
    size_t end = i + 1;
    while (end < line.size() && line[end] != '}' && line[end] != ':' && line[end] != '!' &&
           line[end] != '{')
      ++end;
    out.push_back({line.substr(i + 1, end - i - 1), i});
    const size_t close = line.find('}', i);
    if (close == std::string_view::npos) break;
    i = close;
  }
  return out;
}

namespace {

// fmt writes as many characters as a field's width or precision says: `{tool:>1000000000}`
// would make a 1 GB line at load time and again for every block. Widths and precisions are kept
// to two digits, and never taken from a field (`{tool:{offset}}`). Returns what is wrong, or "".
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
      if (!is_digit(spec[k])) {
        ++k;
        continue;
      }
      unsigned value = 0;
      size_t j = k;
      for (; j < spec.size() && is_digit(spec[j]); ++j)
        value = std::min(value * 10 + static_cast<unsigned>(spec[j] - '0'), kMaxWidth + 1);
      if (value > kMaxWidth)
        return fmt::format("width or precision {} is too large (at most {})", spec.substr(k, j - k),
                           kMaxWidth);
      k = j;
    }
  }
  return {};
}

std::string field_list(const TemplateSpec& spec) {
  std::string fields;
  for (const TemplateField& f : spec.fields)
    fields += fmt::format("{}{{{}}}", fields.empty() ? "" : ", ", f.name);
  return fields.empty() ? "none" : fields;
}

}  // namespace

std::string check_template_line(const TemplateSpec& spec, std::string_view line, size_t& offset) {
  offset = 0;
  if (std::string problem = oversized_field(line); !problem.empty()) return problem;
  std::vector<std::string_view> names;
  for (const TemplateField& f : spec.fields) names.push_back(f.name);
  for (const FieldUse& u : field_uses(line)) {
    const bool named = !u.name.empty() && !is_digit(u.name[0]);
    if (!named || std::find(names.begin(), names.end(), u.name) != names.end()) continue;
    offset = u.offset;
    return fmt::format("unknown field '{{{}}}'{} (fields: {})", u.name, did_you_mean(u.name, names),
                       field_list(spec));
  }
  TemplateValues v(spec);
  v.set_stand_ins();
  TemplateValues::Line l = v.format(line);
  if (!l.ok) return fmt::format("{} (fields: {})", l.error, field_list(spec));
  return {};
}

}  // namespace clpost

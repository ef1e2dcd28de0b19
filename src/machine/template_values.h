#pragma once
// The values of one template's fields, set by declared field (machine_schema.h), and the
// formatting of a template line with them. The loader formats every line with stand-in values
// when it loads (so a line fmt cannot format is caught there); NcProgram with the real ones.
//
//   TemplateFill<tmpl::kProgramStart> a;
//   a.text<"program_name">(name);  // a name program_start does not declare does not compile
#include <cstddef>
#include <string>
#include <string_view>
#include <variant>
#include <vector>

#include "machine/machine_schema.h"

namespace clpost {

class TemplateValues {
 public:
  using Value = std::variant<std::monostate, long long, std::string>;
  explicit TemplateValues(const TemplateSpec& t) : spec_(&t), values_(t.fields.size()) {}
  const TemplateSpec& spec() const { return *spec_; }

  void set_text(size_t field, std::string v) { values_.at(field) = std::move(v); }
  void set_whole(size_t field, long long v) { values_.at(field) = v; }
  // A stand-in for every field (0, "0"), as the loader checks a line.
  void set_stand_ins();

  // How one line came out: `text` when `ok`; else `missing` names the first field the line
  // uses that has no value (a value the caller could not know, as a dwell's), or `error` says
  // what fmt found wrong.
  struct Line {
    bool ok = false;
    std::string text;
    std::string_view missing;
    std::string error;
  };
  Line format(std::string_view line) const;

 private:
  const TemplateSpec* spec_;
  std::vector<Value> values_;
};

// A field name as a template argument: text<"lead">(…).
template <size_t N>
struct FieldName {
  char s[N]{};
  consteval FieldName(const char (&a)[N]) {  // NOLINT: implicit on purpose
    for (size_t i = 0; i < N; ++i) s[i] = a[i];
  }
  constexpr std::string_view view() const { return {s, N - 1}; }
};

// TemplateValues for template `T`, whose fields are named at compile time.
template <const TemplateSpec& T>
class TemplateFill : public TemplateValues {
 public:
  TemplateFill() : TemplateValues(T) {}
  template <FieldName F>
  TemplateFill& text(std::string v) {
    constexpr size_t i = T.field(F.view(), FieldKind::kText);
    set_text(i, std::move(v));
    return *this;
  }
  template <FieldName F>
  TemplateFill& whole(long long v) {
    constexpr size_t i = T.field(F.view(), FieldKind::kWhole);
    set_whole(i, v);
    return *this;
  }
};

// The names of the fields line `line` uses, with their offsets in it ("{{" is a brace, not a
// field). A field with no name ("{}", "{0}") has an empty or numeric name.
struct FieldUse {
  std::string_view name;
  size_t offset;  // of the '{'
};
std::vector<FieldUse> field_uses(std::string_view line);
// Whether machine `m`'s template `spec` (any of its lines) uses field `field`.
bool template_has_field(const Machine& m, const TemplateSpec& spec, std::string_view field);

// What is wrong with template line `line` of `spec`, or "" when it is fine; `offset` is where in
// the line (an unknown field: "unknown field '{speeed}' … (did you mean 'speed'?)").
std::string check_template_line(const TemplateSpec& spec, std::string_view line, size_t& offset);

}  // namespace clpost

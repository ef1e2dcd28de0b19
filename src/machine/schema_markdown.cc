#include "machine/schema_markdown.h"

#include <fmt/format.h>

#include "machine/machine_schema.h"

namespace clpost {
namespace {

struct Section {
  std::string_view name;     // KeySpec::section
  std::string_view heading;  // as the docs title it
  std::string_view intro;
};

constexpr Section kSections[] = {
    {"Identity", "Identity", ""},
    {"CL frame", "CL frame (`cl.*`)",
     "CAM systems that write the turning plane as XY set `cl: {radial_axis: y, axial_axis: x}`."},
    {"Output", "Output (`output.*`, `comments.*`, `block_numbers.*`)", ""},
    {"Limits", "Limits (`limits.*`)", ""},
    {"Threading", "Threading (`threading.*`)", ""},
    {"Control facts", "Control facts (`threading.*`)",
     "Facts of the control that a cycle's words do not carry (they live in the control's "
     "parameters or settings, so the machine file states them)."},
    {"Cycle time", "Cycle time (`time.*`)",
     "What the estimated cycle time (`clpost check`, the batch `--report`) needs beyond the CL: "
     "how fast the machine rapids and changes tools."},
    {"Holes", "Holes on the spindle axis (`holes.*`)",
     "`CYCLE/DRILL|DEEP|BRKCHP|TAP|BORE|REAM` with the hole's GOTO on the centre line: written "
     "with the `hole_*` templates when the machine has them and the cycle says what the CL says, "
     "else as G0/G1/G4 moves with the reason in a comment."},
    {"Mill-turn", "Mill-turn (`millturn.*`)",
     "Live tools, the C axis and the Y axis (docs/millturn.md): what the machine has, and how "
     "its control drills with a live tool."},
};

std::string range(double lo, double hi) {
  return fmt::format("{}…{}", lo, hi);
}

std::string type_text(const KeySpec& k) {
  switch (k.type) {
    case KeyType::kString:
      return "text";
    case KeyType::kBool:
      return "bool";
    case KeyType::kNumber:
      return "number " + range(k.lo, k.hi);
    case KeyType::kNumberOrAuto:
      return "number " + range(k.lo, k.hi) + " \\| `auto`";
    case KeyType::kInt:
      return "whole number " + range(k.lo, k.hi);
    case KeyType::kList:
      return "list of text";
    case KeyType::kChoice: {
      std::string s;
      for (const Choice& c : k.choices)
        s += fmt::format("{}`{}`", s.empty() ? "" : " \\| ", c.name);
      return s;
    }
  }
  return {};
}

std::string cell(std::string_view value) {
  return value.empty() ? std::string("—") : fmt::format("`{}`", value);
}

std::string keys_tables(const Schema& schema) {
  const Machine defaults;
  std::string out;
  for (const Section& s : kSections) {
    out += fmt::format("### {}\n\n", s.heading);
    if (!s.intro.empty()) out += fmt::format("{}\n\n", s.intro);
    out += "| key | type | default | meaning |\n|---|---|---|---|\n";
    for (const KeySpec& k : schema.keys) {
      if (k.section != s.name) continue;
      out += fmt::format("| `{}` | {} | {} | {} |\n", k.path, type_text(k),
                         cell(key_value_text(k, defaults)), k.doc);
    }
    out += "\n";
  }
  return out;
}

std::string formats_tables(const Schema& s) {
  std::string out =
      "### Number formats (`formats.<name>`)\n\n"
      "A map from a format name to how its numbers are written:\n\n"
      "| key | type | default | meaning |\n|---|---|---|---|\n";
  const NumberFormat defaults;
  for (const FormatKeySpec& k : format_keys()) {
    const std::string type = k.type == KeyType::kBool  ? "bool"
                             : k.type == KeyType::kInt ? "whole number " + range(k.lo, k.hi)
                                                       : "number " + range(k.lo, k.hi);
    out += fmt::format("| `{}` | {} | {} | {} |\n", k.name, type,
                       cell(k.default_text.empty() ? format_key_value_text(k, defaults)
                                                   : std::string(k.default_text)),
                       k.doc);
  }
  out +=
      "\nThe format names: an address the machine writes, or a named format. An address that a "
      "key of the machine names (`threading.lead_address`, `lead_address_x`, `tpi_address`, "
      "`start_angle_address`) may have a format too; any other name is an error.\n\n"
      "| format | used for |\n|---|---|\n";
  for (const NameSpec& f : s.formats) out += fmt::format("| `{}` | {} |\n", f.name, f.doc);
  return out + "\n";
}

std::string codes_table(const Schema& s) {
  std::string out =
      "### Codes (`codes.<name>`)\n\n"
      "G and M codes by role; any other name is an error.\n\n"
      "| code | required | used for |\n|---|---|---|\n";
  for (const NameSpec& c : s.codes)
    out += fmt::format("| `{}` | {} | {} |\n", c.name, c.required ? "yes" : "", c.doc);
  return out + "\n";
}

std::string need_text(const TemplateSpec& t) {
  switch (t.need) {
    case Need::kAlways:
      return "always";
    case Need::kSetting:
      return fmt::format("when `{}: {}`", t.setting, t.choice);
    case Need::kClWord:
      return fmt::format("when the CL has {} (else an error at that line)", t.cl_words);
    case Need::kOptional:
      return fmt::format("no: {} uses it when present", t.cl_words);
  }
  return {};
}

std::string templates_tables(const Schema& s) {
  std::string out =
      "### Templates (`templates.<name>`)\n\n"
      "A block layout as a list of lines (each one NC block) with named `{fields}` in "
      "[fmt syntax](https://fmt.dev/latest/syntax.html). A template may use only its own fields "
      "(whole-number fields take integer specs such as `{tool:02}`; the others are text, already "
      "formatted with the format named); any other name is an error when the machine loads. "
      "An empty list (`dwell: []`) is the integrator's choice: that template writes nothing. "
      "A template the program needs but the machine lacks is an error: at load time when it is "
      "always required or selected by a setting, else at the CL line that needs it. Fields "
      "written one after another (`T{tool:02}{offset:02}`) are told apart by their widths alone, "
      "as `clpost verify` reads them back: a number after the first wider than its width (offset "
      "700 in two digits) is an error at the CL line, never a word that reads as other "
      "numbers.\n\n"
      "| template | required | used for |\n|---|---|---|\n";
  for (const TemplateSpec* t : s.templates)
    out += fmt::format("| `{}` | {} | {} |\n", t->name, need_text(*t), t->doc);
  out += "\nThe fields of each template:\n\n";
  for (const TemplateSpec* t : s.templates) {
    std::string fields;
    for (const TemplateField& f : t->fields)
      fields += fmt::format("{}`{{{}}}` {}{}", fields.empty() ? "" : "; ", f.name,
                            f.kind == FieldKind::kWhole ? "(whole number) " : "", f.doc);
    out += fmt::format("- `{}`: {}\n", t->name, fields.empty() ? "no fields" : fields);
  }
  return out;
}

}  // namespace

std::string schema_markdown(const Schema& s) {
  return fmt::format("{}\n\n{}{}{}{}\n{}\n", kSchemaDocBegin, keys_tables(s), formats_tables(s),
                     codes_table(s), templates_tables(s), kSchemaDocEnd);
}

}  // namespace clpost

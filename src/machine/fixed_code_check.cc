#include "machine/fixed_code_check.h"

#include <fmt/format.h>

#include <cstdlib>

#include "machine/control.h"
#include "machine/yaml_text.h"
#include "support/diagnostics.h"

namespace clpost {
namespace {

// One fixed code `f`: m's code of its key must be its code.
bool check_fixed_code(const Machine& m, const FixedCode& f, const KeyOrigins& origins,
                      const YamlText& machine_text, std::string& errors) {
  if (m.code(std::string(f.key)) == f.code) return true;
  const std::string key = fmt::format("codes.{}", f.key);
  const std::string message = fmt::format(
      "{} is '{}', but on the {} control {} {}: a control's own codes are its meaning, not "
      "machine data",
      key, m.code(std::string(f.key)), m.control->name, f.code, f.meaning);
  const auto o = origins.find(key);
  const std::string where = o == origins.end() ? m.source : o->second;
  const size_t colon = where.rfind(':');
  Diagnostics d(colon == std::string::npos ? where : where.substr(0, colon));
  const uint32_t line =
      colon == std::string::npos ? 0 : static_cast<uint32_t>(std::atoi(where.c_str() + colon + 1));
  // The line is shown when it is the machine file's (a post's key names the post file and line).
  const bool own = d.file() == m.source;
  const std::string_view text = own ? machine_text.line(line) : std::string_view();
  const size_t indent = text.find_first_not_of(' ');
  const uint32_t col = line == 0 ? 0 : static_cast<uint32_t>(indent == text.npos ? 0 : indent) + 1;
  d.error(SourceLoc{line, col}, text, message);
  errors += d.render_all();
  return false;
}

}  // namespace

bool check_fixed_codes(const Machine& m, const KeyOrigins& origins, std::string_view machine_text,
                       std::string& errors) {
  if (m.control == nullptr) return true;
  const YamlText t(machine_text);
  bool ok = true;
  for (const FixedCode& f : kIsoMotionCodes) ok &= check_fixed_code(m, f, origins, t, errors);
  for (const FixedCode& f : m.control->fixed_codes)
    ok &= check_fixed_code(m, f, origins, t, errors);
  return ok;
}

}  // namespace clpost

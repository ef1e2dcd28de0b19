#include "machine/machine.h"

#include <cassert>

#include "machine/machine_schema.h"

namespace clpost {

const NumberFormat& Machine::format_for(std::string_view address) const {
  auto it = formats.find(std::string(address));
  if (it != formats.end()) return it->second;
  auto def = formats.find("default");
  if (def != formats.end()) return def->second;
  static const NumberFormat kDefault;  // immutable, so safe to share between threads
  return kDefault;
}

void use_units(Machine& copy, const Machine& loaded, bool inch) {
  for (const auto& [address, f] : loaded.formats) copy.formats[address] = f.in_units(inch);
}

const std::string& Machine::code(const std::string& key) const {
  // A name the schema does not declare is a typo in clpost (Debug and sanitizer builds stop).
  assert(declared_code(controls, key) && "code name not declared (machine_schema.cc, a Control)");
  static const std::string kEmpty;
  auto it = codes.find(key);
  return it == codes.end() ? kEmpty : it->second;
}

bool writes_program_header(const Machine& m) {
  auto h = m.templates.find(std::string(tmpl::kProgramHeader.name));
  return h != m.templates.end() && !h->second.empty();
}

}  // namespace clpost

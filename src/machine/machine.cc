#include "machine/machine.h"

namespace clpost {

const NumberFormat& Machine::format_for(std::string_view address) const {
  auto it = formats.find(std::string(address));
  if (it != formats.end()) return it->second;
  auto def = formats.find("default");
  if (def != formats.end()) return def->second;
  static const NumberFormat kDefault;  // immutable, so safe to share between threads
  return kDefault;
}

const std::string& Machine::code(const std::string& key) const {
  static const std::string kEmpty;
  auto it = codes.find(key);
  return it == codes.end() ? kEmpty : it->second;
}

}  // namespace clpost

// Where a control's keys' values are (control.h).
#include "machine/control.h"

#include <cassert>
#include <functional>

#include "machine/machine.h"
#include "machine/machine_schema.h"

namespace clpost {

uint32_t first_slot(ControlSet set, const Control* c) {
  size_t n = 0;
  for (const Control* before : set) {
    if (before == c) break;
    n += before->keys.size();
  }
  return static_cast<uint32_t>(n);
}

double control_value(const Machine& m, const KeySpec& key) {
  const ControlSlot& slot = std::get<ControlSlot>(key.member);
  if (m.control == nullptr) return slot.initial;
  const std::span<const KeySpec> own = m.control->keys;
  assert(std::less_equal<>()(own.data(), &key) && std::less<>()(&key, own.data() + own.size()) &&
         "not a key of m.control");
  const size_t at = m.own_keys_at + static_cast<size_t>(&key - own.data());
  return at < m.control_values.size() ? m.control_values[at] : slot.initial;
}

}  // namespace clpost

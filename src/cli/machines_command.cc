#include "cli/machines_command.h"

#include <fmt/format.h>

#include <algorithm>
#include <optional>

#include "controls/registry.h"
#include "machine/machine_listing.h"
#include "machine/machine_loader.h"

namespace clpost {
namespace {

constexpr int kExitUsage = 2;
constexpr size_t kOriginColumn = 48;  // where "# origin" starts when the line is shorter

}  // namespace

CommandOutput machines_show(const std::string& machine, const std::vector<std::string>& sets,
                            bool origin, const std::vector<std::string>& data_dirs) {
  CommandOutput r;
  Machine m;
  KeyOrigins origins;
  if (!load_machine(machine, data_dirs, sets, shipped_controls(), m, r.err, &origins)) {
    r.exit_code = kExitUsage;
    return r;
  }
  r.out = fmt::format("# machine {}: {}\n", m.name, m.source);
  for (const MachineValue& v : machine_values(m)) {
    std::string line = fmt::format("{}: {}", v.key, v.value);
    if (origin) {
      auto it = origins.find(v.key);
      line = fmt::format("{:<{}} # {}", line, kOriginColumn - 1,
                         it == origins.end() ? "default" : it->second);
    }
    r.out += line + "\n";
  }
  return r;
}

CommandOutput machines_diff(const std::string& a, const std::string& b,
                            const std::vector<std::string>& data_dirs) {
  CommandOutput r;
  Machine ma, mb;
  if (!load_machine(a, data_dirs, {}, shipped_controls(), ma, r.err) ||
      !load_machine(b, data_dirs, {}, shipped_controls(), mb, r.err)) {
    r.exit_code = kExitUsage;
    return r;
  }
  const std::vector<MachineValue> va = machine_values(ma), vb = machine_values(mb);
  auto value_in = [](const std::vector<MachineValue>& vs,
                     const std::string& key) -> std::optional<std::string> {
    auto it =
        std::find_if(vs.begin(), vs.end(), [&](const MachineValue& v) { return v.key == key; });
    if (it == vs.end()) return std::nullopt;
    return it->value;
  };
  size_t differ = 0;
  std::string lines;
  auto compare = [&](const std::string& key) {
    const std::optional<std::string> x = value_in(va, key), y = value_in(vb, key);
    if (x == y) return;
    ++differ;
    lines += fmt::format("{}: {} -> {}\n", key, x.value_or("(none)"), y.value_or("(none)"));
  };
  for (const MachineValue& v : va) compare(v.key);
  for (const MachineValue& v : vb)
    if (!value_in(va, v.key)) compare(v.key);
  r.out = fmt::format("--- {}: {}\n+++ {}: {}\n{}{} {} differ\n", ma.name, ma.source, mb.name,
                      mb.source, lines, differ, differ == 1 ? "key" : "keys");
  r.exit_code = differ == 0 ? 0 : 1;
  return r;
}

}  // namespace clpost

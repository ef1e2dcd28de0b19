// The machine's own positions (templates home and tool_change_position, written without fields):
// a block that starts with one of their lines' first code moves the tool to a machine position
// the program does not state (G28 U0., G53 …), so the tool's position is unknown after it.
#include <string>
#include <vector>

#include "machine/machine_schema.h"
#include "simulator/sim_state.h"

namespace clpost::sim {

namespace {
// The G codes that begin the lines of templates home and tool_change_position, found once per
// program (State::position_codes).
const std::vector<Code>& position_codes(State& s) {
  if (s.position_codes) return *s.position_codes;
  std::vector<Code> codes;
  for (const TemplateSpec* t : {&tmpl::kHome, &tmpl::kToolChangePosition}) {
    auto it = s.m.templates.find(std::string(t->name));
    if (it == s.m.templates.end()) continue;
    for (size_t i = 0; i < it->second.size(); ++i) {
      const Code c = template_code(s.m, *t, i);
      if (!c.empty() && c.address == "G") codes.push_back(c);
    }
  }
  return *(s.position_codes = std::move(codes));
}
}  // namespace

bool machine_position_block(State& s, const NcBlock& b) {
  if (b.words.empty()) return false;
  for (const Code& c : position_codes(s)) {
    if (!has_code(b, c)) continue;
    s.pos_known = false;
    return true;
  }
  return false;
}

}  // namespace clpost::sim

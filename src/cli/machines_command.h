#pragma once
// `clpost machines show NAME|FILE [--set …] [--origin]`: the machine exactly as loaded, every key
// with its value (and where it came from); `clpost machines diff A B`: the keys whose values
// differ.
#include <string>
#include <vector>

#include "cli/schema_command.h"

namespace clpost {

CommandOutput machines_show(const std::string& machine, const std::vector<std::string>& sets,
                            bool origin, const std::vector<std::string>& data_dirs);

// Exit status 0 when the two machines are the same, 1 when they differ, 2 when one does not
// load.
CommandOutput machines_diff(const std::string& a, const std::string& b,
                            const std::vector<std::string>& data_dirs);

}  // namespace clpost

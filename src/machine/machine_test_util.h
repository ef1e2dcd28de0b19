#pragma once
// The shipped machines for tests and fuzz targets (which define CLPOST_SOURCE_DIR): the source
// tree's machines/, listed by list_machines as `clpost machines` lists them, and the registry's
// controls they load with (shipped_controls(): tests name them, the stages below the controls
// never do). A test or fuzz target that runs on every machine takes them from here and names
// none, so a machine added to machines/ is tested everywhere. (No gtest here: the fuzz targets
// use it too.)
#include <string>
#include <vector>

#include "controls/registry.h"
#include "machine/machine_loader.h"

namespace clpost::testing {

// Every shipped machine's name, sorted.
inline std::vector<std::string> shipped_machine_names() {
  std::vector<std::string> names;
  for (const MachineInfo& mi : list_machines({CLPOST_SOURCE_DIR})) names.push_back(mi.name);
  return names;
}

}  // namespace clpost::testing

#pragma once
// A loaded machine as flat `key: value` lines, every key of the declared schema in its order,
// then each number format's keys, the codes and the templates (by name): what `clpost machines
// show` prints and `clpost machines diff` compares.
#include <string>
#include <vector>

#include "machine/machine.h"

namespace clpost {

struct MachineValue {
  std::string key;    // dotted: "threading.strategy", "formats.X.decimals", "codes.rapid"
  std::string value;  // as a machine file writes it; text quoted when YAML would misread it
};

std::vector<MachineValue> machine_values(const Machine& m);

// `s` as a YAML scalar: as is when YAML reads it back as the same text, else double-quoted.
std::string yaml_scalar(const std::string& s);

}  // namespace clpost

#pragma once
// A control's own codes (machine/control.h: FixedCode) are its meaning, not machine data: once a
// machine is loaded, a post, machine file or --set that redefined one is an error at the key
// (docs/cl-meaning.md).
#include <string>
#include <string_view>

#include "machine/machine_loader.h"

namespace clpost {

// Checks m's codes against its control's fixed codes (and kIsoMotionCodes); `origins` says
// where each key was set, `machine_text` is the machine file's (its line is shown). False after
// rendering the errors into `errors`.
bool check_fixed_codes(const Machine& m, const KeyOrigins& origins, std::string_view machine_text,
                       std::string& errors);

}  // namespace clpost

#pragma once
// `clpost verify --plan PLAN.json`: the thread plans read back from `clpost plan --format json`
// (shared/reference/threading.md section 10). What the JSON leaves out is derived the way the
// planner does: pull-out ends (to + pullout), start angles (by angle when the machine has a
// start-angle word), the axis the lead is measured along. Coupled and single-pass threads have no
// path in the JSON and are refused.
#include <string>
#include <string_view>
#include <vector>

#include "machine/machine.h"
#include "planner/thread_plan.h"
#include "support/diagnostics.h"

namespace clpost {

// Parses `text` (one file's plan object); errors go to `diags` with the JSON's line and column.
bool read_plan_json(std::string_view text, const Machine& m, std::vector<ThreadPlan>& plans,
                    Diagnostics& diags);

}  // namespace clpost

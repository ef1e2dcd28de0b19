#pragma once
// What the planner needs to know of a machine. The planner does not see machines (its stage
// links only the reader): it takes PlannerSettings, and this is where a machine becomes them.
#include "machine/machine.h"
#include "planner/planner.h"

namespace clpost {

// Machine `m`'s threading defaults and words, as the planner takes them.
PlannerSettings planner_settings(const Machine& m);

}  // namespace clpost

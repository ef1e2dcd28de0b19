#pragma once
// Pass plans as text: the JSON of `clpost plan --format json` (threading.md section 10) and a
// table for people.
#include <string>
#include <string_view>
#include <vector>

#include "planner/thread_plan.h"

namespace clpost {

// One object {"file", "units", "threads": [...]} for one input file, indented with two spaces,
// one pass per line, ending in a newline. Numbers: at most 6 decimals, trailing zeros trimmed
// (num_text in number_text.h). `option`, `tool_angle` and `cutang` are null for single-pass and
// coupled threads (they have no infeed). The file name is escaped (invalid UTF-8 becomes U+FFFD).
std::string plan_to_json(const std::string& file, LengthUnit units,
                         const std::vector<ThreadPlan>& plans);

// The same plans for people: a title line for the file, then per thread a header line (line,
// form, kind, side, pitch, lead, starts, depth, option, tool angle, cutang, pull-out), a table of
// its passes (pass, start, depth, step, shift, kind, from -> to) and a line saying how the tool
// returns and where it ends.
std::string plan_to_text(const std::string& file, LengthUnit units,
                         const std::vector<ThreadPlan>& plans);

// Each pass's step: its depth less the depth its start had before it (the first pass of a start:
// its depth). The "step" column of plan_to_text and of the setup sheet.
std::vector<double> pass_steps(const ThreadPlan& p);

// Names used in both formats.
const char* form_name(ThreadForm f);
const char* kind_name(ThreadKind k);
const char* side_name(ThreadSide s);
const char* pass_kind_name(PassKind k);
const char* units_name(LengthUnit u);  // "mm" | "in"

}  // namespace clpost

#pragma once
// The kind of tool a tool change loads, as the CL says it (tool_kind.cc); TDATA/, TLDATA/,
// APPLY/, SET/MODE and MODE/ are its handlers (statement_table.h).
#include <optional>

#include "interpreter/post_state.h"

namespace clpost {

// The kind of the tool LOADTL-like statement `st` loads (its tool number is argument `first`):
// a MILL or TURN word of its own (`at` set to it), else the tool data before it (TDATA/MILL,
// TOOLNO/…,MILL), else the CL's mode (APPLY/MILL); none: a turning tool.
std::optional<ToolKindWord> loadtl_kind(const PostState& s, const Statement& st, size_t first,
                                        SourceLoc& at);
// The kind TOOLNO/n,…,MILL|TURN,… gives the next tool (the last such word), or none.
std::optional<ToolKindWord> toolno_kind(const Statement& st);

}  // namespace clpost

// Tool changes: LOADTL/n[,ADJUST|OSETNO|OFFSET,m], LOAD/TOOL,n, TURRET/n.
#include <fmt/format.h>

#include <cmath>

#include "interpreter/statement_table.h"
#include "interpreter/tool_kind.h"
#include "interpreter/tool_paths.h"
#include "machine/template_values.h"

namespace clpost {

namespace {

// A whole number 0..9999 (tool and offset numbers).
bool whole_0_9999(double v) {
  return v >= 0 && v == std::floor(v) && v <= 9999;
}

// Whether the machine's tool change can select offset `offset` for tool `tool`: its template
// writes the offset, or the offset is the tool's own (which the tool number selects).
bool offset_written(PostState& s, const Statement& st, int tool, int offset, SourceLoc at) {
  if (offset == tool || template_has_field(s.m, tmpl::kToolChange, "offset")) return true;
  error(s, st, at,
        fmt::format("machine '{}' cannot select offset {} with tool {}: its tool_change "
                    "template writes no {{offset}}, and the tool number selects offset {}",
                    s.m.name, offset, tool, tool));
  return false;
}

// The tool change whose tool number is argument `first`.
void tool_change(PostState& s, const Statement& st, size_t first) {
  double tool = 0;
  if (!number_arg(s, st, first, "a tool number", tool)) return;
  if (!whole_0_9999(tool)) {
    error(s, st, st.args[first].loc,
          fmt::format("tool number must be a whole number 0..9999, got {}", st.args[first].text));
    return;
  }
  int offset = static_cast<int>(tool);
  SourceLoc offset_loc = st.loc;
  for (size_t i = first + 1; i + 1 < st.args.size(); ++i) {
    const Arg& word = st.args[i];
    if (!(word.is("ADJUST") || word.is("OSETNO") || word.is("OFFSET")) ||
        !st.args[i + 1].is_number())
      continue;
    const Arg& o = st.args[i + 1];
    if (!whole_0_9999(o.number)) {
      error(s, st, o.loc,
            fmt::format("tool offset must be a whole number 0..9999, got {}", o.text));
      return;
    }
    offset = static_cast<int>(o.number);
    offset_loc = o.loc;
  }
  if (!offset_written(s, st, static_cast<int>(tool), offset, offset_loc)) return;
  SourceLoc kind_at;
  const std::optional<ToolKindWord> kind = loadtl_kind(s, st, first, kind_at);
  ensure_started(s);
  // The path of the tool leaving ends its work, the new tool's path is selected (tool_paths.h).
  if (!change_path(s, st, static_cast<int>(tool), kind, kind_at)) {
    s.tool = ToolInfo{};  // its SPINDL and motions are not posted: the error says why
    s.tool.number = static_cast<int>(tool), s.tool.kind = kind;
    return;
  }
  // The tool data written before this change (CATIA: TOOLNO, TPRINT, PPRINT TOOL:) describe it.
  s.tool = std::move(s.next_tool);
  s.next_tool = ToolInfo{};
  s.tool.kind = kind;
  s.prog.writer().number_next();
  tool_change_position(s, st);
  s.tool.number = static_cast<int>(tool);
  s.tool.motions_at_change = s.stats.motions;
  s.tool_line = st.loc.line;
  s.tool.offset = offset;
  time_tool_change(s);
  if (TemplateWrite r = s.prog.tool_change(static_cast<int>(tool), offset, ""); !r)
    return error(s, st, st.loc, template_error(s.m, r));
  // A tool change leaves the spindle as the CL left it (docs/cl-meaning.md).
  if (s.m.control && s.m.control->tool_change_stops_spindle && s.spindle.on)
    s.spindle_stopped = true;
  s.path->begin(s, st);
}

}  // namespace

void loadtl_stmt(PostState& s, const Statement& st) {
  tool_change(s, st, 0);
}

void load_stmt(PostState& s, const Statement& st) {
  if (st.args.empty() || !st.args[0].is("TOOL")) return unknown_stmt(s, st);
  tool_change(s, st, 1);
}

}  // namespace clpost

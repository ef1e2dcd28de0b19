// The tool change's choice of the motion path (tool_paths.h).
#include "interpreter/tool_paths.h"

#include <fmt/format.h>

namespace clpost {

bool change_path(PostState& s, const Statement& st, int tool,
                 const std::optional<ToolKindWord>& kind, SourceLoc at) {
  const bool mills = kind && kind->kind == ToolKind::kMill;
  if (mills && !s.m.live_tools) {
    const std::string where = kind->line == st.loc.line
                                  ? std::string("LOADTL's MILL word")
                                  : fmt::format("{} at line {}", kind->said, kind->line);
    error(s, st, at,
          fmt::format("tool {} is a milling (live) tool ({}), but machine '{}' has no live tools "
                      "(millturn.live_tools: false): its SPINDL would turn the main spindle, "
                      "with the part, at the live tool's speed",
                      tool, where, s.m.name));
    s.paths->live.reported = true;  // its motions are not reported again
    follow_tool_axis(s);
    return false;
  }
  s.path->leave(s, st, false);
  s.tool_axis = ToolAxis{};  // a tool axis the CL gave the last tool is not the new one's
  s.path = mills ? static_cast<ToolPath*>(&s.paths->face) : &s.paths->turning;
  s.path->prepare(s, st);
  return true;
}

void follow_tool_axis(PostState& s) {
  if (s.tool_axis.radial)
    s.path = &s.paths->radial;
  else
    s.path = &s.paths->face;
}

std::vector<MillSegment> take_mill(PostState& s) {
  return std::move(s.paths->live.written);
}

}  // namespace clpost

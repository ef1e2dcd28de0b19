#pragma once
// The motion paths of one post with their state (tool_path.h), and the tool change's choice among
// them (tool_paths.cc): the only place that asks which kind of tool is loaded.
#include <optional>
#include <vector>

#include "interpreter/live_path.h"
#include "interpreter/turning_path.h"

namespace clpost {

struct ToolPaths {
  TurningPath turning;
  LiveState live;
  LiveFacePath face{live};
  LiveRadialPath radial{live};
};

// The tool change (tool.cc) to tool `tool` of `kind` (loadtl_kind): the path in force leaves, the
// tool axis goes back to the spindle's, and the path for the kind is selected and prepared
// (PostState::path). False (an error at `at`): a milling tool on a machine without live tools;
// the live path is selected still, with its motions reported (left out silently).
bool change_path(PostState& s, const Statement& st, int tool,
                 const std::optional<ToolKindWord>& kind, SourceLoc at);
// A live tool's GOTO gave a tool axis (PostState::tool_axis): the face or the radial path.
void follow_tool_axis(PostState& s);
// Every milling piece the live paths wrote (Interpreter::take_mill).
std::vector<MillSegment> take_mill(PostState& s);

}  // namespace clpost

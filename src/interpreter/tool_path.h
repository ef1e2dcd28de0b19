#pragma once
// The motion path of the loaded tool: how the statements that move a tool, turn its spindle or
// end its work are written for the kind of tool the last tool change loaded. Turning
// (turning_path.h): the main spindle turns the part. A live tool (live_path.h): a driven tool
// mills while the main spindle stands as the C axis, at the face (the tool axis along the
// spindle's) or across the axis (radial). The tool change selects the path once (tool_paths.h,
// change_path); the statement handlers call the one in force (PostState::path) and never ask
// which kind of tool is loaded. Each path keeps its own state (a live tool's: LiveState);
// PostState holds what every path shares: the CL's modal state, the main spindle, the C axis.
//
// A new kind of path (a turning tool on the sub-spindle, a channel's own) is a class that
// implements this interface in its own file, its state in ToolPaths, and one case in
// change_path: no handler changes.
#include "interpreter/post_state.h"
#include "interpreter/spindle_words.h"

namespace clpost {

class ToolPath {
 public:
  virtual ~ToolPath() = default;

  // The tool change (tool.cc): before its block, what the machine does first for this path's
  // tool (a live tool: the main spindle stops); after it, the path begins (a live tool: C
  // engaged).
  virtual void prepare(PostState& s, const Statement& st) = 0;
  virtual void begin(PostState& s, const Statement& st) = 0;
  // The tool's work ends: before the next tool change, or at the program end (`program_end`:
  // the C axis is released too, whatever the tool).
  virtual void leave(PostState& s, const Statement& st, bool program_end) = 0;

  // GOTO/x,y,z,i,j,k gave a tool axis (PostState::tool_axis, already stored).
  virtual void tool_axis(PostState& s, const Statement& st) = 0;
  // GOTO/ to CL point `p`: every motion of a turning program comes here.
  virtual void go_to(PostState& s, const Statement& st, const Point3& p) = 0;
  // GODLTA/: to `p`, where the increment takes the tool.
  virtual void go_delta(PostState& s, const Statement& st, const Point3& p) = 0;
  // CIRCLE/ (and MOVARC/) `c`: the arc the next GOTO ends.
  virtual void circle(PostState& s, const Statement& st, const Circle& c) = 0;
  // HELICAL/.
  virtual void helical(PostState& s, const Statement& st) = 0;
  // Geometric motion: GOFWD/, GOLFT/, GORGT/, GOBACK/; and PSIS/, its part surface.
  virtual void go(PostState& s, const Statement& st) = 0;
  virtual void part_surface(PostState& s, const Statement& st) = 0;
  // A lathe rapid (move_to) ended at radius `x` (output units).
  virtual void rapid_reached(double x) = 0;

  // SPINDL/ with its words read.
  virtual void spindle(PostState& s, const Statement& st, SpindleWords w) = 0;
  // Whether the main spindle that a control's tool change stopped turns again before this
  // path's next motion (restart_stopped_spindle): a live tool keeps it stopped.
  virtual bool turns_main_spindle() const = 0;
  // CUTCOM/ to `c`, `word` its LEFT, RIGHT or OFF as written.
  virtual void cutter_comp(PostState& s, const Statement& st, const Arg& word, CutterComp c) = 0;
  // ROTABL/ is about to index C (engaged).
  virtual void before_c_index(PostState& s, const Statement& st) = 0;
};

}  // namespace clpost

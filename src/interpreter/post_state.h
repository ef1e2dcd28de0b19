#pragma once
// The state of one post in progress: the machine, the program being written, the diagnostics and
// the CL's modal state (units, position, feed, spindle, tool, thread sequences). Every statement
// handler (statement_table.h) reads and changes it; one PostState per file, nothing shared. What
// one kind of tool alone needs is its motion path's (tool_path.h): PostState holds the path in
// force and the paths with their state (ToolPaths).
#include <algorithm>
#include <cmath>
#include <functional>
#include <memory>
#include <optional>
#include <string>
#include <string_view>
#include <vector>

#include "emitters/cycle_output.h"
#include "interpreter/cl_motion.h"
#include "interpreter/cycle_time.h"
#include "interpreter/hole_cycle.h"
#include "interpreter/thread_sequence.h"
#include "laws/xzc_law.h"
#include "machine/machine.h"
#include "planner/thread_plan.h"
#include "reader/statement.h"
#include "support/diagnostics.h"
#include "writer/nc_program.h"

namespace clpost {

struct PostOptions {
  bool strict = false;        // unknown statements are errors, not warnings
  bool keep_motions = false;  // collect every motion's end point (verify of the whole path)
  // Where a program waits for its header (program_header), on disk: the directory of its output
  // file (OutputFile::directory_beside), empty for the system's temporary directory.
  std::string spool_dir{};
  // With keep_motions: each motion, once finished, with its state, handed over and not kept
  // (ClPath then holds the last motion and state only): verify while the program is written.
  std::function<void(const ClMotion&, const CutStateAt&)> on_motion{};
  // Each piece of a live tool's milling as it is written, handed over and not kept (PostSummary::
  // mill then empty): verify of milling while the program is written.
  std::function<void(const MillSegment&)> on_mill{};
};

struct PostStats {
  size_t statements = 0;
  size_t motions = 0;
  size_t threads = 0;
  size_t passes = 0;
};

// CIRCLE/ waiting for the GOTO that ends its arc.
struct Circle {
  double cx = 0, cy = 0, cz = 0, ax = 0, ay = 0, az = 0, radius = 0;
  SourceLoc loc;
};

// The spindle as last programmed.
struct SpindleState {
  bool on = false;
  bool css = false;
  double value = 0;  // rpm, or the surface speed when css
  double css_max_rpm = 0;
  std::optional<double> cl_max_rpm;  // the CL's last MAXRPM, in force until changed
  SpindleDir dir = SpindleDir::kCw;
};

// What a tool does: turn (the main spindle turns the part) or mill (a driven tool turns, the
// part stands still or moves as the C axis). docs/millturn.md.
enum class ToolKind : uint8_t { kTurn, kMill };

// Where the CL said a tool mills or turns (LOADTL/…,MILL, TDATA/MILL, APPLY/MILL, …).
struct ToolKindWord {
  ToolKind kind = ToolKind::kTurn;
  std::string said;   // "TDATA/MILL"
  uint32_t line = 0;  // its CL line (0: none)
};

// The C axis as the program left it (millturn.cc).
struct CAxisState {
  bool engaged = false;  // the main spindle is the C axis (codes.c_engage written)
  bool clamped = false;  // codes.c_clamp written since C last moved
  bool cl_unclamped =
      false;  // CLAMP/OFF,CAXIS in force: no clamp after an index (docs/millturn.md)
  std::optional<double> angle;  // C as last written (unknown after engaging)
  // The last ROTABL's angle: the part frame is turned by it (a hole off the X axis is at this
  // index plus its own angle, hole_live.cc), while C may have moved on to a hole.
  std::optional<double> index;
};

// The tool axis as the CL's last GOTO/x,y,z,i,j,k gave it, until the next tool change (one that
// is refused keeps it): what a live tool's path reads (its face or radial work, tool_paths.h); a
// turning tool's is noted and ignored.
struct ToolAxis {
  Point3 dir{0, 0, 1};  // a unit vector in the CL frame (the last one given of length > 0)
  bool radial = false;  // not along the spindle's axis (or of length 0): across it, or tilted
};

class ToolPath;
struct ToolPaths;

// The tool in the spindle or turret station, as the CL described it: the tool change sets number
// and offset; tool-data words (TOOLNO, TPRINT, CUTTER, SWITCH, a `PPRINT TOOL:` comment) fill in
// what they say. Read by the tool list and by whatever needs the tool's geometry.
struct ToolInfo {
  int number = -1;                    // -1: no tool loaded yet
  int offset = -1;                    // the offset register selected with it (-1: none yet)
  std::string text;                   // its description (TPRINT, PPRINT TOOL:, TOOLNO)
  std::optional<double> nose_radius;  // CL units
  std::optional<int> tip_quadrant;    // tool-tip direction 1..9 (SWITCH/n), for nose-radius
                                      // compensation
  std::string feed, speed;            // its default feed and speed as written ("0.1 MMPR")
  std::optional<ToolKindWord> kind;   // what the CL said it does (none: it turns)
  std::optional<double> diameter;     // CL units: CUTTER/d, TLDATA/MILL|DRILL,…,d
  size_t motions_at_change = 0;       // PostStats::motions when it was loaded
};

// The largest CL value (coordinate, feed, speed, time) that becomes an NC word: anything larger
// is a units mistake or garbage, and would not fit an NC address anyway.
inline constexpr double kMaxClValue = 1e6;
inline bool within_limits(double v) {
  return std::abs(v) <= kMaxClValue;  // NaN is not
}

struct PostState {
  PostState(const Machine& machine, NcProgram& program, Diagnostics& d, const PostOptions& o);
  ~PostState();

  const Machine& m;
  NcProgram& prog;
  Diagnostics& diags;
  PostOptions opts;
  PostStats stats;
  std::function<void(const ThreadPlan&)> on_thread;  // every thread plan (clpost plan)

  LengthUnit units;
  bool started = false;  // the program's start template is written
  bool ended = false;    // FINI seen (or the end written)
  std::string partno;
  std::optional<Point3> pos;  // where the tool is, in the CL frame (unknown at first)
  int home_line = 0;          // the CL line of the last GOHOME that wrote the home template
  bool rapid_next = false;    // RAPID: the next move only
  std::optional<Circle> circle;
  bool feed_given = false;
  FeedMode feed_mode = FeedMode::kPerMinute;
  double feed = 0;  // output units
  SpindleState spindle;
  // The motion path of the tool loaded (tool_path.h), selected at the tool change, and every
  // path of the post with its own state (tool_paths.h).
  std::unique_ptr<ToolPaths> paths;
  ToolPath* path = nullptr;
  // Mill-turn (millturn.cc): the C axis (the main spindle as an axis, for any tool's ROTABL/),
  // the CL's mill/turn mode (APPLY/, SET/MODE, MODE/) for tool changes that do not say.
  CAxisState c;
  std::optional<ToolKindWord> cl_mode;
  ToolAxis tool_axis;
  bool spindle_stopped = false;     // the control's tool change stopped the CL's turning spindle
  Coolant coolant = Coolant::kOff;  // as the CL last set it
  // OPSKIP/ON … OFF: the spindle and coolant before the range, which the blocks after it must
  // state again when a skipped block changed them.
  std::optional<std::pair<SpindleState, Coolant>> before_skip;
  bool spindle_in_skip = false;  // a SPINDL/ inside the range wrote the spindle
  // The CL lines that last set the tool, the feed and the spindle (verify's messages).
  uint32_t tool_line = 0, feed_line = 0, spindle_line = 0;
  // The lathe frame: the CL axis of the radius. With cl.radial_axis: auto it is found at the
  // first point off the spindle axis (frame.cc); until then points lie on the axis and every
  // choice gives the same output.
  ClAxis radial = ClAxis::kX;
  bool radial_auto = false;   // cl.radial_axis: auto
  uint32_t radial_found = 0;  // the CL line that decided it (auto; 0: not yet)
  int off_plane_axis = -1;    // the third axis once the frame is settled (-1: not yet)
  ToolInfo tool;              // the tool loaded last
  ToolInfo next_tool;  // tool data written before the tool change it describes (TOOLNO, TPRINT)
  double cutter_diameter = 0;      // CUTTER/
  bool dntcut = false;             // DNTCUT … CUT: moves set the position, nothing is cut
  std::optional<Point3> indirv;    // INDIRV/: the direction of the next geometric motion
  std::optional<Point3> last_dir;  // the direction the last motion ended in
  // SYN/'word','replacement': major words read as others; an empty replacement: ignored.
  std::vector<std::pair<std::string, std::string>> synonyms;
  bool in_cycle = false;  // between CYCLE/ and CYCLE/OFF: its GOTOs are holes or not posted
  std::optional<HoleCycle> hole_cycle;  // a hole-making cycle in force: its GOTOs are holes
  std::vector<Hole> holes;              // every hole written, in order (verify)
  std::vector<OutputUsed> outputs;      // the output of every thread, hole and undercut written
  CycleTime clock;                      // the tool list and estimated times (cycle_time.h)
  ClPath cl_path;                       // with PostOptions::keep_motions
  std::optional<Vec2> clock_at;         // where the clock's tool is (lathe frame), if known
  size_t y_warnings = 0;                // points off the lathe plane (warned once)
  std::vector<std::string> noted;       // keys of notes already given once
  ThreadSequence thread;                // the thread sequence being read, if any
  double clock_feed = -1;         // the feed in force for the clock, per minute (time_feed_rate)
  bool clock_feed_noted = false;  // the clock tool's feeds and speeds have the feed in force
};

// Diagnostics at statement `st` (its own line text is shown).
void error(PostState& s, const Statement& st, SourceLoc loc, std::string msg);
void warning(PostState& s, const Statement& st, SourceLoc loc, std::string msg);
// A note at `st`, given once per `key` in a file.
void note_once(PostState& s, const Statement& st, std::string_view key, std::string msg);

// Argument `i` of `st` as a number within ±kMaxClValue into `out`; false (reported) otherwise.
// Inline for the common case (every GOTO coordinate comes here), the diagnostics out of line.
bool bad_number_arg(PostState& s, const Statement& st, size_t i, std::string_view what);
inline bool number_arg(PostState& s, const Statement& st, size_t i, std::string_view what,
                       double& out) {
  if (i < st.args.size() && st.args[i].is_number() && within_limits(st.args[i].number)) {
    out = st.args[i].number;
    return true;
  }
  return bad_number_arg(s, st, i, what);
}
// `a` within ±kMaxClValue; false (reported) otherwise.
bool in_range(PostState& s, const Statement& st, const Arg& a, std::string_view what);
// The message for `a`, one of st.args, where a word of `major`'s vocabulary was expected:
// "unknown SPINDL word 'X': expected …" for a word, else "SPINDL/: expected …, found an empty
// argument" (reader/statement.h describe_arg: never an empty '').
std::string unknown_word(const Statement& st, const Arg& a, std::string_view major,
                         std::string_view expected);
// The arguments from `from` on as written, joined by ',' ("" when they are all empty), for
// "the words after it are not written (…)".
std::string rest_of_args(const Statement& st, size_t from);

// Writes the program start (once) before the first block.
void ensure_started(PostState& s);
// CIRCLE/ applies to the next GOTO only (docs/cl-meaning.md): true, with an error naming the
// circle, when one waits for its GOTO and `st` moves the tool otherwise (motion.cc).
bool circle_waits(PostState& s, const Statement& st);
// Writes the spindle as the CL last left it (speed or surface speed with its limit, direction)
// (spindle_feed.cc).
void restate_spindle(PostState& s, const Statement& st);
// Before a motion: the spindle a control's tool change stopped (LinuxCNC's M6) turns again as
// the CL left it, unless a SPINDL/ came first. The common case inline (every GOTO comes here):
// the spindle was not stopped.
void restart_stopped_spindle(PostState& s, SourceLoc loc, std::string_view line_text);
inline void restart_stopped_spindle(PostState& s, const Statement& st) {
  if (s.spindle_stopped) [[unlikely]]
    restart_stopped_spindle(s, st.loc, st.line_text(st.loc.line));
}

// The lathe frame: a CL point as (radius, axial) in CL units, and as NcProgram's point.
Vec2 cl2(const PostState& s, Point3 p);
inline LathePoint lathe(const PostState& s, Point3 p) {
  const Vec2 v = cl2(s, p);
  return LathePoint{v.x, v.z};
}
// The CL point of lathe-frame point `v` (the third axis 0).
Point3 cl_point(const PostState& s, Vec2 v);
// The CL axis that is neither radial nor axial: a lathe has none.
ClAxis third_axis(const PostState& s);
double axis_value(Point3 p, ClAxis a);
// Every CL point the program moves through comes here first (frame.cc): with cl.radial_axis:
// auto the first point off the spindle axis decides the radial axis (a note), and a point off
// the lathe plane after that is an error; with a fixed axis such a point is warned about once
// and its third coordinate ignored. False: an error was reported.
// The common case inline (every GOTO comes here): the frame is settled and the point on the plane.
bool frame_point_checked(PostState& s, const Statement& st, const Point3& p);
inline bool frame_point(PostState& s, const Statement& st, const Point3& p) {
  if (s.off_plane_axis >= 0) {
    const double v[3] = {p.x, p.y, p.z};
    if (!(std::abs(v[s.off_plane_axis]) > 1e-6)) return true;
  }
  return frame_point_checked(s, st, p);
}
// An arc's axis `n` (cl.radial_axis: auto, not yet found): an axis normal to one of the two
// candidate planes decides the radial axis (a note); anything else leaves it open.
void frame_normal(PostState& s, const Statement& st, Point3 n);

}  // namespace clpost

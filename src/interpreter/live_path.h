#pragma once
// The paths of a live (milling) tool (tool_path.h, docs/millturn.md): a driven tool mills while
// the main spindle stands still as the C axis. It works the face, its axis along the spindle's
// (live_face_path.cc), or across the axis, its axis through the centre line (radial:
// live_radial_path.cc); the GOTO that gives another tool axis turns one into the other. What
// both do alike is LivePath's (live_path.cc): the tool change, the live spindle, cutter
// compensation, holes, and leaving the milling. The motion itself is written by the milling
// engine (milling_motion.h): X Y Z on a machine with Y, X Z C computed by the post without it,
// or the control's polar interpolation.
#include <algorithm>
#include <optional>
#include <vector>

#include "interpreter/tool_path.h"
#include "laws/xzc_law.h"

namespace clpost {

// The milling of the tool loaded, as written so far: the plane and Y of a machine with Y, the
// feed mode of XZC moves, polar interpolation. Back to its start when the milling ends
// (LivePath::leave_milling).
struct MillState {
  int plane = 18;                   // the plane in force: 17 (plane_face), 19 (plane_side), 18
  double y = 0;                     // Y as last written (output units)
  bool inverse_time = false;        // codes.inverse_time in force
  bool per_minute = false;          // codes.feed_per_min written for this tool's milling
  bool polar = false;               // in polar interpolation (codes.polar_on written)
  double polar_x = 0, polar_y = 0;  // there: the tool in the face plane at C0 (a radius)
  // The live tool's G41/G42 in force (CUTCOM): the plane does not change under it, and G40 is
  // written before the plane goes back (LivePath::leave_milling).
  CutterComp comp = CutterComp::kOff;
  // The largest X (a radius, output units) a rapid of this live tool reached: its approach,
  // which the CL put in the clear. A radial tool goes back out to it before the post's own Y 0.
  std::optional<double> rapid_x;
  void rapid_reached(double x) { rapid_x = std::max(rapid_x.value_or(x), x); }
};

// The live paths' state, one for the post (ToolPaths::live).
struct LiveState {
  // The live tool's spindle as last programmed: a later live tool's SPINDL/ON turns at its speed.
  SpindleState spindle;
  MillState mill;
  // The first milling motion of the tool loaded that is not written was reported (later ones are
  // left out silently: one cause, one message).
  bool reported = false;
  // Every milling piece written, in order (verify), unless PostOptions::on_mill takes them.
  std::vector<MillSegment> written;
};

// How far a live tool's work ends (LivePath::leave_milling).
enum class Leave : uint8_t {
  kMilling,  // the milling moves end, the tool stays: before a hole, before C indexes in polar
  kTool,     // the tool leaves: a tool change
  kProgram,  // the program ends: C is released too
};

class LivePath : public ToolPath {
 public:
  // `radial`: the tool works across the axis, else the face.
  LivePath(LiveState& l, bool radial) : l_(l), radial_(radial) {}

  void prepare(PostState& s, const Statement& st) override;
  void begin(PostState& s, const Statement& st) override;
  void leave(PostState& s, const Statement& st, bool program_end) override;
  void tool_axis(PostState& s, const Statement& st) override;
  void go_delta(PostState& s, const Statement& st, const Point3& p) override;
  void circle(PostState& s, const Statement& st, const Circle& c) override;
  void helical(PostState& s, const Statement& st) override;
  void go(PostState& s, const Statement& st) override;
  void part_surface(PostState& s, const Statement& st) override;
  void rapid_reached(double x) override { l_.mill.rapid_reached(x); }
  void spindle(PostState& s, const Statement& st, SpindleWords w) override;
  bool turns_main_spindle() const override { return false; }
  void cutter_comp(PostState& s, const Statement& st, const Arg& word, CutterComp c) override;
  void before_c_index(PostState& s, const Statement& st) override;

 protected:
  // Before the post's own Y 0 at the end of the milling: what takes the tool clear of the part
  // first (a face tool: nothing; a radial tool: X out).
  virtual void retract(PostState&) {}
  // The end of the milling, in the one order a control takes it (docs/millturn.md, "What a tool
  // change does"): cutter compensation off, polar interpolation off, the retract and Y back to
  // 0, the lathe plane; then with kTool or kProgram the live spindle stops, with kProgram C is
  // released.
  void leave_milling(PostState& s, const Statement& st, Leave how);
  // A hole cycle's GOTO to `p`: the milling ends, then the hole (hole_live.h).
  void hole(PostState& s, const Statement& st, Point3 p);

  LiveState& l_;
  const bool radial_;
};

// A live tool at the face (live_face_path.cc): its axis along the spindle's.
class LiveFacePath final : public LivePath {
 public:
  explicit LiveFacePath(LiveState& l) : LivePath(l, false) {}
  void go_to(PostState& s, const Statement& st, const Point3& p) override;
};

// A live tool across the axis (live_radial_path.cc): its axis through the centre line.
class LiveRadialPath final : public LivePath {
 public:
  explicit LiveRadialPath(LiveState& l) : LivePath(l, true) {}
  void go_to(PostState& s, const Statement& st, const Point3& p) override;

 private:
  void retract(PostState& s) override;
};

}  // namespace clpost

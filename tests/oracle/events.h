#pragma once
// The oracle's events: what a CL program means (model.h) and what LinuxCNC's interpreter does
// with the posted program (canon.h), in one form, in mm, so that the two can be compared
// (compare.h). Written from docs/cl-meaning.md; shares no code with src/.
#include <string>
#include <vector>

namespace oracle {

constexpr double kMmPerInch = 25.4;
constexpr int kHomeX = 1, kHomeZ = 2;

enum class MotionKind { kRapid, kFeed, kArc, kThread };
enum class FeedMode { kPerMinute, kPerRev };
enum class SpindleDir { kCw, kCcw };

struct Spindle {
  bool on = false;
  SpindleDir dir = SpindleDir::kCw;
  bool css = false;  // constant surface speed
  double speed = 0;  // rev/min, or m/min at constant surface speed
  double limit = 0;  // rev/min, constant surface speed only
};

struct Coolant {
  bool flood = false, mist = false;
};

// The modal state a motion is made with.
struct Modal {
  bool feed_given = false;
  double feed = 0;  // mm/min or mm/rev
  FeedMode feed_mode = FeedMode::kPerMinute;
  Spindle spindle;
  int tool = 0, offset = 0;
  Coolant coolant;
};

// Where a model event's state came from: CL lines, and what happened since (for the report and
// for sorting differences into classes).
struct Provenance {
  int feed_line = 0;
  bool feed_without_mode = false;  // the FEDRAT in force had no mode word
  bool units_since_feed = false;   // a UNITS switch came after it
  int spindle_line = 0;
  bool spindle_by_on = false;        // the spindle state is SPINDL/ON's
  bool maxrpm_from_earlier = false;  // the CSS limit is an earlier statement's MAXRPM
  bool units_since_spindle = false;
  bool tool_change_since_spindle = false;
  int tool_line = 0;
  bool feed_in_range = false;      // the FEDRAT in force is inside an OPSKIP range
  bool spindle_in_range = false;   // so is the SPINDL
  bool coolant_in_range = false;   // and the COOLNT
  bool after_range = false;        // the first motion after an OPSKIP range
  bool units_since_pitch = false;  // a UNITS switch came after the PITCH in force
  bool modal_pitch = false;        // a thread cut at PITCH's lead (not its own)
};

struct Event {
  enum class Kind { kMotion, kDwell };
  Kind kind = Kind::kMotion;
  MotionKind motion = MotionKind::kRapid;
  double x = 0, z = 0;    // end point, mm, X a radius
  double cx = 0, cz = 0;  // arc centre
  int rotation = 0;       // arc: +1 counter-clockwise in (Z, X) seen from +Y, -1 clockwise
  double lead = 0;        // thread, mm/rev
  double seconds = 0;     // dwell
  Modal state;
  // A return to the machine's reference position (GOHOME, G28): the axes it returns, kHomeX |
  // kHomeZ (GOHOME: both); x and z unsaid.
  int home = 0;
  bool skipped = false;  // inside an OPSKIP range (model)
  bool inch = false;     // the units the numbers were read in (rs274: the program's)
  int line = 0;          // the CL line (model) or the canonical call's number (rs274)
  std::string source;    // the CL statement or the canonical call
  Provenance why;        // model only
};

// One line: "feed to X10.0000 Z-2.0000 | F0.2000/rev | S800 rpm CW | T3 H3 | (CL 7: GOTO/...)".
std::string describe(const Event& e);
std::string describe_state(const Modal& m, bool with_feed);

// The M codes the control readers take alike (DIN 66025 / ISO 6983-1, and each control's manual
// cited at its reader's mcode): M3/M4 start the spindle clockwise/counter-clockwise, M5 stops
// it, M7 mist and M8 flood coolant on, M9 both off. False for any other M code (nothing set).
bool spindle_coolant_m(int m, bool& on, bool& ccw, Coolant& coolant);

}  // namespace oracle

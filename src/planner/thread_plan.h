#pragma once
// Thread descriptions (what the CL says) and pass plans (what will be cut). Pure data; the
// planner functions are in planner.h. Semantics: shared/reference/threading.md and
// docs/threading.md.
#include <cstdint>
#include <optional>
#include <string>
#include <vector>

#include "support/source_loc.h"
#include "support/vec2.h"

namespace clpost {

enum class LengthUnit : uint8_t { kMm, kInch };

// Modal pitch state (PITCH/, or the pitch couplets of THREAD/ and COUPLE/), in CL units.
struct PitchSpec {
  bool set = false;
  double pitch = 0;           // crest to crest, CL units
  bool from_tpi = false;      // the CL gave threads per inch (some controls have a TPI word)
  double tpi = 0;             // when from_tpi
  int starts = 1;             // MULTRD
  double lead_change = 0;     // INCR (+) / DECR (-): change of lead per revolution, CL units
  SourceLoc loc;              // where the pitch was given
  SourceLoc starts_loc;       // where MULTRD was given (line 0: never)
  SourceLoc lead_change_loc;  // where INCR / DECR was given (line 0: never)
};

enum class ThreadForm : uint8_t { kMulti, kSingle, kCouple, kChain };
enum class ThreadKind : uint8_t { kTurn, kFace, kTaper };
enum class ThreadSide : uint8_t { kExternal, kInternal };
enum class PassKind : uint8_t { kRough, kFinish, kSpring };

struct ThreadPass {
  int n = 0;         // 1-based pass number (depth ladder index)
  int start = 0;     // start index k, 0-based
  double depth = 0;  // cumulative depth d_i
  PassKind kind = PassKind::kRough;
  double shift = 0;  // flank shift sigma_i along the cutting direction
  Vec2 approach;     // where the infeed along CUTANG begins (on the clearance line)
  Vec2 from;         // synchronized cut start
  Vec2 to;           // synchronized cut end
  Vec2 pullout_end;  // to + pull-out delta (== to when there is no pull-out)
  Vec2 clear;        // after the cut: the tool rapids here (clear of the thread, above the end)
  double start_angle = 0;  // spindle start angle in degrees for this start (0 when starts are
                           // made by offset)
  // A chained thread (threading.md section 11): the vertices of the synchronized cut in cutting
  // order, `from` first and `to` last. Empty for the other forms (their cut is from -> to).
  std::vector<Vec2> path;
};

struct ThreadPlan {
  SourceLoc loc;  // THREAD/ON, THREAD/<kind>, COUPLE/ON or OP/THREAD statement
  ThreadForm form = ThreadForm::kMulti;
  ThreadKind kind = ThreadKind::kTurn;
  ThreadSide side = ThreadSide::kExternal;
  LengthUnit units = LengthUnit::kMm;
  PitchSpec pitch;   // pitch, TPI, starts, variable lead
  double lead = 0;   // starts x pitch
  double depth = 0;  // full thread depth D
  int option = 0;
  double tool_angle = 60;
  double cutang = 0;  // degrees, the infeed direction actually used
  Vec2 p0, p1, p2;
  std::optional<Vec2> pullout;     // the delta, or none
  bool pullout_linear = false;     // chamfer angle outside 30..60: cut with G1 in emulation
  bool starts_by_angle = false;    // multi-start made with a spindle start angle (else offset)
  bool feed_approach = false;      // the CL had feed (not RAPID) in force for the approach
  Vec2 end_position;               // where the tool is when the thread is done
  double clearance = 0;            // height of the clear line above the line P1-P2 (outward)
  bool lead_along_z = true;        // |dZ| >= |dX|: the lead is measured along Z (else along X)
  std::vector<ThreadPass> passes;  // in cutting order
  // Coupled / single-pass threads: the synchronized moves in order (the first point is where
  // the tool is when the thread starts).
  std::vector<Vec2> path;
  // A chained thread: the contour P1 ... Pk as the CL gives it (the passes are it translated).
  std::vector<Vec2> points;
  size_t passes_not_kept = 0;  // a coupled path longer than the plan keeps: moves cut, not listed
  // Where the lead is not yet right (planner/run_in.h): the spindle speed the thread is cut at
  // (0: not known) and, along the lead axis, the run-in δ1 and run-out δ2 of every cut.
  double rpm = 0;
  double run_in = 0;
  double run_out = 0;
  bool run_in_added = false;  // threading.run_in auto: every pass begins run_in before P1
};

}  // namespace clpost

#pragma once
// Verify of the whole path: every CL motion's end point (GOTO, GODLTA, arcs) is reached by the
// program, in order, by the same kind of move (a rapid where the CL rapids, a straight feed or an
// arc of the same sense around the same centre where it cuts), within the tolerance, and with the
// CL's tool, feed (value and mode) and spindle (direction, RPM or CSS, speed, limit) as the
// program's words set them (simulator/toolpath.h's StateReadback says which the machine's words
// let it read) — so that a machine file writing a wrong word anywhere, or a program edited by
// hand, is caught as a control emulator would catch it. A state difference is reported once,
// where it begins. Thread passes and holes are compared on their own (verify.h, hole_verify.h);
// their moves lie between these points.
#include <cstdio>
#include <memory>
#include <string>
#include <vector>

#include "interpreter/cl_motion.h"
#include "laws/hole_law.h"
#include "laws/xzc_law.h"
#include "simulator/toolpath.h"
#include "support/diagnostics.h"
#include "support/ring.h"
#include "verify/verify.h"

namespace clpost {

// What the CL file says the program must do besides its threads.
struct ClExpected {
  std::vector<Hole> holes;
  ClPath path;
  std::vector<MillSegment> mill;  // a live tool's milling (verify/mill_verify.h)
};

struct PathReport {
  std::string text;  // a summary line (and the first difference), "" when there are no motions
  size_t problems = 0;
};

// The whole path in memory (clpost verify --cl).
PathReport verify_path(const ClPath& cl, const Toolpath& path, const Machine& m,
                       const VerifyOptions& options, Diagnostics& nc_diags);

// The same comparison as the CL motions and the program's moves come (clpost --verify: the CL
// is posted while the program is read back): a CL motion is compared once `window` moves past
// the one it is looked for from have come (or at the end), and the moves behind are let go, so
// memory does not grow with the file. With a window as long as the program, verify_path.
class PathStream {
 public:
  struct ClStep {
    ClMotion motion;
    CutStateAt state;
    bool known = false;  // state is the motion's
  };
  struct ProgramMove {
    Move move;
    CutState state;
    bool known = false;  // state is the move's
  };
  struct Check;
  // `units`: the program's as it is read (the messages' feed and speed units).
  PathStream(const Machine& m, const VerifyOptions& options, const StateReadback& readback,
             const LengthUnit& units, size_t window);
  ~PathStream();
  // A CL motion, in order, with its state (nullptr: not known, not compared).
  void cl_motion(const ClMotion& c, const CutStateAt* state);
  // A program move, in order (the entries from an unknown position among them).
  void program_move(const Move& mv, const CutState* state);
  // This stream made what `o` is now (its comparison so far, the CL motions it has waiting, on
  // disk too), with its own units: as if it had had o's input. (The program with block delete
  // on is compared by o until it first differs from the program with it off.)
  void take_over(const PathStream& o);
  // Both ended: the motions left compared, every problem added to `nc_diags` in order.
  // `cl_states`: how many states the CL made (the summary says it).
  PathReport finish(size_t cl_states, Diagnostics& nc_diags);

 private:
  static constexpr size_t kSpillBatch = 4096;
  void advance(bool at_end);
  void queue(const ClStep& step);
  void refill();
  size_t window_;
  // CL motions beyond the window wait on disk, then in spill_buffer_, after cl_.
  std::FILE* spill_ = nullptr;
  size_t spill_written_ = 0, spill_read_ = 0;  // motions written to it, read back
  std::vector<ClStep> spill_buffer_;
  double shown_ = 0;  // the tolerance as the report says it
  Ring<ClStep> cl_;
  std::unique_ptr<Check> k_;
};

}  // namespace clpost

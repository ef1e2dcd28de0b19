#pragma once
// Verify of a live tool's milling (docs/millturn.md): the program's moves in X, Y, Z and C
// (simulator/control_sim.h SimMillMove) mapped back to the part (X the radius at angle C, Y
// across: the point turned by C) against the CL's milling in the part frame turned by its C
// index (laws/xzc_law.h MillSegment): every CL point reached in order, and every feed move,
// sampled as the control moves (X, Y, Z and C linear), within the tolerance of the CL path.
#include <memory>
#include <string>
#include <vector>

#include "laws/xzc_law.h"
#include "simulator/control_sim.h"
#include "support/diagnostics.h"
#include "verify/verify.h"

namespace clpost {

struct MillReport {
  std::string text;     // the report's lines ("" without milling)
  size_t problems = 0;  // CL motions not reached or left
};

// The tolerance: the verify tolerance, and the machine's xzc_tolerance plus the written
// numbers' rounding. Every problem is also an error in `nc_diags` at the program's line.
// `nc_count`: the program's moves in X, Y, Z and C in all (Simulation::mill_move_count), of
// which `nc` are those that can be milling.
MillReport verify_milling(const std::vector<MillSegment>& cl, const std::vector<SimMillMove>& nc,
                          size_t nc_count, const Machine& m, const VerifyOptions& options,
                          Diagnostics& nc_diags);

// The same as the moves come (clpost --verify, verify --cl): the CL's milling pieces as they are
// posted, the program's moves as they are read, in either order; compared as they come, holding
// only the CL motions and program moves the walk has not reached.
class MillStream {
 public:
  MillStream(const Machine& m, const VerifyOptions& options);
  ~MillStream();
  void cl_segment(const MillSegment& g);
  // A CL motion that is not milling (the milling before it is whole), and the CL's end.
  void cl_break();
  void cl_ended();
  void program_move(const SimMillMove& m);
  // Both ended: the report, as verify_milling's.
  MillReport finish(size_t nc_count, Diagnostics& nc_diags);

 private:
  struct Impl;
  std::unique_ptr<Impl> impl_;
};

}  // namespace clpost

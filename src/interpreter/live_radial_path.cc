// A live tool across the axis (live_path.h, docs/millturn.md): its axis through the centre line,
// at the part's periphery. Its approach along X at Y 0 is the lathe's XZ move; its other GOTOs
// are milling (in X Y Z with Y, in X Z C without: "Peripheral milling without Y"), or the holes of
// a hole cycle, drilled along X.
#include <cmath>

#include "interpreter/clock.h"
#include "interpreter/live_path.h"
#include "interpreter/milling_motion.h"
#include "interpreter/millturn.h"
#include "interpreter/statement_table.h"

namespace clpost {

namespace {

// A GOTO to `p` that is an XZ move at the C index, written as a lathe's move: the tool axis
// along X at Y 0 (the radial drill's approach), `p` at Y 0, C indexed (or X 0), a rapid or a
// feed per minute.
bool live_xz_move(const PostState& s, Point3 p) {
  if (std::fabs(axis_value(s.tool_axis.dir, third_axis(s))) > 1e-6 ||
      std::fabs(axis_value(s.tool_axis.dir, s.m.cl_axial)) > 1e-6)
    return false;
  if (std::fabs(axis_value(p, third_axis(s))) > 1e-4) return false;
  if (!s.c.angle && std::fabs(cl2(s, p).x) > 1e-4) return false;
  return s.rapid_next || s.feed_mode != FeedMode::kPerRev;
}

// The radial drill's approach along X at Y 0 (live_xz_move) from the +X side: a tool from the
// -X side is milling (C turns it to the turret's side). Without Y only a rapid at the C index on
// the tool's side of the centre line is that approach: the tool's other moves are milling in
// X Z C, the point giving C (docs/millturn.md, "Peripheral milling without Y").
bool xz_approach(const PostState& s, Point3 p) {
  return live_xz_move(s, p) && s.tool_axis.dir.x > 0 &&
         (s.m.y_axis || (s.rapid_next && c_at_index(s) && p.x > 0));
}

}  // namespace

void LiveRadialPath::go_to(PostState& s, const Statement& st, const Point3& p) {
  if (s.in_cycle) {  // a hole cycle's GOTOs are holes; a refused cycle's were reported at CYCLE/
    if (s.hole_cycle) hole(s, st, p);
    return;
  }
  if (xz_approach(s, p)) return lathe_goto(s, st, p);
  milling_goto(s, l_, st, p, true);
}

// Before the post's own Y 0: from where the CL left a radial tool (retracted sideways, along
// Y, at its cutting depth) Y 0 would go through the part. So X goes out first to the largest X
// a rapid of the section reached (the approach, trusted as clear: the CL brought the tool there),
// when the tool is below it. A face tool has no such step: its depth is Z, and X out at its Z
// would move it across the face. Its limit: that X is clear at the approach's Y and Z, not
// proven at Y 0.
void LiveRadialPath::retract(PostState& s) {
  const std::optional<LathePoint> at = s.prog.position();
  const std::optional<double> x = l_.mill.rapid_x;
  const double f = diameter_factor(s.m);
  if (!at || !x || !(at->r < *x) || s.prog.num("X", f * at->r) == s.prog.num("X", f * *x)) return;
  s.prog.writer().code(s.m.code("rapid")).word("X", f * *x).end_block();
  s.prog.cycle_ended_at(LathePoint{*x, at->z});
  time_rapid(s, Vec2{*x, at->z});
}

}  // namespace clpost

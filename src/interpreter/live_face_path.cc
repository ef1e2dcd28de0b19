// A live tool at the face (live_path.h, docs/millturn.md): its axis along the spindle's (0,0,1,
// or 0,0,-1 from the -Z side). Its GOTOs are milling in the face plane (polar interpolation where
// the machine asks for it), or the holes of a hole cycle, drilled along Z.
#include "interpreter/live_path.h"
#include "interpreter/milling_motion.h"

namespace clpost {

void LiveFacePath::go_to(PostState& s, const Statement& st, const Point3& p) {
  if (s.in_cycle) {  // a hole cycle's GOTOs are holes; a refused cycle's were reported at CYCLE/
    if (s.hole_cycle) hole(s, st, p);
    return;
  }
  milling_goto(s, l_, st, p, false);
}

}  // namespace clpost

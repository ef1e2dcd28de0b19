#pragma once
// The holes of a live (milling) tool (hole_live.cc, docs/millturn.md): where a hole cycle's GOTO
// is in the lathe frame when it is off the centre line, the C it needs, and the feed a live tool
// drills at.
#include "interpreter/hole_cycle.h"
#include "interpreter/post_state.h"

namespace clpost {

// Where the hole of a live tool at CL point `p` is: a face hole (tool axis along Z) at radius
// hypot(x, y), or a radial hole (tool axis through the centre line) at Z, both at C = the last
// ROTABL's index plus atan2(y, x). Sets h.radial, h.x or h.z, h.c, and `top` and `start` along
// the hole's axis (Z, or X as a radius). False (reported) when the machine cannot drill it or
// the CL does not say enough.
bool live_hole(PostState& s, const Statement& st, const HoleCycle& c, Point3 p, Hole& h,
               double& top, double& start);

// A feed per revolution of a live tool's hole, written per minute from the live tool's rpm
// (millturn.md section 3: a G99 feed with the main spindle stopped does not move); a comment
// says so. False (reported) when the live tool's rpm is not known.
bool live_feed_per_minute(PostState& s, const Statement& st, const HoleCycle& c, Hole& h);

// Moves C to hole `h`'s angle (h.c: the index plus the hole's own angle) when it is not there,
// and sets h.c to the C written. False (reported) when the c_index template cannot be written.
bool live_hole_c(PostState& s, const Statement& st, Hole& h);

}  // namespace clpost

#pragma once
// The holes of a live (milling) tool (hole_live.cc, docs/millturn.md): where a hole cycle's GOTO
// is in the lathe frame when it is off the centre line, the C it needs, and the feed a live tool
// drills at.
#include "interpreter/live_path.h"

namespace clpost {

// The GOTO of a live tool's hole at CL point `p` while a hole cycle is in force: a face hole
// (tool axis along Z) at radius hypot(x, y), or a radial hole (`radial`: the tool axis through
// the centre line) drilled along X at the hole's Z, both at C = the last ROTABL's index plus
// atan2(y, x); its feed per revolution is the live tool's (spindle `l.spindle`), written per
// minute. Reported when the machine cannot drill it or the CL does not say enough.
void live_hole(PostState& s, LiveState& l, const Statement& st, Point3 p, bool radial);

}  // namespace clpost

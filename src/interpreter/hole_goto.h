#pragma once
// The GOTO of a hole while a hole-making cycle is in force (hole_goto.cc), in steps a path takes
// in its own order: the turning path drills on the centre line (lathe_hole, statement_table.h),
// a live tool off it, at a C (hole_live.h).
#include "interpreter/post_state.h"

namespace clpost {

// Hole `h` of the cycle in force at `st`'s CL line: its kind, name and the tool's diameter.
void name_hole(PostState& s, const Statement& st, Hole& h);
// Its top (CL point `p`) and its start (where the tool is) along the spindle axis; false
// (reported) when the start is not known.
bool hole_start(PostState& s, const Statement& st, Point3 p, Hole& h);
// Its depths, pecks, dwell and feed (a tap's lead from the rpm of spindle `sp`); false
// (reported) when they cannot be written.
bool hole_depths(PostState& s, const Statement& st, const SpindleState& sp, Hole& h);
// Writes hole `h` at CL point `p` (a stopped main spindle turns first, as for every motion):
// the tool is then at the hole's retract plane.
void drill_hole(PostState& s, const Statement& st, Point3 p, Hole& h);

}  // namespace clpost

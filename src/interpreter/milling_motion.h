#pragma once
// The milling engine of the live paths (live_path.h, docs/millturn.md): GOTO, GODLTA, CIRCLE/,
// HELICAL/ and geometric motion of a milling tool outside a hole cycle. The CL point is in the
// part frame (Z the spindle axis, X/Y the face plane) turned by the C index (the last ROTABL): on
// a machine with Y it is written as X (diameter) Y Z in the face plane at that C, without Y as
// X, Z and C computed by the post (laws/xzc_law.h), or in the control's polar interpolation
// (milling_polar.h). `l` is the live paths' state; `radial`: the tool works across the axis
// (LiveRadialPath), else the face.
#include "interpreter/live_path.h"

namespace clpost {

// A GOTO (or GODLTA) of a milling tool to part point `p`.
void milling_goto(PostState& s, LiveState& l, const Statement& st, Point3 p, bool radial);
// CIRCLE/ `c` with a milling tool: the arc of the next GOTO, about an axis along Z.
void milling_circle(PostState& s, LiveState& l, const Statement& st, const Circle& c, bool radial);
// An arc of a milling tool from where it is to `end`, about `axis` through `center`, turning
// `sense` (+1 positively about the axis): HELICAL/ and geometric motion (milling_geometry.cc).
void milling_arc_to(PostState& s, LiveState& l, const Statement& st, Point3 center, Point3 axis,
                    int sense, Point3 end, bool radial);
// TLON,GOFWD/(CYLNDR/…),ON[,n,INTOF],(PLANE/…) of a milling tool (milling_geometry.cc).
void milling_go(PostState& s, LiveState& l, const Statement& st, bool radial);
// HELICAL/CENTER,…,INDIRV,…,AXIS,…,END,… (CATIA): an arc (a helix when END moves along the
// axis) from where the tool is to END, turning the way INDIRV starts it.
void milling_helical(PostState& s, LiveState& l, const Statement& st, bool radial);
// The plane code `plane` (17 plane_face, 18 plane_lathe, 19 plane_side) when another is in
// force.
void plane_code(PostState& s, LiveState& l, NcWriter& w, int plane);

}  // namespace clpost

#pragma once
// A live tool's milling motion (milling_motion.cc, docs/millturn.md): GOTO, GODLTA and CIRCLE/
// of a milling tool outside a hole cycle. The CL point is in the part frame (Z the spindle axis,
// X/Y the face plane) turned by the C index (the last ROTABL): on a machine with Y it is written
// as X (diameter) Y Z in the face plane at that C, without Y as X, Z and C computed by the post
// (laws/xzc_law.h).
#include "interpreter/post_state.h"

namespace clpost {

// A GOTO (or GODLTA) of a milling tool to part point `p`.
void milling_goto(PostState& s, const Statement& st, Point3 p);
// CIRCLE/ `c` with a milling tool: the arc of the next GOTO, about an axis along Z.
void milling_circle(PostState& s, const Statement& st, const Circle& c);
// An arc of a milling tool from where it is to `end`, about `axis` through `center`, turning
// `sense` (+1 positively about the axis): HELICAL/ and geometric motion (milling_geometry.cc).
void milling_arc_to(PostState& s, const Statement& st, Point3 center, Point3 axis, int sense,
                    Point3 end);
// TLON,GOFWD/(CYLNDR/…),ON[,n,INTOF],(PLANE/…) of a milling tool (milling_geometry.cc).
void milling_go(PostState& s, const Statement& st);
// HELICAL/ (CATIA) with a milling tool: an arc or a helix about any axis; without a milling
// tool the comment an unknown statement is.
void helical_stmt(PostState& s, const Statement& st);
// Before a hole or a tool change: Y back to 0 and the lathe plane after face milling in Y.
void end_milling(PostState& s);
// Before CUTCOM/LEFT|RIGHT of a milling tool on a machine with Y: the plane the compensation
// works in, G17 for a face tool, G19 for a radial one (a control refuses a plane change under
// G41/G42: docs/millturn.md).
void milling_comp_plane(PostState& s);

}  // namespace clpost

#pragma once
// Face milling on a lathe without Y (docs/millturn.md): a point of the part frame (Z the spindle
// axis, X/Y the face plane) turned by the C index is reached at radius hypot(x, y) and
// C = index + atan2(y, x). A straight part-frame line is not straight in X and C: it is split
// into pieces, each moving X, Z and C together (linearly, as the control interpolates them),
// whose chordal error from the line stays within a tolerance. Pure geometry: the interpreter
// writes the pieces (interpreter/milling_xzc.cc), verify maps X and C back.
#include <cstdint>
#include <vector>

namespace clpost {

// A point or a direction in 3-D, CL units: a CL point as read (before the lathe frame is
// applied), a point of the part frame (Z the spindle axis, X/Y the face plane), a tool axis.
struct Point3 {
  double x = 0, y = 0, z = 0;
};

// One straight piece of a live tool's milling in the part frame (CL units) and the C index it
// was milled at (degrees): what verify checks the program's X, Y, Z and C moves against
// (interpreter/milling_motion.cc, verify/mill_verify.h). An arc is its chords, each with the
// arc's CL line.
struct MillSegment {
  uint32_t line = 0;  // the CL line of the motion
  Point3 from, to;
  double index = 0;
  bool rapid = false;
};

// A point as the XZC machine reaches it: `r` the radius (>= 0), `c` the C angle in degrees as a
// continuous angle (unwrapped: the nearest to the C before it), `z`.
struct XzcPoint {
  double r = 0, c = 0, z = 0;
};

// One piece of a line: the machine moves linearly from the piece before to `to`. `length` is
// the part-frame length the piece covers (its share of the CL line): the feed is along it. A
// `flip` turns C alone at the centre line (r 0): the line crosses it, and C turns by about
// 180 degrees with the tool on the centre (nothing moves on the part).
struct XzcPiece {
  XzcPoint to;
  double length = 0;
  bool flip = false;
};

// The part point `p` at C index `index` (degrees), with C the nearest to `near` (degrees).
XzcPoint xzc_point(Point3 p, double index, double near);
// The part point the machine position `q` is at C index `index`.
Point3 part_point(XzcPoint q, double index);
// The part point (at C0) a machine position is at: X (a radius) and Y turned by C (degrees) about
// Z, the tool standing still while C turns the part. What verify and plot map a program's X, Y, Z
// and C back with (verify/mill_verify.h, plot/mill_views.h).
Point3 part_of_machine(double x, double y, double z, double c);

// The pieces of the straight part-frame line from `a` to `b` at C index `index`, the machine at
// C `c_from` at `a`, each within `tol` of the line (the distance, at the same fraction of the
// piece, between the machine's motion and the line: an upper bound of the chordal error). A
// line that passes within `tol` of the centre goes straight to the centre, flips C there, and
// goes straight out: never a spin of C at a tiny radius. Each piece turns C by at most 90
// degrees, so a rollover control's shortest way is the piece's way.
std::vector<XzcPiece> xzc_line(Point3 a, Point3 b, double index, double c_from, double tol);

// The largest distance between the machine's motion from `from` to `to` (linear in r, C, z) and
// the straight part-frame line between the points they are, sampled at `samples` fractions.
double xzc_deviation(XzcPoint from, XzcPoint to, double index, int samples = 16);

}  // namespace clpost

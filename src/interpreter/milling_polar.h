#pragma once
// Face milling in the control's polar interpolation (milling_polar.cc, docs/millturn.md "Polar
// interpolation"): Fanuc G12.1 / G13.1, Haas G112 / G113, as the machine file says them (codes
// polar_on, polar_off; millturn.polar_interpolation, polar_address, polar_x).
#include <string>

#include "interpreter/live_path.h"

namespace clpost {

// Whether a live tool's milling motion is written in polar interpolation: the machine asks for
// it and the tool works on the face (not `radial`).
bool polar_motion(const PostState& s, bool radial);
// What machine `m` does not say that polar interpolation needs (the keys, for an error); empty
// when it says everything.
std::string polar_missing(const Machine& m);
// The straight move from part point `from` to `to` (the part frame turned by C index `index`)
// in the mode, entered first; false (reported) when it is not written.
bool polar_line(PostState& s, LiveState& l, const Statement& st, Point3 from, Point3 to,
                double index, bool rapid, double feed);
// The arc about the spindle axis through part point `center` from `from` to `to`, turning
// counter-clockwise about +Z when `ccw`: G2/G3 in the mode; false (reported) when not written.
bool polar_arc(PostState& s, LiveState& l, const Statement& st, Point3 center, bool ccw,
               Point3 from, Point3 to, double index, double feed);
// Leaves the mode (codes.polar_off) when in it; C is then where the last move left it.
void polar_exit(PostState& s, LiveState& l);

}  // namespace clpost

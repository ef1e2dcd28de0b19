// Face milling in the control's polar interpolation (docs/millturn.md "Polar interpolation").
// The meanings, with their sources:
// - The mode makes X and the virtual axis a Cartesian plane across the spindle axis; its word is
//   the rotary axis's on Fanuc ("The axis address for the rotation axis is used as the axis
//   address for the second axis (virtual axis) in the plane", FANUC Series 15i/150i-MA
//   Operator's Manual B-63324EN/03, 4 "Polar coordinate interpolation"; Fusion's Takisawa/Fanuc
//   post, revision 42650, setPolarMode: yOutput prefix "C"), Y on Haas (Fusion's Haas lathe
//   post, FORKID {14D60AD3-4366-49dc-939C-4DB5EA48FF68} revision 41993, setPolarMode: G112, the
//   plane G17, Y enabled): millturn.polar_address.
// - The plane is fixed to C0: "Polar interpolation is started assuming the angle of 0 for the
//   position of the tool when G12.1 is specified" (the Fanuc manual above), and both Fusion
//   posts write "G0 C0" before the mode ("set C-axis to 0 to avoid G112 issues"). So C goes to 0
//   first and a part point p at index C is written as p turned by the index: the reading that
//   both agree on. C turns in the mode: it is unclamped.
// - X as a radius or a diameter in the mode: millturn.polar_x (the Haas post writes a radius,
//   `xFormat.setScale(1); // radius mode`; for Fanuc the sources disagree, see
//   machines/fanuc-0i-tf-live.yaml). The virtual axis and I, J are radii in both posts.
// - F: "Specify the feedrate as a speed (relative speed between the workpiece and tool)
//   tangential to the polar coordinate interpolation plane (Cartesian coordinate system) using
//   F", per minute (the Fanuc manual); the Haas post writes the CL's feed too.
// - Arcs (millturn.polar_arcs): G2/G3 with I and J in the plane ("I and J in the Xp-Yp plane
//   when the linear axis is the X-axis", the Fanuc manual), each at most 120 degrees (both
//   posts: maximumCircularSweep 120, "reduced sweep due to G112 support"); the Haas post
//   linearizes every arc in G112 (onCircular), so haas-st-20y writes chords
//   (milling_arc.cc, mill_arc).
// A feed move along Z and across the plane at once is an error: no source says how F is taken
// for it.
#include "interpreter/milling_polar.h"

#include <fmt/format.h>

#include <cmath>

#include "interpreter/clock.h"
#include "interpreter/milling_parts.h"
#include "interpreter/millturn.h"
#include "support/angles.h"

namespace clpost {

namespace {

// A point of the face plane at C0 (the mode's X and virtual axis, both radii).
struct FacePoint {
  double x = 0, y = 0;
};

// Part point `p` turned by C index `index` (degrees): where it is at C0.
FacePoint at_c0(Point3 p, double index) {
  const double a = radians(index), c = std::cos(a), n = std::sin(a);
  return {p.x * c - p.y * n, p.x * n + p.y * c};
}

// The words of a point in the mode: X (a radius or a diameter), the virtual axis, Z.
void point_words(const PostState& s, NcWriter& w, FacePoint p, double z) {
  const double x_factor = s.m.polar_x == PolarX::kDiameter ? 2 : 1;
  w.word("X", x_factor * p.x).word(s.m.polar_address, p.y).word("Z", z);
}

void moved_to(PostState& s, LiveState& l, FacePoint p, double z, bool rapid) {
  l.mill.polar_x = p.x;
  l.mill.polar_y = p.y;
  const double r = std::hypot(p.x, p.y);
  s.prog.cycle_ended_at(LathePoint{r, z});
  rapid ? time_rapid(s, Vec2{r, z}) : time_feed(s, Vec2{r, z});
}

// C to 0 (unclamped), code polar_on, plane_face when the machine has it. On a feed move the tool
// must be where C0 puts it: at `from` (turned by the index) on the plane's X axis.
bool enter(PostState& s, LiveState& l, const Statement& st, Point3 from, double index, bool rapid) {
  if (l.mill.polar) return true;
  if (l.mill.comp != CutterComp::kOff) {
    // G41/G42 are among the G codes of the mode (the Fanuc manual: "Polar coordinate
    // interpolation is applied to the path after cutter compensation"); what a compensation
    // started before the mode does across its start no source says.
    error(s, st, st.loc,
          "CUTCOM/LEFT or RIGHT in force where polar interpolation starts: start the "
          "compensation after the first motion in the mode (docs/millturn.md)");
    return false;
  }
  const bool cl_unclamped = s.c.cl_unclamped;
  s.c.cl_unclamped = true;  // no c_clamp after C0: C turns in the mode
  const bool ok = write_c_steps(s, st, c_steps(s.m, s.c.angle, 0, false, std::nullopt));
  s.c.cl_unclamped = cl_unclamped;
  if (!ok) return false;
  NcWriter& w = s.prog.writer();
  if (s.c.clamped) w.code(s.m.code("c_unclamp")).end_block();
  s.c.clamped = false;
  w.code(s.m.code("polar_on")).end_block();
  if (!s.m.code("plane_face").empty()) {
    w.code(s.m.code("plane_face")).end_block();
    l.mill.plane = 17;
  }
  s.prog.forget_modal();
  l.mill.polar = true;
  const double r = std::hypot(from.x, from.y);
  l.mill.polar_x = r;
  l.mill.polar_y = 0;
  const FacePoint f = at_c0(from, index);
  if (rapid || std::hypot(f.x - r, f.y) <= s.m.xzc_tolerance) return true;
  error(s, st, st.loc,
        "a feed move starts polar interpolation, and the C0 the mode starts at moves the tool "
        "off its start point: bring the tool to the start with a RAPID first (docs/millturn.md)");
  return false;
}

}  // namespace

bool polar_motion(const PostState& s, bool radial) {
  return s.m.polar_interpolation && !radial;
}

std::string polar_missing(const Machine& m) {
  if (m.code("polar_on").empty() || m.code("polar_off").empty())
    return "codes polar_on and polar_off (the mode's codes) are not both set";
  if (m.polar_address.empty())
    return "millturn.polar_address (the word of the virtual axis in the mode) is not set";
  if (m.polar_x == PolarX::kUnknown)
    return "millturn.polar_x is unknown: how the control takes X in the mode (a radius or a "
           "diameter) is not pinned; set it from the control's manual";
  return {};
}

bool polar_line(PostState& s, LiveState& l, const Statement& st, Point3 from, Point3 to,
                double index, bool rapid, double feed) {
  if (!enter(s, l, st, from, index, rapid)) return false;
  const FacePoint a{l.mill.polar_x, l.mill.polar_y}, b = at_c0(to, index);
  if (!rapid && std::abs(to.z - from.z) > 1e-9 && std::hypot(b.x - a.x, b.y - a.y) > 1e-9) {
    error(s, st, st.loc,
          "a feed move along Z and across the face at once in polar interpolation: how the "
          "control takes F for it is not known (F is the speed in the plane)");
    return false;
  }
  NcWriter& w = s.prog.writer();
  // A rapid as a G1 at millturn.polar_rapid_feed, on a control that takes no G0 in the mode.
  const bool g1 = !rapid || s.m.polar_rapid_feed > 0;
  if (g1) per_minute_code(s, l, w);
  w.code(s.m.code(g1 ? "linear" : "rapid"));
  point_words(s, w, b, to.z);
  if (g1) w.word("F", rapid ? s.m.polar_rapid_feed : feed);
  w.end_block();
  moved_to(s, l, b, to.z, rapid);
  return true;
}

bool polar_arc(PostState& s, LiveState& l, const Statement& st, Point3 center, bool ccw,
               Point3 from, Point3 to, double index, double feed) {
  if (std::abs(to.z - from.z) > 1e-9) {
    error(s, st, st.loc, "a helix in polar interpolation is not written (an arc at one Z is)");
    return false;
  }
  if (!enter(s, l, st, from, index, false)) return false;
  const FacePoint c = at_c0(center, index), a = at_c0(from, index), b = at_c0(to, index);
  const double a0 = std::atan2(a.y - c.y, a.x - c.x), r = std::hypot(a.x - c.x, a.y - c.y);
  double sweep = std::atan2(b.y - c.y, b.x - c.x) - a0;
  if (!ccw) sweep = -sweep;
  while (sweep <= 1e-9) sweep += 2 * kPi;
  const int n = static_cast<int>(std::ceil(sweep / (2 * kPi / 3) - 1e-9));
  NcWriter& w = s.prog.writer();
  FacePoint at = a;
  for (int k = 1; k <= n; ++k) {
    const double ang = a0 + (ccw ? 1 : -1) * sweep * k / n;
    const FacePoint e = k == n ? b : FacePoint{c.x + r * std::cos(ang), c.y + r * std::sin(ang)};
    per_minute_code(s, l, w);
    w.code(s.m.code(ccw ? "arc_ccw" : "arc_cw"));
    point_words(s, w, e, to.z);
    w.word("I", c.x - at.x).word("J", c.y - at.y).word("F", feed).end_block();
    moved_to(s, l, e, to.z, false);
    at = e;
  }
  return true;
}

void polar_exit(PostState& s, LiveState& l) {
  if (!l.mill.polar) return;
  s.prog.writer().code(s.m.code("polar_off")).end_block();
  s.prog.forget_modal();
  l.mill.polar = false;
  // C is at the angle of the tool's point in the plane (where it entered when on the centre).
  const double x = l.mill.polar_x, y = l.mill.polar_y;
  const double c = std::hypot(x, y) > 1e-9 ? degrees(std::atan2(y, x)) : 0;
  if (s.m.c_rotation == CRotation::kRollover)
    s.c.angle = c < 0 ? c + 360 : c;
  else
    s.c.angle.reset();  // a continuous C: which turn the control counts is not known
}

}  // namespace clpost

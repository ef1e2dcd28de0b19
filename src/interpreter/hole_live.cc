// The holes of a live tool (docs/millturn.md). The CL point is in the part frame turned by the
// C index (the last ROTABL): a hole at (x, y) is at radius hypot(x, y) and at C = index +
// atan2(y, x). Its tool axis (GOTO i,j,k) says how it is drilled: along Z (a face hole) or along
// a line through the centre line (a radial hole, drilled along X at the hole's Z). Holes are
// written in X, Z and C on every machine, also with a Y axis (Fusion's Haas post: several holes
// use XZC, reference/millturn.md section 2).
#include "interpreter/hole_live.h"

#include <fmt/format.h>

#include <algorithm>
#include <cmath>

#include "interpreter/hole_goto.h"
#include "interpreter/millturn.h"
#include "machine/machine_schema.h"
#include "support/angles.h"
#include "support/number_text.h"

namespace clpost {

namespace {

constexpr double kOnAxis = 1e-4;  // CL units: a hole within this of the centre line is on it

// The hole's position in the face plane (CL units): along the CL's radial axis and its third.
struct FacePoint {
  double x = 0, y = 0;
  double radius() const { return std::hypot(x, y); }
};

FacePoint face_point(const PostState& s, Point3 p) {
  return {axis_value(p, s.radial), axis_value(p, third_axis(s))};
}

// A CL length across the face as the lathe frame's radius (cl2's units).
double as_radius(const PostState& s, double v) {
  return s.m.cl_x_is_diameter ? v / 2 : v;
}

// A tap of a live tool is synchronised with the live spindle by the machine's own cycle: moves
// would reverse the main spindle, so a machine without the template refuses it.
template <typename Refuse>
bool live_tap_writable(const PostState& s, const SpindleState& live, bool radial,
                       const Refuse& refuse) {
  const bool left = live.dir == SpindleDir::kCcw;  // a left-hand tap: its own cycle
  const TemplateSpec& t = radial ? (left ? tmpl::kHoleRadialTapLeft : tmpl::kHoleRadialTap)
                                 : (left ? tmpl::kHoleLiveTapLeft : tmpl::kHoleLiveTap);
  auto it = s.m.templates.find(std::string(t.name));
  // An empty template would tap nothing, silently: it is no template here.
  if (it == s.m.templates.end() ||
      std::all_of(it->second.begin(), it->second.end(), [](const auto& l) { return l.empty(); }))
    return refuse(fmt::format(
        "machine '{}' has no template '{}': a live tool's tap is synchronised with the live "
        "spindle by the control's own cycle, never written as moves",
        s.m.name, t.name));
  return true;
}

// Where the hole of a live tool at CL point `p` is: a face hole (tool axis along Z) at radius
// hypot(x, y), or a radial hole (`radial`: the tool axis through the centre line) at Z, both at
// C = the last ROTABL's index plus atan2(y, x). Sets h.radial, h.x or h.z, h.c, and h.top and
// h.start along the hole's axis (Z, or X as a radius). False (reported) when the machine cannot
// drill it or the CL does not say enough.
bool place_hole(PostState& s, const LiveState& l, const Statement& st, Point3 p, bool radial,
                Hole& h) {
  const HoleCycle& c = *s.hole_cycle;
  const auto refuse = [&](std::string why) {
    error(s, st, st.loc,
          fmt::format("CYCLE/{} {} with live tool {}: {}", c.word, h.name, s.tool.number, why));
    return false;
  };
  const FacePoint at = face_point(s, p);
  const FacePoint axis = face_point(s, s.tool_axis.dir);
  h.radial = radial;
  if (h.radial && std::fabs(axis_value(s.tool_axis.dir, s.m.cl_axial)) > 1e-6)
    return refuse(fmt::format(
        "the tool axis of GOTO/{} is neither along Z (a face hole) nor across it (a radial hole)",
        st.text));
  if (h.radial && at.radius() <= kOnAxis)
    return refuse(
        "a radial hole (the tool axis across Z) at the centre line has no top to drill from");
  if (h.radial && std::fabs(at.x * axis.y - at.y * axis.x) > kOnAxis)
    return refuse(
        "the tool axis does not pass through the centre line: a radial hole is drilled toward "
        "it (an off-centre hole across the part needs Y, which is not written)");
  if (!s.m.face_holes && !h.radial)
    return refuse(fmt::format(
        "machine '{}' does not say how its control drills off the centre line "
        "(millturn.face_holes: false): no source gives its face drilling cycle at X with C "
        "(docs/millturn.md)",
        s.m.name));
  if (!s.c.index)
    return refuse("C is not indexed: a hole of a live tool needs ROTABL/…,CAXIS before it");
  if (c.kind == HoleKind::kTap && !live_tap_writable(s, l.spindle, h.radial, refuse)) return false;
  const double own = at.radius() > kOnAxis ? degrees(std::atan2(at.y, at.x)) : 0;
  h.c = *s.c.index + own;
  const Vec2 v = cl2(s, p);
  if (!h.radial) {
    h.x = as_radius(s, at.radius());
    h.top = v.z;
    h.start = cl2(s, *s.pos).z;
    return true;
  }
  // The tool stands on the machine's X axis while C turns the part under it: its start is its
  // distance from the centre line.
  h.z = v.z;
  h.top = as_radius(s, at.radius());
  h.start = as_radius(s, face_point(s, *s.pos).radius());
  return true;
}

// A feed per revolution of a live tool's hole, written per minute from the live tool's rpm
// (millturn.md section 3: a G99 feed with the main spindle stopped does not move); a comment
// says so. False (reported) when the live tool's rpm is not known.
bool live_feed_per_minute(PostState& s, const SpindleState& live, const Statement& st, Hole& h) {
  const HoleCycle& c = *s.hole_cycle;
  if (h.feed_mode != FeedMode::kPerRev) return true;
  if (!(live.on && !live.css && live.value > 0)) {
    error(s, st, st.loc,
          fmt::format("CYCLE/{} {} with live tool {}: a feed per revolution of the live tool "
                      "needs its speed (SPINDL/n,RPM before it) to be written per minute",
                      c.word, h.name, s.tool.number));
    return false;
  }
  const double per_rev = h.feed;
  h.feed = per_rev * live.value;
  h.feed_mode = FeedMode::kPerMinute;
  // Not "hole at …" first: that starts the hole's own comment, which verify reads.
  s.prog.comment(
      fmt::format("feed {} per revolution of the live tool x {} rpm = {} per minute "
                  "for the {}",
                  num_text(per_rev), num_text(live.value), num_text(h.feed), h.name));
  return true;
}

// Moves C to hole `h`'s angle (h.c: the index plus the hole's own angle) when it is not there,
// and sets h.c to the C written. False (reported) when the c_index template cannot be written.
bool live_hole_c(PostState& s, const Statement& st, Hole& h) {
  if (!h.c) return true;
  if (!write_c_steps(s, st, c_steps(s.m, s.c.angle, *h.c, false, std::nullopt))) return false;
  h.c = s.c.angle;
  return true;
}

}  // namespace

void live_hole(PostState& s, LiveState& l, const Statement& st, Point3 p, bool radial) {
  Hole h;
  name_hole(s, st, h);
  if (!hole_start(s, st, p, h) || !place_hole(s, l, st, p, radial, h) ||
      !hole_depths(s, st, l.spindle, h))
    return;
  // A live tool's tap has no moves to fall back to: its cycle fits, or it is an error.
  if (h.kind == HoleKind::kTap)
    if (std::string why = hole_misfit(s.m, h); !why.empty())
      return error(s, st, st.loc,
                   fmt::format("CYCLE/TAP {} with live tool {}: {}", h.name, s.tool.number, why));
  ensure_started(s);
  if (!live_feed_per_minute(s, l.spindle, st, h) || !live_hole_c(s, st, h)) return;
  drill_hole(s, st, p, h);
}

}  // namespace clpost

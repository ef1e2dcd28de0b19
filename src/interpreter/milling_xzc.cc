// A live tool's milling without Y (docs/millturn.md): X, Z and C computed by the post from the
// part-frame line (laws/xzc_law.h), split within millturn.xzc_tolerance, its feed written so that
// the tool moves along the part at the CL's feed (millturn.xzc_feed).
#include <cmath>

#include "interpreter/clock.h"
#include "interpreter/milling_parts.h"
#include "interpreter/millturn.h"

namespace clpost {

namespace {

// One XZC piece from `from`: a rapid, or a feed move whose F makes the tool move along the
// part at `feed` per minute. A piece that does not turn C is the lathe's own move (G94 F is
// exact along X and Z).
void xzc_block(PostState& s, LiveState& l, XzcPoint from, const XzcPiece& pc, bool rapid,
               double feed) {
  const std::vector<double> steps = c_steps(s.m, s.c.angle, pc.to.c, false, std::nullopt);
  const LathePoint to{pc.to.r, pc.to.z};
  if (steps.empty()) {
    if (rapid) return s.prog.rapid(to);
    s.prog.set_feed(feed, FeedMode::kPerMinute);
    s.prog.linear(to);
    l.mill.inverse_time = false;
    l.mill.per_minute = true;
    return;
  }
  if (s.c.clamped) {
    s.prog.writer().code(s.m.code("c_unclamp")).end_block();
    s.c.clamped = false;
  }
  NcWriter& w = s.prog.writer();
  const double dc = pc.to.c - from.c;
  if (rapid) {
    w.code(s.m.code("rapid"));
  } else if (s.m.xzc_inverse_time) {
    if (!l.mill.inverse_time) w.code(s.m.code("inverse_time"));
    l.mill.inverse_time = true;
    w.code(s.m.code("linear"));
  } else {
    per_minute_code(s, l, w);
    w.code(s.m.code("linear"));
  }
  w.word("X", diameter_factor(s.m) * to.r).word("Z", to.z).word(s.m.c_address, steps.back());
  if (!rapid) {
    const double dr = pc.to.r - from.r, dz = pc.to.z - from.z;
    const double machine = std::sqrt(dr * dr + dz * dz + dc * dc);
    // Inverse time: the piece takes length / feed minutes (a flip on the centre: C at the feed
    // read as degrees per minute). Combined: F over the X, Z and C move in the same time.
    const double minutes = pc.length > 0 ? pc.length / feed : std::abs(dc) / feed;
    w.word("F", s.m.xzc_inverse_time ? 1 / minutes : machine / minutes);
  }
  w.end_block();
  s.c.angle = steps.back();
  s.prog.cycle_ended_at(to);  // X and Z as written here; the lathe's modal words forgotten
}

}  // namespace

void xzc_move(PostState& s, LiveState& l, Point3 from, Point3 to, double index, bool rapid,
              double feed, double tol) {
  const double c0 = *s.c.angle;
  std::vector<XzcPiece> pieces;
  if (rapid) {
    pieces.push_back({xzc_point(to, index, c0), 0, false});  // the control's own path
  } else {
    pieces = xzc_line(from, to, index, c0, tol);
  }
  XzcPoint at = xzc_point(from, index, c0);
  at.c = c0;
  for (const XzcPiece& pc : pieces) {
    xzc_block(s, l, at, pc, rapid, feed);
    rapid ? time_rapid(s, Vec2{pc.to.r, pc.to.z}) : time_feed(s, Vec2{pc.to.r, pc.to.z});
    at = pc.to;
  }
}

void xzc_plane(PostState& s, LiveState& l, bool radial) {
  const int plane = radial ? 19 : 18;
  if (l.mill.plane == plane || s.m.code(radial ? "plane_side" : "plane_lathe").empty()) return;
  plane_code(s, l, s.prog.writer(), plane);
}

}  // namespace clpost

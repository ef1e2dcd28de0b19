// The GOTO of a hole while a hole-making cycle is in force (hole_cycles.cc): checked (on the
// centre line, a known start, a feed; a tap's feed equal to its lead × rpm) and written
// (emitters/hole_output.h).
#include <fmt/format.h>

#include <cmath>

#include "emitters/hole_output.h"
#include "interpreter/hole_live.h"
#include "interpreter/statement_table.h"
#include "support/number_text.h"

namespace clpost {

namespace {

// The tap's lead per revolution, checked against its feed; nullopt (reported) when it is wrong.
std::optional<double> tap_lead(PostState& s, const Statement& st, const HoleCycle& c, double feed,
                               FeedMode mode, double rpm) {
  const double from_feed = mode == FeedMode::kPerRev ? feed : feed / rpm;
  if (!c.lead) return from_feed;
  if (!c.feed) return *c.lead;  // the feed follows the lead
  const double want = mode == FeedMode::kPerRev ? *c.lead : *c.lead * rpm;
  if (std::fabs(feed - want) <= 1e-4 * want) return *c.lead;
  error(
      s, st, st.loc,
      mode == FeedMode::kPerRev
          ? fmt::format("CYCLE/TAP of line {}: feed {} per revolution is not the tap's lead "
                        "{}: the tap would strip the thread",
                        c.line, num_text(feed), num_text(*c.lead))
          : fmt::format("CYCLE/TAP of line {}: feed {} per minute is not the tap's lead {} x "
                        "{} rpm = {}: the tap would strip the thread",
                        c.line, num_text(feed), num_text(*c.lead), num_text(rpm), num_text(want)));
  return std::nullopt;
}

// Feed, lead and speed of hole `h` from the cycle and the modal state; false (reported).
bool hole_feed(PostState& s, const Statement& st, const HoleCycle& c, Hole& h) {
  if (!c.feed && !s.feed_given && !(c.kind == HoleKind::kTap && c.lead)) {
    error(s, st, st.loc,
          fmt::format("CYCLE/{} of line {} has no feed: give one in the cycle (MMPM, IPM, MMPR, "
                      "IPR) or a FEDRAT/ before it",
                      c.word, c.line));
    return false;
  }
  h.feed = c.feed.value_or(s.feed);
  h.feed_mode = c.feed ? c.feed_mode : s.feed_mode;
  const SpindleState& sp = s.tool.mills() ? s.live : s.spindle;  // a live tool: its own
  h.rpm = sp.on && !sp.css ? sp.value : 0;
  h.spindle = sp.dir;
  if (c.dwell_revs && *c.dwell_revs > 0) {
    if (!(h.rpm > 0)) {
      error(s, st, st.loc,
            fmt::format("CYCLE/{} of line {} dwells {} revolutions (REV): the spindle must turn "
                        "at a set RPM (SPINDL/n,RPM) to write the dwell in seconds",
                        c.word, c.line, num_text(*c.dwell_revs)));
      return false;
    }
    h.dwell = *c.dwell_revs * 60 / h.rpm;
  }
  if (c.kind != HoleKind::kTap) return true;
  if (c.invers && h.spindle != SpindleDir::kCcw) {
    error(s, st, st.loc,
          fmt::format("CYCLE/TAP of line {} is INVERS (a left-hand tap) but the spindle turns "
                      "clockwise here",
                      c.line));
    return false;
  }
  if (!(h.rpm > 0)) {
    error(s, st, st.loc,
          fmt::format("CYCLE/TAP of line {} needs the spindle turning at a set RPM (SPINDL/n,RPM "
                      "before it): a tap's feed is its lead per revolution",
                      c.line));
    return false;
  }
  const std::optional<double> lead = tap_lead(s, st, c, h.feed, h.feed_mode, h.rpm);
  if (!lead) return false;
  h.lead = h.feed = *lead;
  h.feed_mode = FeedMode::kPerRev;
  return true;
}

// The hole at CL point `p`; false (reported) when it cannot be drilled on a lathe.
bool make_hole(PostState& s, const Statement& st, Point3 p, Hole& h) {
  const HoleCycle& c = *s.hole_cycle;
  const Vec2 v = cl2(s, p);
  const double radius = std::hypot(v.x, axis_value(p, third_axis(s)));
  h.kind = c.kind;
  h.cl_line = st.loc.line;
  h.name = fmt::format("hole at CL line {}", st.loc.line);
  h.tool_diameter = s.tool.diameter;
  if (!s.tool.mills() && radius > 1e-4) {
    error(s, st, st.loc,
          fmt::format("CYCLE/{} {} is {} off the spindle's centre line (GOTO/{}): a hole off "
                      "the centre line needs live tooling, which a lathe post does not write",
                      c.word, h.name, num_text(radius), st.text));
    return false;
  }
  if (!s.pos) {
    error(s, st, st.loc,
          fmt::format("CYCLE/{} {}: the tool's start is unknown (no GOTO or FROM before it)",
                      c.word, h.name));
    return false;
  }
  h.start = cl2(s, *s.pos).z;
  h.top = v.z;
  if (s.tool.mills() && !live_hole(s, st, c, p, h, h.top, h.start)) return false;
  h.dir = h.start >= h.top ? -1 : 1;
  h.bottom = h.top + h.dir * c.depth;
  h.r = c.clearance ? h.top - h.dir * *c.clearance : h.start;
  h.retract = c.retract ? h.top - h.dir * *c.retract : h.start;
  h.first_peck = c.first_peck;
  h.peck = c.kind == HoleKind::kDeep || c.kind == HoleKind::kChipBreak ? c.peck : 0;
  h.dwell = c.dwell;
  h.backoff = c.backoff;
  const double pecks = h.peck > 0 ? std::ceil(std::fabs(h.bottom - h.r) / h.peck) : 1;
  if (pecks > static_cast<double>(kMaxHolePecks)) {
    error(s, st, st.loc,
          fmt::format("CYCLE/{} {}: pecks of {} over {} make {} pecks, more than {}", c.word,
                      h.name, num_text(h.peck), num_text(std::fabs(h.bottom - h.r)),
                      num_text(pecks), kMaxHolePecks));
    return false;
  }
  return hole_feed(s, st, c, h);
}

double& axis_ref(Point3& p, ClAxis a) {
  return a == ClAxis::kX ? p.x : a == ClAxis::kY ? p.y : p.z;
}

// Where the tool is after hole `h` at CL point `p`: at its retract plane on the hole's axis, in
// the CL frame (a hole off the X axis keeps its Y).
Point3 hole_exit_point(const PostState& s, Point3 p, const Hole& h) {
  if (!h.radial) {
    Point3 q = cl_point(s, Vec2{cl2(s, p).x, h.retract});
    axis_ref(q, third_axis(s)) = axis_value(p, third_axis(s));
    return q;
  }
  const double k = h.retract / h.top;  // along the hole's radial line
  axis_ref(p, s.radial) *= k;
  axis_ref(p, third_axis(s)) *= k;
  return p;
}

}  // namespace

void hole_goto(PostState& s, const Statement& st, Point3 p) {
  Hole h;
  if (!make_hole(s, st, p, h)) return;
  // A live tool's tap has no moves to fall back to (hole_live.cc): its cycle fits, or it is an
  // error.
  if (s.tool.mills() && h.kind == HoleKind::kTap)
    if (std::string why = hole_misfit(s.m, h); !why.empty()) {
      error(s, st, st.loc,
            fmt::format("CYCLE/TAP {} with live tool {}: {}", h.name, s.tool.number, why));
      return;
    }
  ensure_started(s);
  if (s.tool.mills() && (!live_feed_per_minute(s, st, *s.hole_cycle, h) || !live_hole_c(s, st, h)))
    return;
  restart_stopped_spindle(s, st);
  ++s.stats.motions;
  const SavedLines lines = SavedLines::of(st);
  const bool r = write_hole(
      s.prog, h, EmitContext{.diags = s.diags, .lines = lines, .loc = st.loc, .used = &s.outputs});
  time_hole(s, h);
  if (s.feed_given) s.prog.set_feed(s.feed, s.feed_mode);
  s.pos = hole_exit_point(s, p, h);
  // The hole leaves the tool at its retract plane: a rapid there, as verify sees it.
  if (r && h.radial) record_exit(s, st.loc.line, Vec2{h.retract, h.z});
  if (r && !h.radial) record_exit(s, st.loc.line, Vec2{h.x, h.retract}, h.bottom);
  if (r) s.holes.push_back(std::move(h));
  s.rapid_next = false;
}

}  // namespace clpost

// The GOTO of a hole while a hole-making cycle is in force (hole_cycles.cc): checked (on the
// centre line, a known start, a feed; a tap's feed equal to its lead × rpm) and written
// (emitters/hole_output.h).
#include <fmt/format.h>

#include <cmath>

#include "emitters/hole_output.h"
#include "interpreter/hole_goto.h"
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

// Feed, lead and speed of hole `h` from the cycle, the modal state and spindle `sp`; false
// (reported).
bool hole_feed(PostState& s, const Statement& st, const HoleCycle& c, const SpindleState& sp,
               Hole& h) {
  if (!c.feed && !s.feed_given && !(c.kind == HoleKind::kTap && c.lead)) {
    error(s, st, st.loc,
          fmt::format("CYCLE/{} of line {} has no feed: give one in the cycle (MMPM, IPM, MMPR, "
                      "IPR) or a FEDRAT/ before it",
                      c.word, c.line));
    return false;
  }
  h.feed = c.feed.value_or(s.feed);
  h.feed_mode = c.feed ? c.feed_mode : s.feed_mode;
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

void name_hole(PostState& s, const Statement& st, Hole& h) {
  h.kind = s.hole_cycle->kind;
  h.cl_line = st.loc.line;
  h.name = fmt::format("hole at CL line {}", st.loc.line);
  h.tool_diameter = s.tool.diameter;
}

bool hole_start(PostState& s, const Statement& st, Point3 p, Hole& h) {
  if (!s.pos) {
    error(s, st, st.loc,
          fmt::format("CYCLE/{} {}: the tool's start is unknown (no GOTO or FROM before it)",
                      s.hole_cycle->word, h.name));
    return false;
  }
  h.start = cl2(s, *s.pos).z;
  h.top = cl2(s, p).z;
  return true;
}

bool hole_depths(PostState& s, const Statement& st, const SpindleState& sp, Hole& h) {
  const HoleCycle& c = *s.hole_cycle;
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
  return hole_feed(s, st, c, sp, h);
}

void drill_hole(PostState& s, const Statement& st, Point3 p, Hole& h) {
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

void lathe_hole(PostState& s, const Statement& st, Point3 p) {
  Hole h;
  name_hole(s, st, h);
  const double radius = std::hypot(cl2(s, p).x, axis_value(p, third_axis(s)));
  if (radius > 1e-4) {
    error(s, st, st.loc,
          fmt::format("CYCLE/{} {} is {} off the spindle's centre line (GOTO/{}): a hole off "
                      "the centre line needs live tooling, which a lathe post does not write",
                      s.hole_cycle->word, h.name, num_text(radius), st.text));
    return;
  }
  if (!hole_start(s, st, p, h) || !hole_depths(s, st, s.spindle, h)) return;
  ensure_started(s);
  drill_hole(s, st, p, h);
}

}  // namespace clpost

#pragma once
// The cycle-time clock's hooks (cycle_time.h says how each move is timed): the statement handlers
// call them as the program moves, in the lathe frame, CL units, each from where the clock's tool
// is (PostState::clock_at) to where the move ends. The straight feed move, which every GOTO of a
// turning program is, is timed inline; everything else in cycle_time.cc.
#include <algorithm>
#include <cmath>

#include "interpreter/cycle_time.h"
#include "interpreter/post_state.h"

namespace clpost {

void time_tool_change(PostState& s);
void time_rapid(PostState& s, Vec2 to);
void time_arc(PostState& s, Vec2 to, Vec2 center, bool ccw);
void time_dwell(PostState& s, double seconds);
void time_thread(PostState& s, const ThreadPlan& plan, double rpm);
void time_sync(PostState& s, Vec2 to, double lead, double rpm);
void time_hole(PostState& s, const Hole& h);
// C turning `degrees` (at time.rapid_c) with `clamp_codes` C clamp or unclamp codes written.
void time_c(PostState& s, double degrees, int clamp_codes);

// The tool `t` reaches `p` after `seconds` more: its time and the extremes it reaches.
inline void reach(ToolTime& t, Vec2 p, double seconds) {
  t.seconds += seconds;
  t.x_min = std::min(t.x_min, p.x);
  t.x_max = std::max(t.x_max, p.x);
  t.z_min = std::min(t.z_min, p.z);
  t.z_max = std::max(t.z_max, p.z);
}

// The length of the straight move a -> b. sqrt rather than hypot: every GOTO comes here, and CL
// values are far from overflow.
inline double move_length(Vec2 a, Vec2 b) {
  const double dx = b.x - a.x, dz = b.z - a.z;
  return std::sqrt(dx * dx + dz * dz);
}

// The feed in force as a length per minute, for straight feed moves (PostState::clock_feed):
// the feed per minute, or per revolution times the rpm; -1 when it is not that simple (no feed
// or no speed yet, or constant surface speed, whose rpm changes with the radius): then every
// move is worked out in full. Whatever changes PostState::feed, feed_mode or spindle calls it
// (FEDRAT and SPINDL, spindle_feed.cc), or the next moves are timed at the old feed.
void time_feed_rate(PostState& s);

// A feed move to `to` at the feed in force, in full (cycle_time.cc).
void time_feed_move(PostState& s, Vec2 to);
// The feed and speed in force join the clock tool's lists (ToolTime::feeds, speeds); the fast
// path below calls it once after each change of feed, speed or tool (clock_feed_noted).
void note_feed_used(PostState& s);
// The last tool's NC lines end at the lines written so far (the end of the program).
void end_nc_lines(PostState& s);

// A feed move to `to` at the feed in force. The common one inline (every GOTO of a turning
// program): the clock knows where its tool is, the tool list has begun and the feed per minute
// is known; the same minutes as feed_minutes() in cycle_time.cc gives, length / feed.
inline void time_feed(PostState& s, Vec2 to) {
  std::vector<ToolTime>& tools = s.clock.tools;
  const double feed = s.clock_feed;
  if (!s.clock_at || tools.empty() || !(feed > 0)) return time_feed_move(s, to);
  if (!s.clock_feed_noted) [[unlikely]]
    note_feed_used(s);
  const double seconds = 60 * (move_length(*s.clock_at, to) / feed);
  reach(tools.back(), to, seconds);
  tools.back().cutting_seconds += seconds;
  s.clock_at = to;
}

}  // namespace clpost

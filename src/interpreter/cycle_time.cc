// The cycle-time clock (cycle_time.h, its hooks in clock.h): every hook moves the clock's tool
// from where it is.
#include "interpreter/cycle_time.h"

#include <fmt/format.h>

#include <algorithm>
#include <cmath>
#include <numbers>

#include "interpreter/clock.h"
#include "interpreter/post_state.h"

namespace clpost {

namespace {

// The first move before any tool change starts the list (rare: out of line).
[[gnu::noinline]] void first_entry(CycleTime& c) {
  c.tools.emplace_back();
}

// The tool the clock times. Its data (text, nose radius) came with its change
// (time_tool_change): tool data words describe the next tool (ToolInfo, next_tool), never the one
// in use, so a move has nothing to take.
ToolTime& current(PostState& s) {
  CycleTime& c = s.clock;
  if (c.tools.empty()) [[unlikely]]
    first_entry(c);
  return c.tools.back();
}

// The tool reaches `p` after `seconds` more (one look-up of the tool per move).
void arrive(PostState& s, Vec2 p, double seconds = 0) {
  reach(current(s), p, seconds);
  s.clock_at = p;
}

void add(PostState& s, double seconds) {
  current(s).seconds += seconds;
}

template <class T>
void add_once(std::vector<T>& v, const T& x) {
  if (std::find(v.begin(), v.end(), x) == v.end()) v.push_back(x);
}

// A cutting move to `p` after `seconds`, at feed `f` (in `mode`) and the spindle speed `speed`.
void cut_to(PostState& s, Vec2 p, double seconds, FeedUsed f, SpeedUsed speed) {
  ToolTime& t = current(s);
  reach(t, p, seconds);
  t.cutting_seconds += seconds;
  if (f.value > 0) add_once(t.feeds, f);
  if (speed.value > 0) add_once(t.speeds, speed);
  s.clock_at = p;
}

SpeedUsed speed_in_force(const PostState& s) {
  return s.spindle.on ? SpeedUsed{s.spindle.value, s.spindle.css} : SpeedUsed{};
}

// Minutes to feed `length` along radii r0 .. r1 (linearly) at feed `f` per revolution under
// constant surface speed: rpm(r) = K / (2 pi r), clamped at the limit below the radius rc.
double css_minutes(const PostState& s, double length, double r0, double r1, double f) {
  const SpindleState& sp = s.spindle;
  const double k = sp.value * (s.units == LengthUnit::kInch ? 12 : 1000);
  const double max = sp.css_max_rpm > 0 ? sp.css_max_rpm : s.m.max_rpm;
  const double rc = max > 0 ? k / (2 * std::numbers::pi * max) : 0;
  r0 = std::fabs(r0), r1 = std::fabs(r1);
  auto piece = [&](double ua, double ub) {  // [ua, ub] on one side of rc
    const double r = r0 + (r1 - r0) * (ua + ub) / 2;
    const double ds = length * (ub - ua);
    return r >= rc ? 2 * std::numbers::pi * r * ds / (f * k) : ds / (f * max);
  };
  if ((r0 - rc) * (r1 - rc) < 0) {
    const double uc = (rc - r0) / (r1 - r0);
    return piece(0, uc) + piece(uc, 1);
  }
  return piece(0, 1);
}

// Minutes to feed `length` along radii r0 .. r1 (linearly) at feed `f` in `mode`.
double feed_minutes(const PostState& s, double length, double r0, double r1, double f,
                    FeedMode mode) {
  if (!(f > 0) || length <= 0) return 0;
  if (mode == FeedMode::kPerMinute) return length / f;
  const SpindleState& sp = s.spindle;
  if (!sp.css) return sp.value > 0 ? length / (f * sp.value) : 0;
  return css_minutes(s, length, r0, r1, f);
}

// A feed move from where the clock is to `to` at feed `f`.
void feed_to(PostState& s, Vec2 to, double f, FeedMode mode) {
  double seconds = 0;
  if (s.clock_at) {
    const Vec2 a = *s.clock_at;
    seconds = 60 * feed_minutes(s, move_length(a, to), a.x, to.x, f, mode);
  }
  cut_to(s, to, seconds, FeedUsed{f, mode}, speed_in_force(s));
}

}  // namespace

void time_tool_change(PostState& s) {
  const size_t written = s.prog.writer().lines();
  if (!s.clock.tools.empty()) s.clock.tools.back().last_nc_line = written;
  ToolTime t;
  t.first_nc_line = written + 1;
  t.tool = s.tool.number;
  t.offset = s.tool.offset;
  t.line = s.tool_line;
  t.text = s.tool.text;
  t.nose_radius = s.tool.nose_radius;
  t.seconds = s.m.tool_change_time;
  s.clock.tools.push_back(std::move(t));
}

void time_rapid(PostState& s, Vec2 to) {
  double seconds = 0;
  if (s.clock_at) {
    const double dx = std::fabs(to.x - s.clock_at->x), dz = std::fabs(to.z - s.clock_at->z);
    const double rx = s.m.rapid_x, rz = s.m.rapid_z;
    if ((dx > 0 && rx <= 0) || (dz > 0 && rz <= 0)) s.clock.rapids_untimed = true;
    seconds = 60 * std::max(rx > 0 ? dx / rx : 0, rz > 0 ? dz / rz : 0);
  }
  arrive(s, to, seconds);
}

void time_feed_rate(PostState& s) {
  const double f = s.feed, rpm = s.spindle.value;
  s.clock_feed = -1;
  s.clock_feed_noted = false;
  if (!(f > 0)) return;
  if (s.feed_mode == FeedMode::kPerMinute) {
    s.clock_feed = f;
  } else if (!s.spindle.css && rpm > 0 && f * rpm > 0) {  // (a product below the smallest
    s.clock_feed = f * rpm;                               // double is worked out in full)
  }
}

void time_feed_move(PostState& s, Vec2 to) {
  feed_to(s, to, s.feed, s.feed_mode);
}

void note_feed_used(PostState& s) {
  ToolTime& t = current(s);
  if (s.feed > 0) add_once(t.feeds, FeedUsed{s.feed, s.feed_mode});
  if (const SpeedUsed sp = speed_in_force(s); sp.value > 0) add_once(t.speeds, sp);
  s.clock_feed_noted = true;
}

void end_nc_lines(PostState& s) {
  if (!s.clock.tools.empty()) s.clock.tools.back().last_nc_line = s.prog.writer().lines();
}

void time_arc(PostState& s, Vec2 to, Vec2 center, bool ccw) {
  if (!s.clock_at) return arrive(s, to);
  const Vec2 a = *s.clock_at;
  const double r = move_length(center, a);
  const double t0 = std::atan2(a.x - center.x, a.z - center.z);
  double sweep = std::atan2(to.x - center.x, to.z - center.z) - t0;
  // Positive rotation turns Z toward X (G3 in G18 with the lathe frame as drawn).
  if (ccw && sweep <= 0) sweep += 2 * std::numbers::pi;
  if (!ccw && sweep >= 0) sweep -= 2 * std::numbers::pi;
  constexpr int kSteps = 64;
  double minutes = 0;
  for (int i = 0; i < kSteps; ++i) {
    const double u = t0 + sweep * (i + 0.5) / kSteps;
    const double rad = center.x + r * std::sin(u);
    minutes += feed_minutes(s, r * std::fabs(sweep) / kSteps, rad, rad, s.feed, s.feed_mode);
  }
  cut_to(s, to, 60 * minutes, FeedUsed{s.feed, s.feed_mode}, speed_in_force(s));
}

void time_dwell(PostState& s, double seconds) {
  add(s, seconds);
}

void time_c(PostState& s, double degrees, int clamp_codes) {
  if (degrees > 0 && !(s.m.rapid_c > 0)) s.clock.c_untimed = true;
  add(s, (s.m.rapid_c > 0 ? 60 * degrees / s.m.rapid_c : 0) + clamp_codes * s.m.c_clamp_time);
}

void time_sync(PostState& s, Vec2 to, double lead, double rpm) {
  if (s.clock_at && lead > 0 && rpm > 0) {
    const double travel =
        std::max(std::fabs(to.x - s.clock_at->x), std::fabs(to.z - s.clock_at->z));
    return cut_to(s, to, 60 * travel / (lead * rpm), FeedUsed{lead, FeedMode::kPerRev},
                  SpeedUsed{rpm, false});
  }
  arrive(s, to);
}

void time_thread(PostState& s, const ThreadPlan& plan, double rpm) {
  for (const ThreadPass& p : plan.passes) {
    time_rapid(s, p.approach);
    time_rapid(s, p.from);
    time_sync(s, p.to, plan.lead, rpm);
    if (plan.pullout) time_sync(s, p.pullout_end, plan.lead, rpm);
    time_rapid(s, p.clear);
  }
  time_rapid(s, plan.end_position);
}

void time_hole(PostState& s, const Hole& h) {
  // Along the hole's axis: Z at its X (0 on the centre line), or X at its Z (a radial hole).
  const auto at = [&](double v) { return h.radial ? Vec2{v, h.z} : Vec2{h.x, v}; };
  if (s.clock_at && !h.radial && std::fabs(s.clock_at->x - h.x) > 0)
    time_rapid(s, {h.x, s.clock_at->z});
  if (s.clock_at && h.radial && std::fabs(s.clock_at->z - h.z) > 0)
    time_rapid(s, {s.clock_at->x, h.z});
  time_rapid(s, at(h.r));
  const std::vector<double> ends = hole_feed_ends(h);
  const double clr = s.m.peck_clearance;
  for (size_t i = 0; i < ends.size(); ++i) {
    feed_to(s, at(ends[i]), h.feed, h.feed_mode);
    if (i + 1 == ends.size()) break;
    if (h.kind == HoleKind::kDeep) time_rapid(s, at(h.r));
    const double back = h.kind == HoleKind::kDeep ? clr : chip_backoff(h, clr);
    time_rapid(s, at(h.r + h.dir * std::max(0.0, std::fabs(ends[i] - h.r) - back)));
  }
  time_dwell(s, h.dwell);
  if (h.kind == HoleKind::kTap || h.kind == HoleKind::kBore || h.kind == HoleKind::kReam)
    feed_to(s, at(h.r), h.feed, h.feed_mode);
  time_rapid(s, at(h.retract));
}

std::string untimed_note(const CycleTime& t) {
  std::string out = t.rapids_untimed ? "; rapids not timed: no time.rapid_x/rapid_z" : "";
  if (t.c_untimed) out += "; C moves not timed: no time.rapid_c";
  return out;
}

std::string time_text(double seconds) {
  constexpr double kLongest = 1e6 * 3600;  // a million hours: past it the text says "over"
  if (std::isnan(seconds)) return "not known";
  if (seconds >= kLongest) return "over 1000000:00:00";
  const double tenths = std::round(std::max(0.0, seconds) * 10);
  const long long whole = static_cast<long long>(tenths) / 10;
  const int frac = static_cast<int>(static_cast<long long>(tenths) % 10);
  const long long h = whole / 3600, m = whole / 60 % 60, sec = whole % 60;
  if (h > 0) return fmt::format("{}:{:02}:{:02}.{}", h, m, sec, frac);
  return fmt::format("{}:{:02}.{}", m, sec, frac);
}

bool listed(const ToolTime& t) {
  return !(t.tool < 0 && t.seconds == 0 && t.x_min > t.x_max);
}

void shift_nc_lines(CycleTime& t, size_t lines) {
  for (ToolTime& tt : t.tools) {
    if (tt.first_nc_line > 0) tt.first_nc_line += lines;
    if (tt.last_nc_line > 0) tt.last_nc_line += lines;
  }
}

std::vector<std::string> cycle_time_lines(const CycleTime& t, LengthUnit units, bool diameter) {
  std::vector<std::string> out;
  const char* u = units == LengthUnit::kInch ? "in" : "mm";
  const double xs = diameter_factor(diameter);
  size_t changes = 0;
  for (const ToolTime& tt : t.tools) {
    if (!listed(tt)) continue;
    changes += tt.tool >= 0;
    std::string line = tt.tool < 0 ? std::string("before the first tool")
                                   : fmt::format("T{} offset {}", tt.tool, tt.offset);
    line += fmt::format(": {}", time_text(tt.seconds));
    if (tt.x_min <= tt.x_max)
      line += fmt::format(", X{:.3f} to X{:.3f}, Z{:.3f} to Z{:.3f} {}", tt.x_min * xs,
                          tt.x_max * xs, tt.z_min, tt.z_max, u);
    if (tt.nose_radius) line += fmt::format(", nose radius {:g}", *tt.nose_radius);
    if (!tt.text.empty()) line += ", " + tt.text;
    out.push_back(std::move(line));
  }
  out.push_back(fmt::format("cycle time {}, {} tool change{}{}", time_text(t.total()), changes,
                            changes == 1 ? "" : "s", untimed_note(t)));
  return out;
}

std::vector<std::string> header_lines(const CycleTime& t, std::string_view program,
                                      std::string_view machine, LengthUnit units, bool diameter) {
  // The program's name last: a PARTNO may hold commas of its own ("PIN-01 turned pin, 25 mm
  // stock").
  std::vector<std::string> out{fmt::format("machine {}, program {}", machine, program)};
  std::vector<ToolTime> tools;  // each tool once (number and offset), its times summed
  for (const ToolTime& tt : t.tools) {
    if (tt.tool < 0) continue;
    auto same = std::find_if(tools.begin(), tools.end(), [&tt](const ToolTime& u) {
      return u.tool == tt.tool && u.offset == tt.offset;
    });
    if (same == tools.end()) {
      tools.push_back(tt);
      continue;
    }
    same->seconds += tt.seconds;
    if (same->text.empty()) same->text = tt.text;
    if (!same->nose_radius) same->nose_radius = tt.nose_radius;
  }
  for (const ToolTime& tt : tools) {
    std::string line = fmt::format("T{} offset {}", tt.tool, tt.offset);
    if (!tt.text.empty()) line += ", " + tt.text;
    if (tt.nose_radius) line += fmt::format(", nose radius {:g}", *tt.nose_radius);
    line += fmt::format(", first at CL line {}, {}", tt.line, time_text(tt.seconds));
    out.push_back(std::move(line));
  }
  out.push_back(cycle_time_lines(t, units, diameter).back());
  return out;
}

}  // namespace clpost

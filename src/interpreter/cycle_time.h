#pragma once
// The estimated cycle time of a program, per tool and in total, with the tool list: what each
// tool is (number, offset, text, nose radius) and the extremes of X and Z it reaches. Worked out
// from what the CL asks the machine to do, as it is posted:
//   feed moves       length / feed (per minute), or length / (feed x rpm) per revolution; under
//                    constant surface speed the rpm is S/(2 pi r) at each radius r of the move
//                    (S in mm/min: m/min x 1000, or in/min: ft/min x 12), clamped at the limit;
//   rapid moves      each axis at its rate (time.rapid_x as a radius, time.rapid_z), the slower
//                    axis deciding (both move at once);
//   threads          every pass of the plan: rapid to its approach and start, the cut and a
//                    synchronized pull-out at lead x rpm (along the longer axis), rapid clear;
//   holes            the hole's own moves (pecks, dwell, retract) whatever NC writes them;
//   C moves        the angle each C index or hole's C turns over time.rapid_c (degrees per
//                    minute; the first C after engaging, from an unknown angle, is not timed),
//                    and time.c_clamp seconds for every C clamp or unclamp code written;
//   dwells, and time.tool_change seconds for every tool change.
// A rapid rate of 0 (not given) times rapids as 0 s and says so.
#include <cstdint>
#include <limits>
#include <optional>
#include <string>
#include <string_view>
#include <vector>

#include "emitters/hole_output.h"
#include "planner/thread_plan.h"

namespace clpost {

// A feed or spindle speed a tool cuts with (clpost sheet): the value as the CL gave it, CL units.
struct FeedUsed {
  double value = 0;
  FeedMode mode = FeedMode::kPerMinute;
  bool operator==(const FeedUsed&) const = default;
};
struct SpeedUsed {
  double value = 0;  // rpm, or the surface speed when css
  bool css = false;  // m/min (ft/min in inch programs)
  bool operator==(const SpeedUsed&) const = default;
};

struct ToolTime {
  int tool = -1;  // -1: before the first tool change
  int offset = -1;
  uint32_t line = 0;  // the CL line of the tool change
  std::string text;
  std::optional<double> nose_radius;
  double seconds = 0;
  double cutting_seconds = 0;  // of `seconds`: feed, arc and synchronized (thread, tap) moves
  // The NC program's lines (1-based) from the tool change to the last before the next one (0:
  // none written), counting the program_header's lines.
  size_t first_nc_line = 0, last_nc_line = 0;
  // The feeds and speeds its feed moves cut with, in the order first used, each once; a thread's
  // feed is its lead per revolution.
  std::vector<FeedUsed> feeds;
  std::vector<SpeedUsed> speeds;
  // The extremes of X (as a radius) and Z the tool reaches (min > max: it never moves).
  double x_min = std::numeric_limits<double>::infinity();
  double x_max = -std::numeric_limits<double>::infinity();
  double z_min = std::numeric_limits<double>::infinity();
  double z_max = -std::numeric_limits<double>::infinity();
};

struct CycleTime {
  std::vector<ToolTime> tools;  // in the order they are used
  bool rapids_untimed = false;  // a rapid was met with a rapid rate of 0
  bool c_untimed = false;       // a C move was met with time.rapid_c 0
  double total() const {
    double t = 0;
    for (const ToolTime& tt : tools) t += tt.seconds;
    return t;
  }
};

// What the cycle time leaves out ("; rapids not timed: no time.rapid_x/rapid_z"), or "".
std::string untimed_note(const CycleTime& t);

// "0:42.5" (minutes:seconds to 0.1 s), "1:02:03.0" past an hour; "over 1000000:00:00" for a
// longer time (a CL with an absurd feed or distance), "not known" for one that is not a number.
std::string time_text(double seconds);
// The tool list and times as text lines ("T1 D1 ...", then "total ..."), for clpost check and
// the NC header; each line without a line ending, in `units`.
std::vector<std::string> cycle_time_lines(const CycleTime& t, LengthUnit units, bool diameter);
// Whether cycle_time_lines lists `t` (the entry before the first tool only when it moves or takes
// time): the sheet lists the same tools.
bool listed(const ToolTime& t);
// Every tool's NC lines moved down by `lines` (a program_header written before them).
void shift_nc_lines(CycleTime& t, size_t lines);

// The program header (program_header): the program's name and the machine's, then each tool
// once, in the order first used (number, offset, text, nose radius, the CL line of its first
// change, its time over all its uses), then the cycle time as cycle_time_lines() says it.
std::vector<std::string> header_lines(const CycleTime& t, std::string_view program,
                                      std::string_view machine, LengthUnit units, bool diameter);

// The hooks that time a program as it is posted are in clock.h.

}  // namespace clpost

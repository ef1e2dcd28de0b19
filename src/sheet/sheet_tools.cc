// The tool list, in the order the tools are used, and the total cycle time: the clock's
// CycleTime, the one `clpost check` prints (cycle_time_lines), row for row.
#include <fmt/format.h>

#include "sheet/html_text.h"
#include "sheet/sheet_parts.h"
#include "sheet/sheet_text.h"
#include "support/number_text.h"

namespace clpost {

namespace {

// The items as unbroken pieces, ", " between them (HTML).
template <class T, class F>
std::string joined(const std::vector<T>& v, F text) {
  std::string o;
  for (size_t i = 0; i < v.size(); ++i) o += (i ? ", " : "") + nw(text(v[i]));
  return o;
}

// "X0.000 to X32.000, Z-42.000 to Z2.000" broken only after the comma (HTML).
std::string reach_html(const ToolTime& t, bool diameter) {
  const std::string r = reach_text(t, diameter);
  const size_t comma = r.find(", ");
  if (comma == std::string::npos) return esc(r);
  return nw(r.substr(0, comma + 1)) + " " + nw(r.substr(comma + 2));
}

std::string nc_lines(const ToolTime& t) {
  if (t.first_nc_line == 0 || t.last_nc_line < t.first_nc_line) return "-";
  return fmt::format("{}-{}", t.first_nc_line, t.last_nc_line);
}

std::string tool_row(size_t n, const ToolTime& t, const SheetData& d) {
  auto feed = [&](const FeedUsed& f) { return feed_text(f, d.units); };
  auto speed = [&](const SpeedUsed& s) { return speed_text(s, d.units); };
  return row({{std::to_string(n), true},
              {tool_name(t)},
              {t.offset < 0 ? "-" : std::to_string(t.offset), true},
              {t.text},
              {t.nose_radius ? num_text(*t.nose_radius) : "-", true},
              {nc_lines(t), true},
              {time_text(t.cutting_seconds), true},
              {time_text(t.seconds), true},
              {joined(t.feeds, feed), false, true},
              {joined(t.speeds, speed), false, true},
              {reach_html(t, d.diameter), false, true}});
}

}  // namespace

std::string tools_section(const SheetData& d) {
  std::string o = "<section id=\"tools\">\n<h2>Tools, in the order they are used</h2>\n";
  o += "<table class=\"tools\">\n";
  o += head_row({"#", "Tool", "Offset", "Description", "Nose radius", "NC lines", "Cutting",
                 "Total", "Feeds", "Speeds", "Reach"});
  o += "<tbody>\n";
  size_t n = 0;
  for (const ToolTime& t : d.cycle_time.tools)
    if (listed(t)) o += tool_row(++n, t, d);
  o += "</tbody>\n</table>\n";
  o += fmt::format(
      "<p class=\"total\">Total cycle time <strong id=\"cycle-time\">{}</strong>, {} tool "
      "change{}{}. Times are estimates from the machine file's rapid rates and tool change "
      "time.</p>\n",
      esc(time_text(d.cycle_time.total())), tool_changes(d.cycle_time),
      tool_changes(d.cycle_time) == 1 ? "" : "s", untimed_note(d.cycle_time));
  return o + "</section>\n";
}

}  // namespace clpost

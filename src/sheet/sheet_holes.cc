// Every hole the program drills (on the spindle axis, or off it with a live tool): where, how
// deep, the cycle, and the output that wrote it (the holes the post keeps for verify,
// PostSummary::holes).
#include <fmt/format.h>

#include <algorithm>
#include <cmath>

#include "planner/plan_format.h"
#include "sheet/html_text.h"
#include "sheet/sheet_parts.h"
#include "sheet/sheet_text.h"
#include "support/number_text.h"

namespace clpost {

namespace {

std::string pecks(const Hole& h) {
  if (h.peck <= 0 && h.first_peck <= 0) return "-";
  if (h.first_peck > 0 && h.first_peck != h.peck)
    return fmt::format("{} then {}", num_text(h.first_peck), num_text(h.peck));
  return num_text(h.peck > 0 ? h.peck : h.first_peck);
}

// Where the hole is, as the program writes it: on the centre line at Z, on the face at X and C,
// or radial at Z and C from X (docs/millturn.md).
std::string position(const SheetData& d, const Hole& h) {
  const double k = d.diameter ? 2 : 1;
  const std::string c = h.c ? fmt::format(" C{}", num_text(*h.c)) : std::string();
  if (h.radial) return fmt::format("X{} Z{}{}, radial", num_text(h.top * k), num_text(h.z), c);
  return fmt::format("X{}{} Z{}", num_text(h.x * k), c, num_text(h.top));
}

std::string hole_row(const SheetData& d, size_t i) {
  const Hole& h = d.holes[i];
  const OutputUsed* o = output_at(d.outputs, h.cl_line);
  const FeedUsed feed{h.feed, h.feed_mode};
  const std::string output = i < d.hole_outputs.size() ? d.hole_outputs[i] : o ? o->name : "-";
  return row({{std::to_string(h.cl_line), true},
              {std::string(hole_kind_name(h.kind))},
              {h.tool_diameter ? num_text(*h.tool_diameter) : "-", true},
              {position(d, h)},
              {num_text(std::fabs(h.bottom - h.top)), true},
              {num_text(h.r), true},
              {pecks(h), true},
              {h.dwell > 0 ? fmt::format("{} s", num_text(h.dwell)) : "-", true},
              {feed_text(feed, d.units)},
              {output},
              {o && !o->unfit.empty() ? fallback_text(*o) : ""}});
}

}  // namespace

std::string holes_section(const SheetData& d) {
  std::string o = "<section class=\"page\" id=\"holes\">\n<h2>Holes</h2>\n";
  if (d.holes.empty()) return o + "<p>No holes on the spindle axis.</p>\n</section>\n";
  const bool live = std::any_of(d.holes.begin(), d.holes.end(), [](const Hole& h) { return h.c; });
  o += fmt::format(
      "<p>{}, lengths in {}.</p>\n",
      live ? "On the spindle axis and off it with a live tool (at C)" : "On the spindle axis",
      units_name(d.units));
  o += "<table class=\"holes\">\n";
  o += head_row({"CL line", "Cycle", "Tool diameter", "Position", "Depth", "R plane", "Pecks",
                 "Dwell", "Feed", "Output", "Fallback"});
  o += "<tbody>\n";
  for (size_t i = 0; i < d.holes.size(); ++i) o += hole_row(d, i);
  return o + "</tbody>\n</table>\n</section>\n";
}

}  // namespace clpost

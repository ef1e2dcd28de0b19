// Every hole on the spindle axis the program drills: where, how deep, the cycle, and the output
// that wrote it (the holes the post keeps for verify, PostSummary::holes).
#include <fmt/format.h>

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

std::string hole_row(const SheetData& d, const Hole& h) {
  const OutputUsed* o = output_at(d.outputs, h.cl_line);
  const FeedUsed feed{h.feed, h.feed_mode};
  return row({{std::to_string(h.cl_line), true},
              {std::string(hole_kind_name(h.kind))},
              {fmt::format("X0 Z{}", num_text(h.top))},
              {num_text(std::fabs(h.bottom - h.top)), true},
              {num_text(h.r), true},
              {pecks(h), true},
              {h.dwell > 0 ? fmt::format("{} s", num_text(h.dwell)) : "-", true},
              {feed_text(feed, d.units)},
              {o ? o->name : "-"},
              {o && !o->unfit.empty() ? fallback_text(*o) : ""}});
}

}  // namespace

std::string holes_section(const SheetData& d) {
  std::string o = "<section class=\"page\" id=\"holes\">\n<h2>Holes</h2>\n";
  if (d.holes.empty()) return o + "<p>No holes on the spindle axis.</p>\n</section>\n";
  o += fmt::format("<p>On the spindle axis, lengths in {}.</p>\n", units_name(d.units));
  o += "<table class=\"holes\">\n";
  o += head_row({"CL line", "Cycle", "Position", "Depth", "R plane", "Pecks", "Dwell", "Feed",
                 "Output", "Fallback"});
  o += "<tbody>\n";
  for (const Hole& h : d.holes) o += hole_row(d, h);
  return o + "</tbody>\n</table>\n</section>\n";
}

}  // namespace clpost

// The page: the program's facts, then the sections (sheet_parts.h), the backplot, the warnings.
#include <fmt/format.h>

#include "plot/backplot_svg.h"
#include "sheet/html_text.h"
#include "sheet/sheet_parts.h"
#include "sheet/sheet_text.h"

namespace clpost {

namespace {

std::string facts_header(const SheetData& d) {
  const std::string name = d.partno.empty() ? d.program : d.partno;
  std::string o = "<header>\n<h1>Setup sheet: " + esc(name) + "</h1>\n";
  o += "<table class=\"facts\" id=\"program\">\n<tbody>\n";
  o += fact("CL file", d.program);
  if (!d.partno.empty()) o += fact("Part", d.partno);
  o += fact("NC program", d.nc_file.empty() ? std::string("(not written)") : d.nc_file);
  o += fact("Machine", d.machine_description.empty()
                           ? d.machine
                           : fmt::format("{} ({})", d.machine, d.machine_description));
  o += fact("Date", d.date);
  o += fact("Units", d.units == LengthUnit::kInch ? "inch" : "mm");
  o += fact("Cycle time", time_text(d.cycle_time.total()));
  o += fact("Tools", std::to_string(tool_changes(d.cycle_time)));
  o += fact("Threads", std::to_string(d.plans.size()));
  o += fact("Holes", std::to_string(d.holes.size()));
  o += fact("Warnings", std::to_string(d.warnings));
  return o + "</tbody>\n</table>\n</header>\n";
}

std::string backplot_section(const SheetData& d) {
  std::string o = "<section class=\"page\" id=\"backplot\">\n<h2>Backplot</h2>\n";
  const std::string title = fmt::format("{} posted on {}", d.program, d.machine);
  o += "<figure class=\"backplot\">\n" +
       inline_svg(backplot_svg(d.toolpath, nullptr, title, simplified_note(d.toolpath)));
  o += "<figcaption>The program as the control runs it: feed moves solid, rapids dashed.";
  return o + "</figcaption>\n</figure>\n</section>\n";
}

}  // namespace

std::string sheet_html(const SheetData& d) {
  std::string o = "<!DOCTYPE html>\n<html lang=\"en\">\n<head>\n<meta charset=\"utf-8\">\n";
  o += "<meta name=\"viewport\" content=\"width=device-width, initial-scale=1\">\n";
  o += "<meta name=\"generator\" content=\"clpost sheet\">\n";
  o += "<title>Setup sheet: " + esc(d.partno.empty() ? d.program : d.partno) + "</title>\n";
  o += "<style>\n" + sheet_css() + "</style>\n</head>\n<body>\n";
  o += facts_header(d);
  o += tools_section(d);
  o += threads_sections(d);
  o += holes_section(d);
  o += backplot_section(d);
  o += warnings_section(d);
  return o + "</body>\n</html>\n";
}

}  // namespace clpost

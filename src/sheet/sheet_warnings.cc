// Every warning and note the post gave, with its CL line: the diagnostics `clpost check` prints.
#include <fmt/format.h>

#include "sheet/html_text.h"
#include "sheet/sheet_parts.h"

namespace clpost {

std::string warnings_section(const SheetData& d) {
  std::string o = "<section class=\"page\" id=\"warnings\">\n<h2>Warnings</h2>\n";
  if (d.diagnostics.empty()) return o + "<p>None.</p>\n</section>\n";
  o += "<table class=\"warnings\">\n";
  o += head_row({"CL line", "Severity", "Message", "CL text"});
  o += "<tbody>\n";
  for (const Diagnostic& g : d.diagnostics)
    o += row({{g.loc.line > 0 ? std::to_string(g.loc.line) : "-", true},
              {std::string(severity_name(g.severity))},
              {g.message},
              {g.line_text}});
  o += "</tbody>\n</table>\n";
  if (d.warnings > d.diagnostics.size())
    o += fmt::format("<p>{} more not listed (the post keeps the first {}).</p>\n",
                     d.warnings - d.diagnostics.size(), d.diagnostics.size());
  return o + "</section>\n";
}

}  // namespace clpost

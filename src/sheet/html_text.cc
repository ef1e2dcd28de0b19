#include "sheet/html_text.h"

#include "plot/svg_writer.h"

namespace clpost {

std::string esc(std::string_view s) {
  return xml_escape(s);
}

std::string row(std::initializer_list<Cell> cells) {
  std::string o = "<tr>";
  for (const Cell& c : cells) {
    o += c.num ? "<td class=\"num\">" : "<td>";
    o += c.html ? c.text : esc(c.text);
    o += "</td>";
  }
  return o + "</tr>\n";
}

std::string nw(std::string_view text) {
  return "<span class=\"nw\">" + esc(text) + "</span>";
}

std::string head_row(std::initializer_list<std::string_view> names) {
  std::string o = "<thead><tr>";
  for (std::string_view n : names) o += "<th>" + esc(n) + "</th>";
  return o + "</tr></thead>\n";
}

std::string fact(std::string_view name, std::string_view value) {
  return "<tr><th>" + esc(name) + "</th><td>" + esc(value) + "</td></tr>\n";
}

std::string inline_svg(std::string_view svg) {
  if (svg.starts_with("<?xml")) {
    const size_t end = svg.find("?>");
    if (end != std::string_view::npos) svg.remove_prefix(end + 2);
  }
  while (!svg.empty() && (svg.front() == '\n' || svg.front() == '\r')) svg.remove_prefix(1);
  return std::string(svg);
}

}  // namespace clpost

#pragma once
// HTML pieces for the sheet: escaped cells and rows, and an SVG document made inline. Everything
// the CL says (names, PPRINT and tool text, messages) goes through esc().
#include <initializer_list>
#include <string>
#include <string_view>

namespace clpost {

// Text for HTML content or a quoted attribute (the SVG writer's escaping: & < > " ' become
// entities, invalid UTF-8 becomes U+FFFD).
std::string esc(std::string_view s);

// A table cell: `text` escaped, or as it is when `html` (made of escaped pieces). Numeric cells
// (`num`) align right; `nowrap` ones keep each piece (nw()) on one line.
struct Cell {
  std::string text;
  bool num = false;
  bool html = false;
};
// `text` escaped, in a span that is not broken across lines.
std::string nw(std::string_view text);
// "<tr><td>…</td>…</tr>\n".
std::string row(std::initializer_list<Cell> cells);
// "<thead><tr><th>…</th>…</tr></thead>\n".
std::string head_row(std::initializer_list<std::string_view> names);
// A two-column row of a facts table: "<tr><th>name</th><td>value</td></tr>\n".
std::string fact(std::string_view name, std::string_view value);

// A standalone SVG document as an element inside HTML: without its XML declaration.
std::string inline_svg(std::string_view svg);

}  // namespace clpost

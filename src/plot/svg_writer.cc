#include "plot/svg_writer.h"

#include <fmt/format.h>

#include <algorithm>
#include <cmath>

namespace clpost {

std::string svg_num(double v, int decimals) {
  if (!std::isfinite(v)) return "0";
  decimals = std::clamp(decimals, 0, 9);
  std::string s = fmt::format("{:.{}f}", v, decimals);
  if (s.find('.') != std::string::npos) {
    while (s.back() == '0') s.pop_back();
    if (s.back() == '.') s.pop_back();
  }
  if (s == "-0") s = "0";
  return s;
}

std::string fixed_text(double v, int decimals) {
  if (!std::isfinite(v)) return "-";
  decimals = std::clamp(decimals, 0, 9);
  std::string s = fmt::format("{:.{}f}", v, decimals);
  if (s.front() == '-' && s.find_first_not_of("-0.") == std::string::npos) s.erase(0, 1);
  return s;
}

namespace {

// Length of the valid UTF-8 sequence at s[i], or 0 when there is none.
size_t utf8_length(std::string_view s, size_t i) {
  const auto b = [&](size_t k) { return static_cast<unsigned char>(s[k]); };
  const unsigned char c = b(i);
  size_t n = 0;
  if (c < 0x80) return 1;
  if (c >= 0xC2 && c <= 0xDF) {
    n = 2;
  } else if (c >= 0xE0 && c <= 0xEF) {
    n = 3;
  } else if (c >= 0xF0 && c <= 0xF4) {
    n = 4;
  } else {
    return 0;
  }
  if (i + n > s.size()) return 0;
  for (size_t k = 1; k < n; ++k)
    if ((b(i + k) & 0xC0) != 0x80) return 0;
  // Overlong forms, surrogates and code points above U+10FFFF.
  if (c == 0xE0 && b(i + 1) < 0xA0) return 0;
  if (c == 0xED && b(i + 1) > 0x9F) return 0;
  if (c == 0xF0 && b(i + 1) < 0x90) return 0;
  if (c == 0xF4 && b(i + 1) > 0x8F) return 0;
  return n;
}

}  // namespace

std::string xml_escape(std::string_view s) {
  std::string o;
  o.reserve(s.size());
  for (size_t i = 0; i < s.size();) {
    const char c = s[i];
    switch (c) {
      case '&':
        o += "&amp;";
        break;
      case '<':
        o += "&lt;";
        break;
      case '>':
        o += "&gt;";
        break;
      case '"':
        o += "&quot;";
        break;
      case '\'':
        o += "&apos;";
        break;
      default: {
        const size_t n = utf8_length(s, i);
        if (n == 0) {
          o += "\xEF\xBF\xBD";  // U+FFFD
          ++i;
          continue;
        }
        const auto u = static_cast<unsigned char>(c);
        if (n == 1 && u < 0x20 && c != '\t' && c != '\n' && c != '\r') {
          ++i;
          continue;
        }
        o.append(s.substr(i, n));
        i += n;
        continue;
      }
    }
    ++i;
  }
  return o;
}

SvgWriter::SvgWriter(double width, double height) : width_(width), height_(height) {}

void SvgWriter::start_tag(std::string_view tag, const SvgAttrs& attrs) {
  body_ += '<';
  body_ += tag;
  for (const auto& [name, value] : attrs) {
    body_ += ' ';
    body_ += name;
    body_ += "=\"";
    body_ += xml_escape(value);
    body_ += '"';
  }
}

void SvgWriter::open(std::string_view tag, const SvgAttrs& attrs) {
  start_tag(tag, attrs);
  body_ += ">\n";
  open_.emplace_back(tag);
}

void SvgWriter::close() {
  if (open_.empty()) return;
  body_ += "</";
  body_ += open_.back();
  body_ += ">\n";
  open_.pop_back();
}

void SvgWriter::empty(std::string_view tag, const SvgAttrs& attrs) {
  start_tag(tag, attrs);
  body_ += "/>\n";
}

void SvgWriter::text(std::string_view tag, const SvgAttrs& attrs, std::string_view content) {
  start_tag(tag, attrs);
  body_ += '>';
  body_ += xml_escape(content);
  body_ += "</";
  body_ += tag;
  body_ += ">\n";
}

void SvgWriter::raw(std::string_view markup) {
  body_ += markup;
}

std::string SvgWriter::finish() {
  while (!open_.empty()) close();
  const std::string w = svg_num(width_);
  const std::string h = svg_num(height_);
  std::string o = "<?xml version=\"1.0\" encoding=\"UTF-8\"?>\n";
  o += fmt::format(
      "<svg xmlns=\"http://www.w3.org/2000/svg\" version=\"1.1\" width=\"{0}\" height=\"{1}\" "
      "viewBox=\"0 0 {0} {1}\" font-family=\"DejaVu Sans, Arial, Helvetica, sans-serif\">\n",
      w, h);
  o += body_;
  o += "</svg>\n";
  return o;
}

void SvgPath::move_to(double x, double y) {
  if (has_point_ && at(x, y)) return;
  if (!d_.empty()) d_ += ' ';
  d_ += fmt::format("M{} {}", svg_num(x), svg_num(y));
  has_point_ = true;
  cx_ = x;
  cy_ = y;
}

void SvgPath::line_to(double x, double y) {
  if (!has_point_) {
    move_to(x, y);
    return;
  }
  d_ += fmt::format(" L{} {}", svg_num(x), svg_num(y));
  cx_ = x;
  cy_ = y;
  ++segments_;
}

void SvgPath::arc_to(double r, bool large_arc, bool sweep, double x, double y) {
  if (!has_point_) {
    move_to(x, y);
    return;
  }
  d_ += fmt::format(" A{0} {0} 0 {1} {2} {3} {4}", svg_num(r), large_arc ? 1 : 0, sweep ? 1 : 0,
                    svg_num(x), svg_num(y));
  cx_ = x;
  cy_ = y;
  ++segments_;
}

void SvgPath::close_path() {
  if (d_.empty()) return;
  d_ += " Z";
  has_point_ = false;
}

bool SvgPath::at(double x, double y) const {
  return has_point_ && std::fabs(x - cx_) < 0.005 && std::fabs(y - cy_) < 0.005;
}

void lead_hatch_pattern(SvgWriter& w, std::string_view id, std::string_view stroke,
                        std::string_view stroke_width) {
  w.open("pattern", {{"id", std::string(id)},
                     {"patternUnits", "userSpaceOnUse"},
                     {"width", "6"},
                     {"height", "6"},
                     {"patternTransform", "rotate(-45)"}});
  w.empty("rect", {{"width", "6"}, {"height", "6"}, {"fill", "#e4e4e4"}});
  w.empty("line", {{"x1", "0"},
                   {"y1", "0"},
                   {"x2", "0"},
                   {"y2", "6"},
                   {"stroke", std::string(stroke)},
                   {"stroke-width", std::string(stroke_width)}});
  w.close();
}

}  // namespace clpost

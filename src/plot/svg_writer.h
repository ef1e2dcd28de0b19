#pragma once
// A tiny SVG document builder for clpost's pictures (thread sections, backplots): elements with
// attributes, escaped text, numbers with a fixed small precision, and path data. No layout, no
// styling beyond what the caller writes; the output is a standalone UTF-8 SVG 1.1 document.
#include <string>
#include <string_view>
#include <utility>
#include <vector>

namespace clpost {

// A number for SVG: fixed notation with `decimals` decimals (default 2, enough for pixels),
// trailing zeros and a bare point trimmed, never "-0"; NaN and infinities become "0" so a bad
// input never makes an unreadable document. 12.5 -> "12.5", pi -> "3.14", -0.001 -> "0".
std::string svg_num(double v, int decimals = 2);

// A number for tables and labels: exactly `decimals` decimals (zeros kept, so columns line up),
// never "-0.000"; NaN and infinities become "-". 0.9200001 with 3 -> "0.920".
std::string fixed_text(double v, int decimals);

// Text for an XML attribute value or element content: & < > " ' become entities, control
// characters other than tab, LF and CR (not allowed in XML 1.0) are dropped, and invalid UTF-8
// becomes U+FFFD.
std::string xml_escape(std::string_view s);

// A width and height in px.
struct SvgSize {
  double width = 0;
  double height = 0;
};

// Name/value pairs of one element, written in the given order; values are escaped on output.
using SvgAttrs = std::vector<std::pair<std::string_view, std::string>>;

// Builds one document. The root <svg> has width/height in px and viewBox "0 0 width height".
// Elements are opened and closed in a stack; finish() closes whatever is still open.
class SvgWriter {
 public:
  SvgWriter(double width, double height);

  // <tag attrs...>, to be closed by close().
  void open(std::string_view tag, const SvgAttrs& attrs = {});
  // Closes the innermost open element (never the root).
  void close();
  // <tag attrs.../>
  void empty(std::string_view tag, const SvgAttrs& attrs);
  // <tag attrs...>text</tag>
  void text(std::string_view tag, const SvgAttrs& attrs, std::string_view content);
  // Raw, already valid markup (e.g. a fragment from another writer's body()).
  void raw(std::string_view markup);

  // The document so far without the XML declaration and root element (for nesting).
  const std::string& body() const { return body_; }
  // The whole document: XML declaration, root <svg>, body, and every open element closed.
  std::string finish();

 private:
  void start_tag(std::string_view tag, const SvgAttrs& attrs);

  double width_;
  double height_;
  std::string body_;
  std::vector<std::string> open_;
};

// SVG path data ("M 1 2 L 3 4 A ..."), numbers via svg_num. line_to() after a break (or first)
// starts a new subpath with M, and repeats of the current point are not written.
class SvgPath {
 public:
  void move_to(double x, double y);
  // A straight segment from the current point; starts a subpath at (x, y) when there is none.
  void line_to(double x, double y);
  // An elliptical arc segment (circular here: rx = ry = r) from the current point.
  void arc_to(double r, bool large_arc, bool sweep, double x, double y);
  void close_path();
  bool empty() const { return d_.empty(); }
  // Whether (x, y) is the current point (within 0.005, half the written precision).
  bool at(double x, double y) const;
  const std::string& data() const { return d_; }
  size_t segments() const { return segments_; }

 private:
  std::string d_;
  bool has_point_ = false;
  double cx_ = 0;
  double cy_ = 0;
  size_t segments_ = 0;
};

// The hatch pattern `id` of a length whose lead is not right (backplot, thread section): dark
// lines of `stroke` and `stroke_width` on grey, slanted at -45 degrees, usable without colour.
void lead_hatch_pattern(SvgWriter& w, std::string_view id, std::string_view stroke,
                        std::string_view stroke_width);

}  // namespace clpost

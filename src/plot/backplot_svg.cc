#include "plot/backplot_svg.h"

#include <fmt/format.h>

#include <algorithm>
#include <array>
#include <cmath>
#include <numbers>
#include <string>

#include "plot/move_geometry.h"
#include "plot/nice_step.h"
#include "plot/svg_writer.h"
#include "plot/thread_section_svg.h"

namespace clpost {
namespace {

constexpr double kWidth = 1200;
constexpr double kLeft = 78;  // room for the X tick numbers
constexpr double kRight = 28;
constexpr double kTop = 112;  // title, summary and legend
constexpr double kMaxPlotH = 640;
constexpr double kMinPlotH = 160;
constexpr double kBelow = 56;  // Z tick numbers and axis title
constexpr double kNoteH = 16;  // a line for the note on a simplified path

// Drawing class of a move; arcs in either direction share one.
enum class Stroke : uint8_t { kRapid, kFeed, kArc, kThread };
constexpr std::array<const char*, 4> kClass = {"rapid", "feed", "arc", "thread"};

Stroke stroke_of(MoveKind k) {
  return static_cast<Stroke>(draw_class(k));
}

// Model (Z, X) to page: equal scale, X up.
struct Frame {
  double ox = kLeft, oy = kTop;  // top-left of the plot
  double w = 0, h = 0;
  double k = 1;  // px per unit
  double z_lo = 0, z_hi = 1, x_lo = 0, x_hi = 1;
  double px(double z) const { return ox + (z - z_lo) * k; }
  double py(double x) const { return oy + h - (x - x_lo) * k; }
};

Frame frame_of(const Bounds& b, double top = kTop) {
  Frame f;
  f.oy = top;
  double z_lo = b.empty ? 0 : b.z_lo, z_hi = b.empty ? 10 : b.z_hi;
  double x_lo = b.empty ? 0 : b.x_lo, x_hi = b.empty ? 10 : b.x_hi;
  // Show the spindle axis when the part is nearer to it than it is tall.
  if (x_lo > 0 && x_lo <= x_hi - x_lo) x_lo = 0;
  double span = std::max(z_hi - z_lo, x_hi - x_lo);
  if (!(span > 0)) span = 1;
  const double pad = span * 0.05;
  z_lo -= pad;
  z_hi += pad;
  x_lo -= pad;
  x_hi += pad;
  const double max_w = kWidth - kLeft - kRight;
  f.k = std::min(max_w / (z_hi - z_lo), kMaxPlotH / (x_hi - x_lo));
  // A flat picture gets more room above and below, never a second scale.
  const double min_x = kMinPlotH / f.k;
  if (x_hi - x_lo < min_x) {
    const double more = (min_x - (x_hi - x_lo)) / 2;
    x_lo -= more;
    x_hi += more;
  }
  f.z_lo = z_lo;
  f.z_hi = z_hi;
  f.x_lo = x_lo;
  f.x_hi = x_hi;
  f.w = (z_hi - z_lo) * f.k;
  f.h = (x_hi - x_lo) * f.k;
  f.ox = kLeft + (max_w - f.w) / 2;
  return f;
}

void draw_style(SvgWriter& w) {
  w.text("style", {},
         ".rapid{fill:none;stroke:#8c8c8c;stroke-width:1;stroke-dasharray:6 4}"
         ".feed{fill:none;stroke:#1f5fbf;stroke-width:1.6;stroke-linejoin:round}"
         ".arc{fill:none;stroke:#13948f;stroke-width:1.6}"
         ".thread{fill:none;stroke:#f07800;stroke-width:3.6;stroke-linecap:round;"
         "stroke-linejoin:round}"
         ".grid{stroke:#e3e6ea;stroke-width:1}"
         ".tick{font-size:12px;fill:#444444}");
}

// Grid lines every `step_z` along Z and `step_x` along X, with their numbers.
void draw_grid_lines(SvgWriter& w, const Frame& f, double step_z, double step_x) {
  w.open("g", {{"class", "grid-lines"}});
  SvgPath grid;
  for (double z = std::ceil(f.z_lo / step_z) * step_z; z <= f.z_hi; z += step_z) {
    grid.move_to(f.px(z), f.oy);
    grid.line_to(f.px(z), f.oy + f.h);
  }
  for (double x = std::ceil(f.x_lo / step_x) * step_x; x <= f.x_hi; x += step_x) {
    grid.move_to(f.ox, f.py(x));
    grid.line_to(f.ox + f.w, f.py(x));
  }
  w.empty("path", {{"class", "grid"}, {"d", grid.data()}});
  for (double z = std::ceil(f.z_lo / step_z) * step_z; z <= f.z_hi; z += step_z)
    w.text("text",
           {{"class", "tick"},
            {"x", svg_num(f.px(z))},
            {"y", svg_num(f.oy + f.h + 17)},
            {"text-anchor", "middle"}},
           svg_num(std::fabs(z) < step_z * 1e-6 ? 0 : z, 6));
  for (double x = std::ceil(f.x_lo / step_x) * step_x; x <= f.x_hi; x += step_x)
    w.text("text",
           {{"class", "tick"},
            {"x", svg_num(f.ox - 7)},
            {"y", svg_num(f.py(x) + 4)},
            {"text-anchor", "end"}},
           svg_num(std::fabs(x) < step_x * 1e-6 ? 0 : x, 6));
  w.close();
}

// The names of a view's axes ("{}" the unit) and whether its X 0 line is the spindle axis.
struct AxisTitles {
  std::string_view across = "Z ({}) \u2192";
  std::string_view up = "\u2191 X radius ({})";
  bool spindle_axis = true;
};

// The plot's border and the names of its axes.
void draw_border(SvgWriter& w, const Frame& f, const char* unit, const AxisTitles& t) {
  w.empty("rect", {{"x", svg_num(f.ox)},
                   {"y", svg_num(f.oy)},
                   {"width", svg_num(f.w)},
                   {"height", svg_num(f.h)},
                   {"fill", "none"},
                   {"stroke", "#9aa0a6"}});
  w.text("text",
         {{"x", svg_num(f.ox + f.w)},
          {"y", svg_num(f.oy + f.h + 38)},
          {"font-size", "13"},
          {"text-anchor", "end"},
          {"fill", "#333333"}},
         fmt::format(fmt::runtime(t.across), unit));
  w.text("text",
         {{"x", svg_num(f.ox)}, {"y", svg_num(f.oy - 8)}, {"font-size", "13"}, {"fill", "#333333"}},
         fmt::format(fmt::runtime(t.up), unit));
}

// The spindle axis (X 0), drawn when the plot reaches across it.
void draw_spindle_axis(SvgWriter& w, const Frame& f) {
  if (!(f.x_lo < 0 && f.x_hi > 0)) return;
  w.empty("line", {{"class", "axis"},
                   {"x1", svg_num(f.ox)},
                   {"y1", svg_num(f.py(0))},
                   {"x2", svg_num(f.ox + f.w)},
                   {"y2", svg_num(f.py(0))},
                   {"stroke", "#555555"},
                   {"stroke-width", "1"},
                   {"stroke-dasharray", "14 3 3 3"}});
  w.text("text",
         {{"x", svg_num(f.ox + 6)},
          {"y", svg_num(f.py(0) - 5)},
          {"font-size", "11"},
          {"fill", "#555555"}},
         "spindle axis");
}

void draw_grid(SvgWriter& w, const Frame& f, const char* unit, const AxisTitles& t = {}) {
  // One step on both axes (one scale), at most about 12 ticks and numbers at least 56 px apart;
  // a flat plot gets finer X ticks, still at least 24 px apart.
  const double step_z =
      nice_step(std::max({(f.z_hi - f.z_lo) / 12, (f.x_hi - f.x_lo) / 12, 56 / f.k}));
  const double step_x = std::min(step_z, nice_step(std::max((f.x_hi - f.x_lo) / 4, 24 / f.k)));
  draw_grid_lines(w, f, step_z, step_x);
  draw_border(w, f, unit, t);
  if (t.spindle_axis) draw_spindle_axis(w, f);
}

// The moves as one <path> per run of one drawing class.
void draw_moves(SvgWriter& w, const std::vector<Move>& moves, const Frame& f) {
  SvgPath path;
  Stroke run = Stroke::kRapid;
  auto flush = [&] {
    if (path.segments() > 0)
      w.empty("path", {{"class", kClass[static_cast<size_t>(run)]}, {"d", path.data()}});
    path = SvgPath();
  };
  w.open("g", {{"class", "moves"}});
  for (const Move& m : moves) {
    if (!finite_move(m)) continue;
    const Stroke s = stroke_of(m.kind);
    if (s != run) {
      flush();
      run = s;
    }
    const double x0 = f.px(m.from.z), y0 = f.py(m.from.x);
    const double x1 = f.px(m.to.z), y1 = f.py(m.to.x);
    if (!path.at(x0, y0)) path.move_to(x0, y0);
    if (s != Stroke::kArc) {
      path.line_to(x1, y1);
      continue;
    }
    const ArcSweep a = arc_sweep(m);
    if (a.radius <= 0 || a.sweep == 0) {
      path.line_to(x1, y1);
      continue;
    }
    const double r = a.radius * f.k;
    const bool cw = a.sweep < 0;  // clockwise on the page too (X up, Z right): SVG sweep 1
    if (std::fabs(a.sweep) > std::numbers::pi * 1.999) {
      const Vec2 mid = arc_point(m.center, a.radius, a.start + a.sweep / 2);
      path.arc_to(r, false, cw, f.px(mid.z), f.py(mid.x));
    }
    path.arc_to(
        r, std::fabs(a.sweep) > std::numbers::pi && std::fabs(a.sweep) <= std::numbers::pi * 1.999,
        cw, x1, y1);
  }
  flush();
  w.close();
}

void draw_start(SvgWriter& w, const PathMeasure& pm, const Frame& f) {
  if (!pm.has_start) {
    w.text("text",
           {{"x", svg_num(f.ox + f.w / 2)},
            {"y", svg_num(f.oy + f.h / 2)},
            {"font-size", "18"},
            {"text-anchor", "middle"},
            {"fill", "#888888"}},
           "no moves");
    return;
  }
  w.empty("circle", {{"class", "start"},
                     {"cx", svg_num(f.px(pm.start.z))},
                     {"cy", svg_num(f.py(pm.start.x))},
                     {"r", "5"},
                     {"fill", "#2ca02c"},
                     {"stroke", "#ffffff"},
                     {"stroke-width", "1.5"}});
}

// Whether any section knows its thread's run-in and run-out.
bool any_lead(const std::vector<ThreadSection>* sections) {
  return sections != nullptr && std::any_of(sections->begin(), sections->end(),
                                            [](const ThreadSection& s) { return s.zones.known; });
}

// A band from `a` to `b` along the thread's lead axis, across what its passes span (and 3 px).
void lead_band(SvgWriter& w, const Frame& f, const SectionLead& g, double a, double b,
               const std::string& title) {
  if (a == b) return;
  const double pad = 3 / f.k, lo = g.across_lo - pad, hi = g.across_hi + pad;
  const double z0 = g.along_z ? std::min(a, b) : lo, z1 = g.along_z ? std::max(a, b) : hi;
  const double x0 = g.along_z ? lo : std::min(a, b), x1 = g.along_z ? hi : std::max(a, b);
  w.open("rect", {{"class", "lead-zone"},
                  {"x", svg_num(f.px(z0))},
                  {"y", svg_num(f.py(x1))},
                  {"width", svg_num((z1 - z0) * f.k)},
                  {"height", svg_num((x1 - x0) * f.k)},
                  {"fill", "url(#lead-hatch)"},
                  {"fill-opacity", "0.8"}});
  w.text("title", {}, title);
  w.close();
}

// Every thread's run-in and run-out as hatched bands under the moves (a chain's sections share
// one thread: drawn once).
void draw_lead_zones(SvgWriter& w, const Frame& f, const std::vector<ThreadSection>* sections) {
  if (!any_lead(sections)) return;
  w.open("g", {{"class", "lead-zones"}});
  const SectionLead* last = nullptr;
  for (const ThreadSection& s : *sections) {
    const SectionLead& g = s.zones;
    if (!g.known || (last != nullptr && last->cut_from == g.cut_from && last->cut_to == g.cut_to &&
                     last->run_in == g.run_in))
      continue;
    last = &g;
    if (!g.any) {
      lead_band(w, f, g, g.cut_from, g.cut_to, "no length has the right lead");
      continue;
    }
    lead_band(w, f, g, g.cut_from, g.right_from, "run-in " + svg_num(g.run_in, 3));
    lead_band(w, f, g, g.right_to, g.cut_to, "run-out " + svg_num(g.run_out, 3));
  }
  w.close();
}

void draw_legend(SvgWriter& w, double y, bool lead) {
  double x = kLeft;
  w.open("g", {{"class", "legend"}});
  for (size_t i = 0; i < kClass.size(); ++i) {
    w.empty("line", {{"class", kClass[i]},
                     {"x1", svg_num(x)},
                     {"y1", svg_num(y)},
                     {"x2", svg_num(x + 34)},
                     {"y2", svg_num(y)}});
    static constexpr std::array<const char*, 4> kNames = {"rapid", "feed", "arc (G2/G3)",
                                                          "thread (synchronized)"};
    w.text("text", {{"x", svg_num(x + 40)}, {"y", svg_num(y + 4)}, {"font-size", "13"}}, kNames[i]);
    x += 40 + 7.5 * static_cast<double>(std::string_view(kNames[i]).size()) + 26;
  }
  w.empty("circle", {{"cx", svg_num(x + 6)}, {"cy", svg_num(y)}, {"r", "5"}, {"fill", "#2ca02c"}});
  w.text("text", {{"x", svg_num(x + 16)}, {"y", svg_num(y + 4)}, {"font-size", "13"}}, "start");
  if (lead) {
    x += 16 + 7.5 * 5 + 26;
    w.empty("rect", {{"x", svg_num(x)},
                     {"y", svg_num(y - 7)},
                     {"width", "26"},
                     {"height", "14"},
                     {"fill", "url(#lead-hatch)"},
                     {"stroke", "#555555"}});
    w.text("text", {{"x", svg_num(x + 32)}, {"y", svg_num(y + 4)}, {"font-size", "13"}},
           "lead not yet right (run-in, run-out)");
  }
  w.close();
}

std::string summary(const PathMeasure& t, size_t total, const char* unit) {
  std::string s = fmt::format("{} move{}", total, total == 1 ? "" : "s");
  static constexpr std::array<const char*, 4> kWords = {"rapid", "feed", "arc", "thread"};
  const char* sep = ": ";
  for (size_t i = 0; i < 4; ++i) {
    if (t.moves[i] == 0) continue;
    s += fmt::format("{}{} {} ({} {})", sep, t.moves[i], kWords[i], svg_num(t.length[i], 1), unit);
    sep = ", ";
  }
  return s;
}

// The bounds the frame shows: the moves, fitted to the cutting moves and what is near them
// (`clipped`) when a rapid goes far off, to a tool-change or home position, which would shrink
// the part to a few pixels.
Bounds plot_bounds(const Bounds& all, const Bounds& cut, bool& clipped) {
  Bounds b = all;
  clipped = false;
  if (cut.empty) return b;
  const double margin = 0.25 * std::max({cut.z_hi - cut.z_lo, cut.x_hi - cut.x_lo, 1e-9});
  Bounds near = cut;
  near.z_lo -= margin;
  near.z_hi += margin;
  near.x_lo -= margin;
  near.x_hi += margin;
  if (b.z_lo < near.z_lo || b.z_hi > near.z_hi || b.x_lo < near.x_lo || b.x_hi > near.x_hi) {
    b.z_lo = std::max(b.z_lo, near.z_lo);
    b.z_hi = std::min(b.z_hi, near.z_hi);
    b.x_lo = std::max(b.x_lo, near.x_lo);
    b.x_hi = std::min(b.x_hi, near.x_hi);
    clipped = true;
  }
  return b;
}

// A thread section drawn under the plot, scaled to the width, at `y`.
struct Inset {
  const ThreadSection* s;
  SvgSize size;
  double scale, y;
};

// The insets of `sections` (may be null) one under the other from `height`, which grows by
// them.
std::vector<Inset> section_insets(const std::vector<ThreadSection>* sections, double& height) {
  std::vector<Inset> insets;
  if (sections == nullptr) return insets;
  for (const ThreadSection& s : *sections) {
    const SvgSize size = thread_section_size(s);
    const double scale = std::min(1.0, (kWidth - 32) / size.width);
    insets.push_back({&s, size, scale, height + 12});
    height += 12 + size.height * scale;
  }
  return insets;
}

void draw_insets(SvgWriter& w, const std::vector<Inset>& insets) {
  for (size_t i = 0; i < insets.size(); ++i) {
    const Inset& in = insets[i];
    w.empty("line", {{"x1", "16"},
                     {"y1", svg_num(in.y - 6)},
                     {"x2", svg_num(kWidth - 16)},
                     {"y2", svg_num(in.y - 6)},
                     {"stroke", "#cccccc"}});
    w.open("svg", {{"x", "16"},
                   {"y", svg_num(in.y)},
                   {"width", svg_num(in.size.width * in.scale)},
                   {"height", svg_num(in.size.height * in.scale)},
                   {"viewBox",
                    fmt::format("0 0 {} {}", svg_num(in.size.width), svg_num(in.size.height))}});
    draw_thread_section(w, *in.s, fmt::format("s{}-", i + 1));
    w.close();
  }
}

// A view of the C-axis work (plot/mill_views.h) under the side view: its frame and title line.
struct MillPanel {
  bool peripheral = false;
  const ThinnedPath* path = nullptr;
  const std::vector<Vec2>* holes = nullptr;
  Frame f;
  double top = 0;
};

// A panel's title, its two lines (counts; what was simplified) and the axis title above its frame.
constexpr double kPanelHead = 86;
constexpr double kLabelAt = 1.08;  // the C0 and C90 directions' length, a part of the stock radius

// What a panel's frame shows: its moves (fitted to the cutting ones), holes and stock circle.
Bounds panel_bounds(const MillViewsDrawn& d, const MillPanel& p) {
  Bounds all = p.path->measure.all, cut = p.path->measure.cut;
  std::vector<Vec2> pts = *p.holes;
  const double r = d.stock_radius * kLabelAt * 1.04;  // room for the C0 and C90 labels
  if (!p.peripheral && d.stock_radius > 0) pts.insert(pts.end(), {{-r, -r}, {r, r}});
  for (const Vec2& v : pts) {
    all.add(v);
    cut.add(v);
  }
  // The unrolled view at least half as wide as it is tall: holes at one Z stay readable.
  const double wide = (cut.x_hi - cut.x_lo) / 2 - (cut.z_hi - cut.z_lo);
  if (p.peripheral && !cut.empty && wide > 0) {
    for (Bounds* b : {&all, &cut}) {
      b->add({cut.x_lo, cut.z_lo - wide / 2});
      b->add({cut.x_lo, cut.z_hi + wide / 2});
    }
  }
  bool clipped = false;
  return plot_bounds(all, cut, clipped);
}

// The face view, then the peripheral view, each where there is such work, from `height`,
// which grows by them.
std::vector<MillPanel> mill_panels(const MillViewsDrawn* d, double& height) {
  std::vector<MillPanel> out;
  if (d == nullptr) return out;
  for (const bool peripheral : {false, true}) {
    if (peripheral ? !d->has_peripheral() : !d->has_face()) continue;
    MillPanel p;
    p.peripheral = peripheral;
    p.path = peripheral ? &d->peripheral : &d->face;
    p.holes = peripheral ? &d->radial_holes : &d->face_holes;
    p.top = height + 8;
    p.f = frame_of(panel_bounds(*d, p), p.top + kPanelHead);
    height = p.f.oy + p.f.h + kBelow;
    out.push_back(p);
  }
  return out;
}

// Each hole a circle with a cross (the tool's diameter is not in the program).
void draw_hole_marks(SvgWriter& w, const std::vector<Vec2>& holes, const Frame& f) {
  if (holes.empty()) return;
  w.open("g",
         {{"class", "holes"}, {"fill", "none"}, {"stroke", "#c0392b"}, {"stroke-width", "1.6"}});
  SvgPath cross;
  for (const Vec2& h : holes) {
    const double x = f.px(h.z), y = f.py(h.x);
    w.empty("circle", {{"class", "hole"}, {"cx", svg_num(x)}, {"cy", svg_num(y)}, {"r", "4.5"}});
    cross.move_to(x - 7, y);
    cross.line_to(x + 7, y);
    cross.move_to(x, y - 7);
    cross.line_to(x, y + 7);
  }
  w.empty("path", {{"d", cross.data()}, {"stroke-width", "1"}});
  w.close();
}

// The face view's stock circle and the directions C0 and C90 from the centre.
void draw_face_marks(SvgWriter& w, const MillViewsDrawn& d, const Frame& f) {
  const double r = d.stock_radius > 0 ? d.stock_radius : 10 / f.k;
  if (d.stock_radius > 0)
    w.empty("circle", {{"class", "stock"},
                       {"cx", svg_num(f.px(0))},
                       {"cy", svg_num(f.py(0))},
                       {"r", svg_num(r * f.k)},
                       {"fill", "none"},
                       {"stroke", "#555555"},
                       {"stroke-width", "1.2"},
                       {"stroke-dasharray", "10 4"}});
  SvgPath dirs;
  dirs.move_to(f.px(0), f.py(0));
  dirs.line_to(f.px(r * kLabelAt), f.py(0));
  dirs.move_to(f.px(0), f.py(0));
  dirs.line_to(f.px(0), f.py(r * kLabelAt));
  w.empty("path", {{"class", "c-directions"},
                   {"d", dirs.data()},
                   {"stroke", "#555555"},
                   {"stroke-dasharray", "14 3 3 3"}});
  const SvgAttrs label = {{"font-size", "12"}, {"fill", "#333333"}};
  SvgAttrs a = label;
  a.insert(a.end(), {{"x", svg_num(f.px(r * kLabelAt) + 4)}, {"y", svg_num(f.py(0) + 4)}});
  w.text("text", a, "C0");
  a = label;
  a.insert(a.end(), {{"x", svg_num(f.px(0) + 4)}, {"y", svg_num(f.py(r * kLabelAt) - 4)}});
  w.text("text", a, "C90");
}

// The peripheral view's lines at C0, C90, ... (R * angle), labelled at the left.
void draw_c_lines(SvgWriter& w, double radius, const Frame& f) {
  const double step = radius * std::numbers::pi / 2;
  if (!(step > 0)) return;
  SvgPath lines;
  for (double k = std::ceil(f.x_lo / step); k * step <= f.x_hi; ++k) {
    lines.move_to(f.ox, f.py(k * step));
    lines.line_to(f.ox + f.w, f.py(k * step));
    w.text("text",
           {{"x", svg_num(f.ox + 4)},
            {"y", svg_num(f.py(k * step) - 4)},
            {"font-size", "12"},
            {"fill", "#333333"}},
           fmt::format("C{}", svg_num(k * 90)));
  }
  w.empty("path", {{"class", "c-lines"},
                   {"d", lines.data()},
                   {"stroke", "#555555"},
                   {"stroke-dasharray", "14 3 3 3"}});
}

// The panel's title and its line of counts.
void draw_panel_head(SvgWriter& w, const MillPanel& p, const MillViewsDrawn& d, const char* unit) {
  w.text("text",
         {{"class", "view-title"},
          {"x", "16"},
          {"y", svg_num(p.top + 22)},
          {"font-size", "16"},
          {"font-weight", "bold"}},
         p.peripheral ? fmt::format("Peripheral work, unrolled at radius {} {}: Z across, the arc "
                                    "length at that radius from C0 up",
                                    svg_num(d.unroll_radius, 3), unit)
                      : std::string("Face work, looking along \u2212Z at the part face: the part "
                                    "at C0, X across, Y up"));
  const size_t n = p.holes->size();
  std::string s = p.path->measure.total() > 0
                      ? summary(p.path->measure, p.path->measure.total(), unit) + "; "
                      : std::string();
  s += fmt::format("{} {} hole{} (marks: the tool diameter is not in the program)", n,
                   p.peripheral ? "radial" : "face", n == 1 ? "" : "s");
  if (!p.peripheral && d.stock_radius > 0)
    s += fmt::format("; dashed circle: radius {}, {}", svg_num(d.stock_radius, 3),
                     d.stock_turned ? "the largest turned" : "the work's largest");
  std::string note = p.path->simplified() ? simplified_note(*p.path) : std::string();
  if (d.holes_not_drawn > 0)
    note += fmt::format("{}{} holes past the marks' budget not drawn", note.empty() ? "" : "; ",
                        d.holes_not_drawn);
  w.text("text",
         {{"class", "view-summary"},
          {"x", "16"},
          {"y", svg_num(p.top + 42)},
          {"font-size", "13"},
          {"fill", "#444444"}},
         s);
  if (!note.empty())
    w.text("text",
           {{"class", "note"},
            {"x", "16"},
            {"y", svg_num(p.top + 60)},
            {"font-size", "13"},
            {"font-style", "italic"},
            {"fill", "#444444"}},
           note);
}

void draw_mill_panels(SvgWriter& w, const std::vector<MillPanel>& panels, const MillViewsDrawn* d,
                      const char* unit) {
  for (const MillPanel& p : panels) {
    const std::string up =
        fmt::format("\u2191 R\u00b7C at radius {} ({{}})", svg_num(d->unroll_radius, 3));
    const AxisTitles t = p.peripheral
                             ? AxisTitles{"Z ({}) \u2192", up, false}
                             : AxisTitles{"part X ({}) \u2192", "\u2191 part Y ({})", false};
    w.empty("line", {{"x1", "16"},
                     {"y1", svg_num(p.top)},
                     {"x2", svg_num(kWidth - 16)},
                     {"y2", svg_num(p.top)},
                     {"stroke", "#cccccc"}});
    draw_panel_head(w, p, *d, unit);
    draw_grid(w, p.f, unit, t);
    const std::string clip = p.peripheral ? "peripheral-clip" : "face-clip";
    w.open("clipPath", {{"id", clip}});
    w.empty("rect", {{"x", svg_num(p.f.ox)},
                     {"y", svg_num(p.f.oy)},
                     {"width", svg_num(p.f.w)},
                     {"height", svg_num(p.f.h)}});
    w.close();
    w.open("g", {{"class", p.peripheral ? "peripheral-view" : "face-view"},
                 {"clip-path", fmt::format("url(#{})", clip)}});
    if (p.peripheral)
      draw_c_lines(w, d->unroll_radius, p.f);
    else
      draw_face_marks(w, *d, p.f);
    draw_moves(w, p.path->path.moves, p.f);
    draw_hole_marks(w, *p.holes, p.f);
    w.close();
  }
}

// What one backplot shows: the moves drawn, what all the program's moves measure, a note.
struct View {
  const std::vector<Move>& moves;
  const PathMeasure& measure;
  LengthUnit units;
  const std::vector<ThreadSection>* sections;
  std::string_view title;
  std::string_view note;                 // under the legend, when not empty
  const MillViewsDrawn* mill = nullptr;  // the C-axis work's views, when there is any
};

void draw_header(SvgWriter& w, const View& v, const char* unit, bool clipped, bool lead) {
  w.text("text",
         {{"class", "summary"}, {"x", "16"}, {"y", "54"}, {"font-size", "13"}, {"fill", "#444444"}},
         summary(v.measure, v.measure.total(), unit) +
             (clipped ? "; fitted to the cutting moves, far rapids run off the frame" : ""));
  draw_legend(w, 78, lead);
  if (!v.note.empty())
    w.text("text",
           {{"class", "note"},
            {"x", "16"},
            {"y", "102"},
            {"font-size", "13"},
            {"font-style", "italic"},
            {"fill", "#444444"}},
           v.note);
}

std::string render(const View& v) {
  const char* unit = v.units == LengthUnit::kInch ? "in" : "mm";
  bool clipped = false;
  Frame f = frame_of(plot_bounds(v.measure.all, v.measure.cut, clipped),
                     v.note.empty() ? kTop : kTop + kNoteH);
  double height = f.oy + f.h + kBelow;
  const std::vector<MillPanel> panels = mill_panels(v.mill, height);
  const std::vector<Inset> insets = section_insets(v.sections, height);
  SvgWriter w(kWidth, height);
  draw_style(w);
  w.empty("rect", {{"width", svg_num(kWidth)}, {"height", svg_num(height)}, {"fill", "#ffffff"}});
  w.text(
      "text",
      {{"class", "title"}, {"x", "16"}, {"y", "30"}, {"font-size", "20"}, {"font-weight", "bold"}},
      v.title.empty() ? std::string_view("Backplot") : v.title);
  draw_grid(w, f, unit);
  w.open("clipPath", {{"id", "plot-clip"}});
  w.empty("rect", {{"x", svg_num(f.ox)},
                   {"y", svg_num(f.oy)},
                   {"width", svg_num(f.w)},
                   {"height", svg_num(f.h)}});
  w.close();
  const bool lead = any_lead(v.sections);
  if (lead) lead_hatch_pattern(w, "lead-hatch", "#6f6f6f", "1.2");
  w.open("g", {{"clip-path", "url(#plot-clip)"}});
  draw_lead_zones(w, f, v.sections);
  draw_moves(w, v.moves, f);
  draw_start(w, v.measure, f);
  w.close();
  draw_header(w, v, unit, clipped, lead);
  draw_mill_panels(w, panels, v.mill, unit);
  draw_insets(w, insets);
  return w.finish();
}

}  // namespace

double backplot_scale(const Bounds& all, const Bounds& cut) {
  bool clipped = false;
  return frame_of(plot_bounds(all, cut, clipped)).k;
}

std::string milling_note(size_t milling) {
  if (milling == 0) return {};
  return fmt::format("{} move{} of the C-axis work drawn in the views below, not here", milling,
                     milling == 1 ? "" : "s");
}

std::string backplot_svg(const Toolpath& tp, const std::vector<ThreadSection>* sections,
                         std::string_view title, const MillViewsDrawn* mill,
                         std::string_view note) {
  PathMeasure pm;
  for (const Move& m : tp.moves) pm.add(m);
  return render({tp.moves, pm, tp.units, sections, title, note,
                 mill != nullptr && mill->any() ? mill : nullptr});
}

std::string backplot_svg(const ThinnedPath& path, const std::vector<ThreadSection>* sections,
                         std::string_view title, std::string_view note,
                         const MillViewsDrawn* mill) {
  return render({path.path.moves, path.measure, path.path.units, sections, title, note,
                 mill != nullptr && mill->any() ? mill : nullptr});
}

}  // namespace clpost

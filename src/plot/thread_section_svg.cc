#include "plot/thread_section_svg.h"

#include <fmt/format.h>

#include <algorithm>
#include <cmath>
#include <initializer_list>
#include <map>
#include <string>
#include <tuple>
#include <vector>

#include "planner/plan_format.h"
#include "plot/nice_step.h"
#include "plot/thread_profile.h"

namespace clpost {
namespace {

constexpr double kAreaX = 100;  // left edge of the drawing (the depth ruler is left of it)
constexpr double kAreaY = 78;   // top of the drawing
constexpr double kAreaW = 560;  // room for the drawing
constexpr double kAreaH = 400;
constexpr double kMinAreaH = 220;  // flatter sections get more part and air, never distortion
constexpr double kTableGap = 56;   // drawing to table
constexpr double kTableW = 372;
constexpr double kRowH = 17;
constexpr double kBelowArea = 92;   // scale bar and legend under the drawing
constexpr double kLeadStripH = 66;  // the run-in and run-out along the thread, at the bottom
constexpr const char* kMono = "DejaVu Sans Mono, Consolas, monospace";

const char* kind_colour(PassKind k) {
  switch (k) {
    case PassKind::kRough:
      return "#1f5fbf";
    case PassKind::kFinish:
      return "#d62728";
    case PassKind::kSpring:
      return "#2ca02c";
  }
  return "#1f5fbf";
}

// Dash pattern of start k's V ("" = solid).
const char* start_dash(int k) {
  static constexpr const char* kDashes[] = {"", "7 4", "2 3", "10 3 2 3"};
  return kDashes[static_cast<size_t>(std::max(k, 0)) % 4];
}

// The tip marker of start k (circle, square, triangle, diamond) centred on (x, y) as path data.
std::string start_marker(int k, double x, double y) {
  SvgPath p;
  const double r = 3.6;
  switch (std::max(k, 0) % 4) {
    case 0:
      p.move_to(x - r, y);
      p.arc_to(r, false, true, x + r, y);
      p.arc_to(r, false, true, x - r, y);
      break;
    case 1:
      p.move_to(x - r, y - r);
      p.line_to(x + r, y - r);
      p.line_to(x + r, y + r);
      p.line_to(x - r, y + r);
      break;
    case 2:
      p.move_to(x, y - r * 1.2);
      p.line_to(x + r * 1.1, y + r * 0.8);
      p.line_to(x - r * 1.1, y + r * 0.8);
      break;
    default:
      p.move_to(x, y - r * 1.3);
      p.line_to(x + r, y);
      p.line_to(x, y + r * 1.3);
      p.line_to(x - r, y);
      break;
  }
  p.close_path();
  return p.data();
}

struct Box {
  double x0, y0, x1, y1;
  bool overlaps(const Box& o) const { return x0 < o.x1 && o.x0 < x1 && y0 < o.y1 && o.y0 < y1; }
};

// Where the section's model lands on the page. Section coordinates (u, d): thread_profile.h.
struct Frame {
  double ox = kAreaX, oy = kAreaY;  // top-left of the drawing
  double w = 0, h = 0;              // its size in px
  double k = 1;                     // px per unit
  double u_lo = 0, u_hi = 1;        // model window along u
  double d_top = 0;                 // depth at the top edge (external) or bottom edge (internal)
  double d_bottom = 0;              // depth at the other edge
  bool internal = false;
  double x(double u) const { return ox + (u - u_lo) * k; }
  double y(double d) const { return internal ? oy + h - (d - d_top) * k : oy + (d - d_top) * k; }
};

struct Layout {
  Frame f;
  double table_x = 0;
  double width = 0;
  double height = 0;
  int decimals = 3;
  const char* unit = "mm";
  double strip_y = 0;  // top of the lead strip (when the section's lead is known)
};

Layout layout_of(const ThreadSection& s) {
  Layout l;
  l.decimals = s.units == LengthUnit::kInch ? 4 : 3;
  l.unit = s.units == LengthUnit::kInch ? "in" : "mm";
  Frame& f = l.f;
  f.internal = s.side == ThreadSide::kInternal;
  const double tn = half_angle_tan(s);
  const double pitch = groove_pitch(s);
  // The deepest point drawn: D or the deepest pass, whichever is more.
  double dv = std::isfinite(s.depth) ? std::fabs(s.depth) : 0;
  for (const SectionPoint& t : cutting_tips(s)) dv = std::max(dv, std::fabs(t.d));
  if (dv <= 0) dv = pitch / (2 * tn);
  // Centre of the first groove: the middle of its Vs at the surface.
  double lo = 0, hi = 0;
  bool any = false;
  for (const SectionPass& p : s.passes) {
    if (!drawable(p) || std::clamp(p.start, 0, 23) != 0) continue;
    const double a = p.shift - std::fabs(p.depth) * tn, b = p.shift + std::fabs(p.depth) * tn;
    lo = any ? std::min(lo, a) : a;
    hi = any ? std::max(hi, b) : b;
    any = true;
  }
  const double c0 = any ? (lo + hi) / 2 : 0;
  f.u_lo = c0 - pitch;
  f.u_hi = c0 + groove_count(s) * pitch;
  // Air above the surface for the tool, part under the deepest point.
  double air = 0.5 * dv, part = 0.35 * dv;
  f.k = std::min(kAreaW / (f.u_hi - f.u_lo), kAreaH / (air + dv + part));
  const double need = kMinAreaH / f.k - (air + dv + part);
  if (need > 0) {
    air += need / 2;
    part += need / 2;
  }
  f.d_top = -air;
  f.d_bottom = dv + part;
  f.w = (f.u_hi - f.u_lo) * f.k;
  f.h = (f.d_bottom - f.d_top) * f.k;
  l.table_x = f.ox + f.w + kTableGap;
  l.width = l.table_x + kTableW + 16;
  const double table_bottom = f.oy + 44 + static_cast<double>(s.passes.size()) * kRowH + 24;
  l.height = std::max(f.oy + f.h + kBelowArea, table_bottom);
  if (s.zones.known) {
    l.strip_y = l.height;
    l.height += kLeadStripH;
  }
  return l;
}

// Text with a white halo so it stays readable over lines and hatching.
SvgAttrs halo(SvgAttrs a) {
  a.emplace_back("stroke", "#ffffff");
  a.emplace_back("stroke-width", "3");
  a.emplace_back("stroke-linejoin", "round");
  a.emplace_back("paint-order", "stroke");
  return a;
}

void draw_part(SvgWriter& w, const ThreadSection& s, const Frame& f, std::string_view id) {
  const std::vector<SectionPoint> prof = cut_profile(s, f.u_lo, f.u_hi);
  SvgPath part, edge;
  for (const SectionPoint& q : prof) {
    part.line_to(f.x(q.u), f.y(q.d));
    edge.line_to(f.x(q.u), f.y(q.d));
  }
  part.line_to(f.x(f.u_hi), f.y(f.d_bottom));
  part.line_to(f.x(f.u_lo), f.y(f.d_bottom));
  part.close_path();
  w.empty("path",
          {{"class", "part"}, {"d", part.data()}, {"fill", fmt::format("url(#{}hatch)", id)}});
  w.empty("path", {{"class", "profile"},
                   {"d", edge.data()},
                   {"fill", "none"},
                   {"stroke", "#333333"},
                   {"stroke-width", "1.6"},
                   {"stroke-linejoin", "round"}});
}

// The plunge line of every groove (shift 0: the shifts are measured from it) and a dashed line
// at the full depth D.
void draw_references(SvgWriter& w, const ThreadSection& s, const Frame& f) {
  SvgPath plunge;
  for (int k = 0; k < groove_count(s); ++k) {
    const double x = f.x(k * groove_pitch(s));
    plunge.move_to(x, f.y(f.d_top));
    plunge.line_to(x, f.y(f.d_bottom));
  }
  w.empty("path", {{"class", "plunge-line"},
                   {"d", plunge.data()},
                   {"stroke", "#777777"},
                   {"stroke-width", "0.8"},
                   {"stroke-dasharray", "1 3"}});
  if (!std::isfinite(s.depth) || s.depth <= 0) return;
  const double y = f.y(s.depth);
  w.empty("line", {{"class", "full-depth"},
                   {"x1", svg_num(f.x(f.u_lo))},
                   {"y1", svg_num(y)},
                   {"x2", svg_num(f.x(f.u_hi))},
                   {"y2", svg_num(y)},
                   {"stroke", "#555555"},
                   {"stroke-width", "1"},
                   {"stroke-dasharray", "8 3 2 3"}});
}

// One pass's V from the tip up into the air above the surface, with its tip marker.
void draw_pass(SvgWriter& w, const ThreadSection& s, const Frame& f, const SectionPass& p,
               int decimals) {
  const double tn = half_angle_tan(s);
  const SectionPoint t = pass_tip(s, p);
  const double reach = t.d - f.d_top;  // tip to the edge of the drawing on the air side
  SvgPath v;
  v.move_to(f.x(t.u - reach * tn), f.y(f.d_top));
  v.line_to(f.x(t.u), f.y(t.d));
  v.line_to(f.x(t.u + reach * tn), f.y(f.d_top));
  const bool spring = p.kind == PassKind::kSpring;
  w.open("g", {{"class", "pass"},
               {"data-pass", fmt::format("{}", p.n)},
               {"data-start", fmt::format("{}", p.start)},
               {"data-kind", pass_kind_name(p.kind)}});
  w.text("title", {},
         fmt::format("pass {}, start {}: depth {}, shift {} ({})", p.n, p.start,
                     fixed_text(p.depth, decimals), fixed_text(p.shift, decimals),
                     pass_kind_name(p.kind)));
  SvgAttrs a = {{"d", v.data()},
                {"fill", "none"},
                {"stroke", kind_colour(p.kind)},
                {"stroke-width", spring                        ? "6"
                                 : p.kind == PassKind::kFinish ? "2"
                                                               : "1.4"},
                {"stroke-linejoin", "round"}};
  if (spring) a.emplace_back("stroke-opacity", "0.35");
  if (*start_dash(p.start) != '\0' && !spring)
    a.emplace_back("stroke-dasharray", start_dash(p.start));
  w.empty("path", a);
  if (!spring)
    w.empty("path", {{"d", start_marker(p.start, f.x(t.u), f.y(t.d))},
                     {"fill", kind_colour(p.kind)},
                     {"stroke", "#ffffff"},
                     {"stroke-width", "0.8"}});
  w.close();
}

// Pass numbers next to the tips; passes that share a tip share a label. Greedy placement: the
// first of a few spots around the tip that overlaps no earlier label and no tip marker.
void draw_tip_labels(SvgWriter& w, const ThreadSection& s, const Frame& f) {
  struct Tip {
    double x, y;
    std::string text;
    PassKind kind;
  };
  std::vector<Tip> tips;
  for (const SectionPass& p : s.passes) {
    if (!drawable(p)) continue;
    const SectionPoint t = pass_tip(s, p);
    const double x = f.x(t.u), y = f.y(t.d);
    auto same = std::find_if(tips.begin(), tips.end(), [&](const Tip& o) {
      return std::fabs(o.x - x) < 0.75 && std::fabs(o.y - y) < 0.75;
    });
    if (same == tips.end()) {
      tips.push_back({x, y, fmt::format("{}", p.n), p.kind});
    } else if (same->text.size() < 24) {
      same->text += fmt::format(",{}", p.n);
    }
  }
  std::vector<Box> taken;
  for (const Tip& t : tips) taken.push_back({t.x - 4.5, t.y - 4.5, t.x + 4.5, t.y + 4.5});
  const double out = f.internal ? -1 : 1;  // +1: "below" the tip is deeper into the part
  for (const Tip& t : tips) {
    const double tw = 7.2 * static_cast<double>(t.text.size()), th = 12;
    struct Spot {
      double dx, dy;  // from the tip to the text box's top-left
    };
    // Vertical offsets of a box `gap` px deeper into the part / further into the air.
    const double deeper = out > 0 ? 5 : -5 - th, shallower = out > 0 ? -5 - th : 5;
    const Spot spots[] = {{7, -th / 2},      {-7 - tw, -th / 2},          {7, deeper},
                          {-7 - tw, deeper}, {-tw / 2, deeper + 2 * out}, {7, shallower}};
    Box chosen{t.x + spots[0].dx, t.y + spots[0].dy, t.x + spots[0].dx + tw,
               t.y + spots[0].dy + th};
    for (const Spot& sp : spots) {
      const Box b{t.x + sp.dx, t.y + sp.dy, t.x + sp.dx + tw, t.y + sp.dy + th};
      if (std::none_of(taken.begin(), taken.end(), [&](const Box& o) { return o.overlaps(b); })) {
        chosen = b;
        break;
      }
    }
    taken.push_back(chosen);
    w.text("text",
           halo({{"class", "tip-label"},
                 {"x", svg_num(chosen.x0)},
                 {"y", svg_num(chosen.y1 - 2)},
                 {"font-size", "12"},
                 {"font-weight", "bold"},
                 {"fill", kind_colour(t.kind)}}),
           t.text);
  }
}

// Depth ruler left of the drawing: 0 at the surface, D, and the pass depths where they fit.
void draw_depth_ruler(SvgWriter& w, const ThreadSection& s, const Frame& f, int decimals) {
  const double x = f.ox - 8;
  std::vector<double> depths;
  for (const SectionPass& p : s.passes)
    if (drawable(p)) depths.push_back(p.depth);
  const bool has_d = std::isfinite(s.depth) && s.depth > 0;
  double deepest = has_d ? s.depth : 0;
  for (double d : depths) deepest = std::max(deepest, d);
  w.empty("line", {{"x1", svg_num(x)},
                   {"y1", svg_num(f.y(0))},
                   {"x2", svg_num(x)},
                   {"y2", svg_num(f.y(deepest))},
                   {"stroke", "#444444"},
                   {"stroke-width", "1"}});
  std::vector<double> labelled;
  auto tick = [&](double d, bool bold, std::string text) {
    const double y = f.y(d);
    w.empty("line", {{"x1", svg_num(x - (bold ? 7 : 4))},
                     {"y1", svg_num(y)},
                     {"x2", svg_num(x)},
                     {"y2", svg_num(y)},
                     {"stroke", "#444444"},
                     {"stroke-width", "1"}});
    if (std::any_of(labelled.begin(), labelled.end(),
                    [&](double o) { return std::fabs(o - y) < 12; }))
      return;
    labelled.push_back(y);
    SvgAttrs a = {{"class", "depth-label"}, {"x", svg_num(x - 10)}, {"y", svg_num(y + 4)},
                  {"font-size", "11"},      {"text-anchor", "end"}, {"fill", "#333333"}};
    if (bold) a.emplace_back("font-weight", "bold");
    w.text("text", a, text);
  };
  tick(0, false, "0");
  if (has_d) tick(s.depth, true, "D " + fixed_text(s.depth, decimals));
  for (double d : depths) tick(d, false, fixed_text(d, decimals));
  w.text("text",
         {{"x", svg_num(x - 10)},
          {"y", svg_num(f.internal ? f.y(deepest) - 10 : f.y(0) - 10)},
          {"font-size", "11"},
          {"text-anchor", "end"},
          {"fill", "#666666"}},
         fmt::format("depth ({})", s.units == LengthUnit::kInch ? "in" : "mm"));
}

// The pass table's number columns, each right-aligned at `right` from the table's left edge;
// the pass kind follows, left-aligned at kKindX.
struct TableCol {
  const char* name;
  double right;
};
constexpr TableCol kTableCols[] = {
    {"pass", 36}, {"start", 84}, {"depth", 158}, {"step", 232}, {"shift", 306}};
constexpr double kKindX = 320;

// The table's title, its column names and the rule under them; returns the rule's y, where the
// rows start.
double draw_table_head(SvgWriter& w, double x, double top, const char* unit) {
  w.text(
      "text",
      {{"x", svg_num(x)}, {"y", svg_num(top + 10)}, {"font-size", "13"}, {"font-weight", "bold"}},
      fmt::format("Passes in cutting order ({})", unit));
  const double head_y = top + 34;
  for (const TableCol& c : kTableCols)
    w.text("text",
           {{"x", svg_num(x + c.right)},
            {"y", svg_num(head_y)},
            {"font-size", "12"},
            {"text-anchor", "end"},
            {"font-weight", "bold"},
            {"fill", "#444444"}},
           c.name);
  w.text("text",
         {{"x", svg_num(x + kKindX)},
          {"y", svg_num(head_y)},
          {"font-size", "12"},
          {"font-weight", "bold"},
          {"fill", "#444444"}},
         "kind");
  w.empty("line", {{"x1", svg_num(x)},
                   {"y1", svg_num(head_y + 5)},
                   {"x2", svg_num(x + kTableW)},
                   {"y2", svg_num(head_y + 5)},
                   {"stroke", "#888888"},
                   {"stroke-width", "1"}});
  return head_y + 5;
}

// One pass's row, its top at `y`: its numbers, the step from `prev` (the depth of the pass
// before it of the same start) and its kind; `shaded` on every other row.
void draw_table_row(SvgWriter& w, const SectionPass& p, double prev, double x, double y,
                    bool shaded, int decimals) {
  if (shaded)
    w.empty("rect", {{"x", svg_num(x)},
                     {"y", svg_num(y)},
                     {"width", svg_num(kTableW)},
                     {"height", svg_num(kRowH)},
                     {"fill", "#f1f3f6"}});
  const double base = y + kRowH - 4.5;
  const std::string cells[] = {fmt::format("{}", p.n), fmt::format("{}", p.start),
                               fixed_text(p.depth, decimals), fixed_text(p.depth - prev, decimals),
                               fixed_text(p.shift, decimals)};
  w.open("g", {{"class", "pass-row"}, {"data-pass", fmt::format("{}", p.n)}});
  for (size_t i = 0; i < 5; ++i)
    w.text("text",
           {{"x", svg_num(x + kTableCols[i].right)}, {"y", svg_num(base)}, {"text-anchor", "end"}},
           cells[i]);
  w.text("text",
         {{"x", svg_num(x + kKindX)},
          {"y", svg_num(base)},
          {"fill", kind_colour(p.kind)},
          {"font-weight", "bold"}},
         pass_kind_name(p.kind));
  w.close();
}

void draw_table(SvgWriter& w, const ThreadSection& s, const Layout& l) {
  double y = draw_table_head(w, l.table_x, l.f.oy, l.unit);
  std::map<int, double> last;  // previous depth per start, for the step column
  size_t row = 0;
  w.open("g", {{"class", "pass-table"}, {"font-family", kMono}, {"font-size", "12"}});
  for (const SectionPass& p : s.passes) {
    const double prev = last.count(p.start) ? last[p.start] : 0;
    last[p.start] = p.depth;
    draw_table_row(w, p, prev, l.table_x, y, row++ % 2 == 0, l.decimals);
    y += kRowH;
  }
  w.close();
}

void draw_scale_bar(SvgWriter& w, const Frame& f, const char* unit) {
  const double len = nice_floor((f.u_hi - f.u_lo) / 4);
  const double x0 = f.ox, x1 = f.ox + len * f.k, y = f.oy + f.h + 28;
  SvgPath p;
  p.move_to(x0, y - 5);
  p.line_to(x0, y);
  p.line_to(x1, y);
  p.line_to(x1, y - 5);
  w.empty("path", {{"class", "scale-bar"},
                   {"d", p.data()},
                   {"fill", "none"},
                   {"stroke", "#222222"},
                   {"stroke-width", "1.5"}});
  w.text("text", {{"x", svg_num(x1 + 8)}, {"y", svg_num(y + 4)}, {"font-size", "12"}},
         fmt::format("{} {}", svg_num(len, 6), unit));
  w.text("text",
         {{"x", svg_num(f.ox + f.w)},
          {"y", svg_num(y + 4)},
          {"font-size", "12"},
          {"text-anchor", "end"},
          {"fill", "#555555"}},
         "cutting direction \u2192   spindle axis \u2193");
}

void draw_legend(SvgWriter& w, const ThreadSection& s, const Frame& f, std::string_view id) {
  double x = f.ox;
  const double y = f.oy + f.h + 62;
  auto label = [&](std::string_view text) {
    w.text("text", {{"x", svg_num(x)}, {"y", svg_num(y + 4)}, {"font-size", "12"}}, text);
    x += 7.0 * static_cast<double>(text.size()) + 18;
  };
  w.open("g", {{"class", "legend"}});
  w.empty("rect", {{"x", svg_num(x)},
                   {"y", svg_num(y - 7)},
                   {"width", "22"},
                   {"height", "14"},
                   {"fill", fmt::format("url(#{}hatch)", id)},
                   {"stroke", "#333333"}});
  x += 28;
  label("part");
  w.empty("line", {{"x1", svg_num(x)},
                   {"y1", svg_num(y - 8)},
                   {"x2", svg_num(x)},
                   {"y2", svg_num(y + 8)},
                   {"stroke", "#777777"},
                   {"stroke-dasharray", "1 3"}});
  x += 8;
  label("shift 0");
  for (PassKind k : {PassKind::kRough, PassKind::kFinish, PassKind::kSpring}) {
    if (!s.passes.empty() && std::none_of(s.passes.begin(), s.passes.end(),
                                          [&](const SectionPass& p) { return p.kind == k; }))
      continue;
    const bool spring = k == PassKind::kSpring;
    w.empty("line", {{"x1", svg_num(x)},
                     {"y1", svg_num(y)},
                     {"x2", svg_num(x + 26)},
                     {"y2", svg_num(y)},
                     {"stroke", kind_colour(k)},
                     {"stroke-width", spring ? "6" : "2"},
                     {"stroke-opacity", spring ? "0.35" : "1"}});
    x += 32;
    label(pass_kind_name(k));
  }
  if (groove_count(s) > 1) {
    for (int k = 0; k < std::min(groove_count(s), 8); ++k) {
      SvgAttrs a = {{"x1", svg_num(x)}, {"y1", svg_num(y)},    {"x2", svg_num(x + 30)},
                    {"y2", svg_num(y)}, {"stroke", "#333333"}, {"stroke-width", "1.4"}};
      if (*start_dash(k) != '\0') a.emplace_back("stroke-dasharray", start_dash(k));
      w.empty("line", a);
      w.empty("path", {{"d", start_marker(k, x + 15, y)}, {"fill", "#333333"}});
      x += 36;
      label(fmt::format("start {}", k));
    }
  }
  w.close();
}

// The strip's line of text: the two lengths, the speed and where the lead is right.
std::string lead_text(const SectionLead& g, int decimals, const char* unit) {
  const char* axis = g.along_z ? "Z" : "X";
  std::string t = fmt::format("lead not yet right ({}): run-in {}, run-out {} at {} rpm; ", unit,
                              fixed_text(g.run_in, decimals), fixed_text(g.run_out, decimals),
                              svg_num(g.rpm, 1));
  if (!g.any) return t + "no length has the right lead";
  return t + fmt::format("right from {} {} to {} {}", axis, fixed_text(g.right_from, decimals),
                         axis, fixed_text(g.right_to, decimals));
}

// A hatched stretch of the strip's bar, from page x `a` to `b`.
void lead_zone(SvgWriter& w, std::string_view cls, double a, double b, double y,
               std::string_view id, const std::string& title) {
  if (!(b > a)) return;
  w.open("rect", {{"class", std::string(cls)},
                  {"x", svg_num(a)},
                  {"y", svg_num(y)},
                  {"width", svg_num(b - a)},
                  {"height", "16"},
                  {"fill", fmt::format("url(#{}lead)", id)}});
  w.text("title", {}, title);
  w.close();
}

// Under everything: the synchronized cut as a bar from its start (left) to its end, the run-in
// and run-out hatched, with the lead-axis coordinates where they end.
void draw_lead_strip(SvgWriter& w, const ThreadSection& s, const Layout& l, std::string_view id) {
  const SectionLead& g = s.zones;
  if (!g.known) return;
  const double x0 = 16, x1 = l.width - 16, top = l.strip_y, bar = top + 24;
  const double len = std::fabs(g.cut_to - g.cut_from), dir = g.cut_to < g.cut_from ? -1 : 1;
  auto at = [&](double v) {
    return len > 0 ? x0 + std::clamp((v - g.cut_from) * dir, 0.0, len) * (x1 - x0) / len : x0;
  };
  w.open("g", {{"class", "lead-strip"}});
  w.empty("rect", {{"x", svg_num(x0)},
                   {"y", svg_num(top)},
                   {"width", "22"},
                   {"height", "14"},
                   {"fill", fmt::format("url(#{}lead)", id)},
                   {"stroke", "#555555"}});
  w.text("text", {{"x", svg_num(x0 + 30)}, {"y", svg_num(top + 12)}, {"font-size", "13"}},
         lead_text(g, l.decimals, l.unit));
  w.empty("rect", {{"class", "lead-cut"},
                   {"x", svg_num(x0)},
                   {"y", svg_num(bar)},
                   {"width", svg_num(x1 - x0)},
                   {"height", "16"},
                   {"fill", "#ffffff"}});
  if (g.any) {
    lead_zone(w, "lead-run-in", x0, at(g.right_from), bar, id,
              "run-in " + fixed_text(g.run_in, l.decimals));
    lead_zone(w, "lead-run-out", at(g.right_to), x1, bar, id,
              "run-out " + fixed_text(g.run_out, l.decimals));
  } else {
    lead_zone(w, "lead-none", x0, x1, bar, id, "no length has the right lead");
  }
  w.empty("rect", {{"x", svg_num(x0)},
                   {"y", svg_num(bar)},
                   {"width", svg_num(x1 - x0)},
                   {"height", "16"},
                   {"fill", "none"},
                   {"stroke", "#555555"}});
  // The coordinates under the bar: its ends, and where the lead is right when there is room.
  auto label = [&](double x, double v, const char* anchor) {
    w.text("text",
           {{"x", svg_num(x)},
            {"y", svg_num(bar + 30)},
            {"font-size", "11"},
            {"text-anchor", anchor},
            {"fill", "#333333"}},
           fmt::format("{} {}", g.along_z ? "Z" : "X", fixed_text(v, l.decimals)));
  };
  label(x0, g.cut_from, "start");
  label(x1, g.cut_to, "end");
  const double a = at(g.right_from), b = at(g.right_to);
  if (g.any && a - x0 >= 90 && x1 - a >= 90) label(a, g.right_from, "middle");
  if (g.any && b - x0 >= 90 && x1 - b >= 90 && b - a >= 90) label(b, g.right_to, "middle");
  w.close();
}

std::string subtitle(const ThreadSection& s, int decimals, const char* unit) {
  std::string t = fmt::format("{} thread, pitch {} {}",
                              s.side == ThreadSide::kInternal ? "internal" : "external",
                              svg_num(s.pitch, 6), unit);
  if (s.starts > 1) t += fmt::format(", lead {}, {} starts", svg_num(s.lead, 6), s.starts);
  t += fmt::format(", depth D {}, tool {}\u00b0, {} pass{}", fixed_text(s.depth, decimals),
                   svg_num(s.tool_angle, 3), s.passes.size(), s.passes.size() == 1 ? "" : "es");
  return t;
}

// The section's clip path, the part's hatch and the lead hatch, ids prefixed with `id`.
void draw_defs(SvgWriter& w, const ThreadSection& s, const Frame& f, std::string_view id) {
  w.open("defs");
  w.open("clipPath", {{"id", fmt::format("{}clip", id)}});
  w.empty("rect", {{"x", svg_num(f.ox)},
                   {"y", svg_num(f.oy)},
                   {"width", svg_num(f.w)},
                   {"height", svg_num(f.h)}});
  w.close();
  w.open("pattern", {{"id", fmt::format("{}hatch", id)},
                     {"patternUnits", "userSpaceOnUse"},
                     {"width", "7"},
                     {"height", "7"},
                     {"patternTransform", "rotate(45)"}});
  w.empty("rect", {{"width", "7"}, {"height", "7"}, {"fill", "#ebe8e1"}});
  w.empty("line", {{"x1", "0"},
                   {"y1", "0"},
                   {"x2", "0"},
                   {"y2", "7"},
                   {"stroke", "#b7b0a2"},
                   {"stroke-width", "1.2"}});
  w.close();
  // Slanted against the part's hatch.
  if (s.zones.known) lead_hatch_pattern(w, fmt::format("{}lead", id), "#5f5f5f", "1.4");
  w.close();
}

}  // namespace

SvgSize thread_section_size(const ThreadSection& section) {
  const Layout l = layout_of(section);
  return {l.width, l.height};
}

void draw_thread_section(SvgWriter& w, const ThreadSection& s, std::string_view id) {
  const Layout l = layout_of(s);
  const Frame& f = l.f;
  w.open("g", {{"class", "thread-section"}});
  w.empty("rect",
          {{"width", svg_num(l.width)}, {"height", svg_num(l.height)}, {"fill", "#ffffff"}});
  w.text(
      "text",
      {{"class", "title"}, {"x", "16"}, {"y", "28"}, {"font-size", "19"}, {"font-weight", "bold"}},
      s.title);
  w.text(
      "text",
      {{"class", "subtitle"}, {"x", "16"}, {"y", "50"}, {"font-size", "13"}, {"fill", "#444444"}},
      subtitle(s, l.decimals, l.unit));
  draw_defs(w, s, f, id);
  w.open("g", {{"clip-path", fmt::format("url(#{}clip)", id)}});
  draw_part(w, s, f, id);
  draw_references(w, s, f);
  // Spring passes first: they are drawn wide and pale under the finish pass they repeat.
  for (const SectionPass& p : s.passes)
    if (drawable(p) && p.kind == PassKind::kSpring) draw_pass(w, s, f, p, l.decimals);
  for (const SectionPass& p : s.passes)
    if (drawable(p) && p.kind != PassKind::kSpring) draw_pass(w, s, f, p, l.decimals);
  w.close();
  w.empty("rect", {{"x", svg_num(f.ox)},
                   {"y", svg_num(f.oy)},
                   {"width", svg_num(f.w)},
                   {"height", svg_num(f.h)},
                   {"fill", "none"},
                   {"stroke", "#999999"},
                   {"stroke-width", "1"}});
  draw_tip_labels(w, s, f);
  draw_depth_ruler(w, s, f, l.decimals);
  draw_table(w, s, l);
  draw_scale_bar(w, f, l.unit);
  draw_legend(w, s, f, id);
  draw_lead_strip(w, s, l, id);
  w.close();
}

std::string thread_section_svg(const ThreadSection& section) {
  const SvgSize size = thread_section_size(section);
  SvgWriter w(size.width, size.height);
  draw_thread_section(w, section, "ts-");
  return w.finish();
}

}  // namespace clpost

// The backplot: one <path> per run of one kind of move, to scale, arcs as arcs, and a valid
// document for empty, hostile and very long programs.
#include "plot/backplot_svg.h"

#include <gtest/gtest.h>

#include <algorithm>
#include <cmath>
#include <numbers>
#include <string>
#include <vector>

#include "plot/move_geometry.h"
#include "plot/svg_test_util.h"

namespace clpost {
namespace {

using testing::check_xml;
using testing::count_of;
using testing::numbers_in;
using testing::parsed;
using testing::XmlDoc;

Move mv(MoveKind k, Vec2 from, Vec2 to, Vec2 center = {}) {
  Move m;
  m.kind = k;
  m.from = from;
  m.to = to;
  m.center = center;
  return m;
}

// A little turned part with one threading pass (x radius, z axis):
//   rapid (20,5)->(10,1), rapid ->(10,0.5)      one rapid run
//   feed ->(10,-20), feed ->(12,-20)            one feed run
//   arc G2 ->(14,-22) centre (14,-20)           concave quarter, clockwise (Z right, X up)
//   feed ->(14,-30)                             second feed run
//   rapid ->(20,5)                              second rapid run
//   rapid ->(9.2,2)                             (joined to the previous rapid)
//   thread ->(9.2,-18), thread ->(10,-19)       thread run with the pull-out
//   rapid ->(20,5)                              third rapid run
Toolpath small_part() {
  Toolpath tp;
  tp.moves = {mv(MoveKind::kRapid, {20, 5}, {10, 1}),
              mv(MoveKind::kRapid, {10, 1}, {10, 0.5}),
              mv(MoveKind::kFeed, {10, 0.5}, {10, -20}),
              mv(MoveKind::kFeed, {10, -20}, {12, -20}),
              mv(MoveKind::kArcCw, {12, -20}, {14, -22}, {14, -20}),
              mv(MoveKind::kFeed, {14, -22}, {14, -30}),
              mv(MoveKind::kRapid, {14, -30}, {20, 5}),
              mv(MoveKind::kRapid, {20, 5}, {9.2, 2}),
              mv(MoveKind::kThread, {9.2, 2}, {9.2, -18}),
              mv(MoveKind::kThread, {9.2, -18}, {10, -19}),
              mv(MoveKind::kRapid, {10, -19}, {20, 5})};
  for (Move& m : tp.moves)
    if (m.kind == MoveKind::kThread) m.lead = 1.5;
  return tp;
}

TEST(BackplotSvg, OnePathPerRunOfOneKind) {
  const XmlDoc d = parsed(backplot_svg(small_part(), nullptr, "part.nc"));
  // <path> elements only: the legend draws its samples as <line>s with the same classes.
  EXPECT_EQ(d.with_class("rapid", "path").size(), 3u);
  EXPECT_EQ(d.with_class("feed", "path").size(), 2u);
  EXPECT_EQ(d.with_class("arc", "path").size(), 1u);
  EXPECT_EQ(d.with_class("thread", "path").size(), 1u);
  EXPECT_EQ(d.with_class("rapid", "line").size(), 1u);  // legend
  // The thread run: M start L end-of-cut L end-of-pull-out.
  const std::string td = d.with_class("thread", "path")[0]->attr("d");
  EXPECT_EQ(count_of(td, "M"), 1u);
  EXPECT_EQ(count_of(td, "L"), 2u);
  // Two rapids joined into one run.
  EXPECT_EQ(count_of(d.with_class("rapid", "path")[0]->attr("d"), "L"), 2u);
  // Summary of counts and lengths: thread 20 + hypot(0.8, 1) = 21.28 mm.
  bool summary = false;
  for (const auto* e : d.with_class("summary"))
    summary = e->text.rfind("11 moves: 5 rapid", 0) == 0 &&
              e->text.find("1 arc (3.1 mm), 2 thread (21.3 mm)") != std::string::npos;
  EXPECT_TRUE(summary);
  EXPECT_EQ(d.with_class("title")[0]->text, "part.nc");
  EXPECT_EQ(d.with_class("start").size(), 1u);
}

TEST(BackplotSvg, EqualScaleZRightXUpAndArcFlags) {
  const XmlDoc d = parsed(backplot_svg(small_part()));
  // First feed run: (Z 0.5, X 10) -> (Z -20, X 10) -> (Z -20, X 12).
  const std::vector<double> f = numbers_in(d.with_class("feed", "path")[0]->attr("d"));
  ASSERT_EQ(f.size(), 6u);
  const double k = (f[0] - f[2]) / 20.5;  // px per mm along Z; -Z is to the left
  EXPECT_GT(k, 5);
  EXPECT_NEAR(f[1], f[3], 0.01);          // same radius, same height
  EXPECT_NEAR(f[3] - f[5], 2 * k, 0.02);  // +X is up, same scale
  // The G2 quarter: from (Z -20, X 12) to (Z -22, X 14) around (Z -20, X 14): radius 2,
  // small arc, clockwise on the page (SVG sweep flag 1).
  const std::vector<double> a = numbers_in(d.with_class("arc", "path")[0]->attr("d"));
  ASSERT_EQ(a.size(), 9u);  // M x y A rx ry rot large sweep x y
  EXPECT_NEAR(a[2], 2 * k, 0.02);
  EXPECT_EQ(a[5], 0);
  EXPECT_EQ(a[6], 1);
  EXPECT_NEAR(a[7] - a[0], -2 * k, 0.02);
  EXPECT_NEAR(a[8] - a[1], -2 * k, 0.02);
}

TEST(BackplotSvg, CcwAndLargeArcs) {
  Toolpath tp;
  // G3 three quarters around (0, 0) from (X 0, Z 5) (angle 0) to (X -5, Z 0) (angle -90).
  tp.moves = {mv(MoveKind::kArcCcw, {0, 5}, {-5, 0}, {0, 0}),
              // full circle, clockwise: two half arcs
              mv(MoveKind::kArcCw, {-5, 0}, {-5, 0}, {0, 0})};
  const XmlDoc d = parsed(backplot_svg(tp));
  ASSERT_EQ(d.with_class("arc", "path").size(), 1u);
  const std::string ad = d.with_class("arc", "path")[0]->attr("d");
  const std::vector<double> a = numbers_in(ad);
  ASSERT_EQ(a.size(), 2u + 3 * 7);
  EXPECT_EQ(a[5], 1);  // large
  EXPECT_EQ(a[6], 0);  // counterclockwise
  EXPECT_EQ(a[12], 0);
  EXPECT_EQ(a[13], 1);  // the circle, clockwise
  EXPECT_EQ(a[19], 0);
  EXPECT_EQ(a[20], 1);
  // The circle's half-way point is opposite its start: (X 5, Z 0), one diameter above.
  EXPECT_NEAR(a[14], a[7], 0.01);
  EXPECT_NEAR(a[8] - a[15], 2 * a[2], 0.05);
}

TEST(BackplotSvg, EscapesTheTitle) {
  const std::string svg = backplot_svg(small_part(), nullptr, "a <&> \"b\"");
  EXPECT_NE(svg.find("a &lt;&amp;&gt; &quot;b&quot;"), std::string::npos);
  EXPECT_EQ(svg.find("<&>"), std::string::npos);
  const XmlDoc d = parsed(svg);
  EXPECT_EQ(d.with_class("title")[0]->text, "a <&> \"b\"");
}

TEST(BackplotSvg, EmptyToolpath) {
  const XmlDoc d = parsed(backplot_svg(Toolpath{}));
  for (const char* c : {"rapid", "feed", "arc", "thread"})
    EXPECT_EQ(d.with_class(c, "path").size(), 0u) << c;
  bool no_moves = false;
  for (const auto* e : d.with_tag("text")) no_moves |= e->text == "no moves";
  EXPECT_TRUE(no_moves);
  EXPECT_EQ(d.with_class("title")[0]->text, "Backplot");
}

TEST(BackplotSvg, SkipsNonFiniteMoves) {
  Toolpath tp = small_part();
  tp.moves.insert(tp.moves.begin() + 3, mv(MoveKind::kFeed, {10, -20}, {std::nan(""), -20}));
  tp.moves.push_back(mv(MoveKind::kRapid, {20, 5}, {INFINITY, 5}));
  const std::string svg = backplot_svg(tp);
  const XmlDoc d = parsed(svg);
  EXPECT_EQ(d.with_class("feed", "path").size(), 2u);
  EXPECT_EQ(svg.find("nan"), std::string::npos);
  EXPECT_EQ(svg.find("inf"), std::string::npos);
}

TEST(BackplotSvg, HundredThousandMovesMerge) {
  // A finely discretized profile: 100k feed moves in one run, then a thread cycle of 4 moves
  // repeated 25 times.
  Toolpath tp;
  tp.moves.reserve(100100);
  for (int i = 0; i < 100000; ++i)
    tp.moves.push_back(mv(MoveKind::kFeed, {10 + std::sin(i * 1e-3), -i * 1e-3},
                          {10 + std::sin((i + 1) * 1e-3), -(i + 1) * 1e-3}));
  for (int i = 0; i < 25; ++i) {
    const double x = 9 - i * 0.01;
    tp.moves.push_back(mv(MoveKind::kRapid, {12, 2}, {x, 2}));
    tp.moves.push_back(mv(MoveKind::kThread, {x, 2}, {x, -20}));
    tp.moves.push_back(mv(MoveKind::kRapid, {x, -20}, {12, -20}));
    tp.moves.push_back(mv(MoveKind::kRapid, {12, -20}, {12, 2}));
  }
  const std::string svg = backplot_svg(tp);
  const XmlDoc d = parsed(svg);
  ASSERT_EQ(d.with_class("feed", "path").size(), 1u);
  EXPECT_EQ(count_of(d.with_class("feed", "path")[0]->attr("d"), "L"), 100000u);
  EXPECT_EQ(d.with_class("thread", "path").size(), 25u);
  // Rapids: in before the first pass, then out, back and in (one run) after every pass.
  EXPECT_EQ(d.with_class("rapid", "path").size(), 26u);
}

TEST(BackplotSvg, SectionInsets) {
  ThreadSection s;
  s.title = "inset";
  s.pitch = 1.5;
  s.lead = 1.5;
  s.depth = 0.92;
  s.passes = {{1, 0, 0.5, 0, PassKind::kRough}, {2, 0, 0.92, 0, PassKind::kFinish}};
  const std::vector<ThreadSection> sections = {s, s};
  const std::string svg = backplot_svg(small_part(), &sections, "with sections");
  const XmlDoc d = parsed(svg);
  EXPECT_EQ(d.with_class("pass").size(), 4u);
  EXPECT_EQ(d.with_tag("svg").size(), 3u);  // the root and one nested per section
  EXPECT_EQ(count_of(svg, "id=\"s1-clip\""), 1u);
  EXPECT_EQ(count_of(svg, "id=\"s2-clip\""), 1u);
}

// The thread of small_part() cut from Z 2 to Z -18 at radius 9.2 to 10: a run-in of 2 and a
// run-out of 1 are hatched bands under the moves, as long as they are along Z, and the legend
// says what the hatch means.
TEST(BackplotSvg, LeadZonesUnderTheMoves) {
  ThreadSection s;
  s.pitch = 1.5;
  s.lead = 1.5;
  std::vector<ThreadSection> sections = {s};
  const XmlDoc plain = parsed(backplot_svg(small_part(), &sections));
  EXPECT_TRUE(plain.with_class("lead-zone").empty());
  EXPECT_FALSE(std::any_of(plain.elements.begin(), plain.elements.end(), [](const auto& e) {
    return e.text == "lead not yet right (run-in, run-out)";
  }));
  sections[0].zones = {true, true, 2, -18, 0, -17, true, 2, 1, 600, 9.2, 10};
  sections.push_back(sections[0]);  // a chain's sections: drawn once
  const XmlDoc d = parsed(backplot_svg(small_part(), &sections));
  const auto zones = d.with_class("lead-zone");
  ASSERT_EQ(zones.size(), 2u);
  const double in_w = std::stod(zones[0]->attr("width")),
               out_w = std::stod(zones[1]->attr("width"));
  EXPECT_NEAR(in_w, 2 * out_w, 0.01);
  EXPECT_EQ(zones[0]->attr("height"), zones[1]->attr("height"));
  // The run-in from Z 2 to 0 (Z grows to the right: its left edge is Z 0), the run-out from Z -17
  // to -18 (its left edge Z -18): 18 run-out widths apart (the page has 2 decimals).
  EXPECT_NEAR(std::stod(zones[0]->attr("x")) - std::stod(zones[1]->attr("x")), 18 * out_w, 0.1);
  EXPECT_TRUE(std::any_of(d.elements.begin(), d.elements.end(), [](const auto& e) {
    return e.text == "lead not yet right (run-in, run-out)";
  }));
}

TEST(MoveGeometry, ArcSweepsAndBounds) {
  const ArcSweep cw = arc_sweep(mv(MoveKind::kArcCw, {12, -20}, {14, -22}, {14, -20}));
  EXPECT_DOUBLE_EQ(cw.radius, 2);
  EXPECT_NEAR(cw.start, -std::numbers::pi / 2, 1e-12);  // from is on -X of the centre
  EXPECT_NEAR(cw.sweep, -std::numbers::pi / 2, 1e-12);  // to -Z, clockwise
  const ArcSweep ccw = arc_sweep(mv(MoveKind::kArcCcw, {12, -20}, {14, -22}, {14, -20}));
  EXPECT_NEAR(ccw.sweep, 1.5 * std::numbers::pi, 1e-12);
  // A half circle over the top (G3 from +Z to -Z around (X 0, Z 0), radius 5) reaches X 5.
  Toolpath tp;
  tp.moves = {mv(MoveKind::kArcCcw, {0, 5}, {0, -5}, {0, 0})};
  const Bounds b = toolpath_bounds(tp);
  EXPECT_NEAR(b.x_hi, 5, 1e-12);
  EXPECT_NEAR(b.x_lo, 0, 1e-12);
  EXPECT_NEAR(b.z_lo, -5, 1e-12);
  EXPECT_NEAR(b.z_hi, 5, 1e-12);
}

}  // namespace
}  // namespace clpost

// The section picture: well-formed, one V per pass, the numbers a machinist reads, the right
// way up.
#include "plot/thread_section_svg.h"

#include <gtest/gtest.h>

#include <algorithm>
#include <cmath>
#include <numbers>
#include <string>
#include <vector>

#include "plot/svg_test_util.h"
#include "support/angles.h"

namespace clpost {
namespace {

using testing::check_xml;
using testing::numbers_in;
using testing::parsed;
using testing::XmlDoc;
using testing::XmlElement;

const double kTan30 = std::tan(std::numbers::pi / 6);

// 2 starts, pitch 1.5, D 0.9, flank infeed: ladder 0.4, 0.7, 0.9 (last finish); start 1 stops
// after pass 2, so 5 passes in all. Shifts d tan 30: 0.23094, 0.40415, 0.51962.
ThreadSection five_passes_two_starts() {
  ThreadSection s;
  s.title = "two-start test";
  s.pitch = 1.5;
  s.lead = 3;
  s.starts = 2;
  s.depth = 0.9;
  s.passes = {{1, 0, 0.4, 0.4 * kTan30, PassKind::kRough},
              {1, 1, 0.4, 0.4 * kTan30, PassKind::kRough},
              {2, 0, 0.7, 0.7 * kTan30, PassKind::kRough},
              {2, 1, 0.7, 0.7 * kTan30, PassKind::kRough},
              {3, 0, 0.9, 0.9 * kTan30, PassKind::kFinish}};
  return s;
}

// The V path of the pass group at `g` (the first <path> after it) and its tip (the middle point).
struct Tip {
  double x = 0, y = 0;
};
Tip tip_of(const XmlDoc& d, const XmlElement* g) {
  const auto it = std::find_if(d.elements.begin(), d.elements.end(),
                               [&](const XmlElement& e) { return &e == g; });
  const auto path =
      std::find_if(it, d.elements.end(), [](const XmlElement& e) { return e.tag == "path"; });
  const std::vector<double> v = numbers_in(path->attr("d"));
  EXPECT_EQ(v.size(), 6u);  // M left L tip L right
  return v.size() == 6 ? Tip{v[2], v[3]} : Tip{};
}

std::vector<std::string> texts_with_class(const XmlDoc& d, std::string_view cls) {
  std::vector<std::string> out;
  for (const XmlElement* e : d.with_class(cls)) out.push_back(e->text);
  return out;
}

bool has_text(const XmlDoc& d, std::string_view text) {
  return std::any_of(d.elements.begin(), d.elements.end(),
                     [&](const XmlElement& e) { return e.text == text; });
}

TEST(ThreadSectionSvg, OneVPerPassWithStartsAndKinds) {
  const XmlDoc d = parsed(thread_section_svg(five_passes_two_starts()));
  const auto passes = d.with_class("pass");
  ASSERT_EQ(passes.size(), 5u);
  std::vector<std::string> ids;
  for (const XmlElement* g : passes)
    ids.push_back(g->attr("data-pass") + "/" + g->attr("data-start") + "/" + g->attr("data-kind"));
  EXPECT_EQ(ids, (std::vector<std::string>{"1/0/rough", "1/1/rough", "2/0/rough", "2/1/rough",
                                           "3/0/finish"}));
  // Start 1 is dashed, start 0 solid; the finish pass is red.
  const auto v_path = [&](const XmlElement* g) {
    auto it = std::find_if(d.elements.begin(), d.elements.end(),
                           [&](const XmlElement& e) { return &e == g; });
    return *std::find_if(it, d.elements.end(), [](const XmlElement& e) { return e.tag == "path"; });
  };
  EXPECT_EQ(v_path(passes[0]).attr("stroke-dasharray"), "");
  EXPECT_EQ(v_path(passes[1]).attr("stroke-dasharray"), "7 4");
  EXPECT_EQ(v_path(passes[4]).attr("stroke"), "#d62728");
  EXPECT_EQ(v_path(passes[0]).attr("stroke"), "#1f5fbf");
}

TEST(ThreadSectionSvg, TipsToScaleAndExternalPointsDown) {
  const XmlDoc d = parsed(thread_section_svg(five_passes_two_starts()));
  const auto passes = d.with_class("pass");
  ASSERT_EQ(passes.size(), 5u);
  const Tip p1s0 = tip_of(d, passes[0]), p1s1 = tip_of(d, passes[1]), p2s0 = tip_of(d, passes[2]);
  const Tip p3s0 = tip_of(d, passes[4]);
  // External: deeper is lower on the page; shift grows to the right.
  EXPECT_GT(p2s0.y, p1s0.y);
  EXPECT_GT(p3s0.y, p2s0.y);
  EXPECT_GT(p2s0.x, p1s0.x);
  // One scale: start 1's groove is one pitch (1.5) to the right, the depth step 0.3 and shift
  // step 0.3 tan 30 are to the same scale.
  const double k = (p2s0.y - p1s0.y) / 0.3;
  EXPECT_GT(k, 50);
  EXPECT_NEAR(p1s1.x - p1s0.x, 1.5 * k, 0.1);  // page numbers have 2 decimals
  EXPECT_NEAR(p1s1.y, p1s0.y, 0.01);
  EXPECT_NEAR(p2s0.x - p1s0.x, 0.3 * kTan30 * k, 0.02);
  // The V's flanks make the tool's included angle: half-width / height = tan 30.
  const auto it = std::find_if(d.elements.begin(), d.elements.end(),
                               [&](const XmlElement& e) { return &e == passes[0]; });
  const auto path =
      std::find_if(it, d.elements.end(), [](const XmlElement& e) { return e.tag == "path"; });
  const std::vector<double> v = numbers_in(path->attr("d"));
  ASSERT_EQ(v.size(), 6u);
  EXPECT_NEAR((v[2] - v[0]) / (v[3] - v[1]), kTan30, 1e-3);
  EXPECT_NEAR((v[4] - v[2]) / (v[3] - v[5]), kTan30, 1e-3);
}

TEST(ThreadSectionSvg, InternalPointsUp) {
  ThreadSection s = five_passes_two_starts();
  s.side = ThreadSide::kInternal;
  const XmlDoc d = parsed(thread_section_svg(s));
  const auto passes = d.with_class("pass");
  ASSERT_EQ(passes.size(), 5u);
  EXPECT_LT(tip_of(d, passes[2]).y, tip_of(d, passes[0]).y);  // deeper is higher
  EXPECT_TRUE(has_text(
      d,
      "internal thread, pitch 1.5 mm, lead 3, 2 starts, depth D 0.900, tool 60\u00b0, 5 passes"));
}

TEST(ThreadSectionSvg, TableAndLabelsCarryTheNumbers) {
  const XmlDoc d = parsed(thread_section_svg(five_passes_two_starts()));
  // Table rows in cutting order: pass, start, depth, step, shift, kind.
  const auto rows = d.with_class("pass-row");
  ASSERT_EQ(rows.size(), 5u);
  std::vector<std::vector<std::string>> cells;
  for (const XmlElement* r : rows) {
    auto it = std::find_if(d.elements.begin(), d.elements.end(),
                           [&](const XmlElement& e) { return &e == r; });
    std::vector<std::string> row;
    for (++it; it != d.elements.end() && it->tag == "text" && row.size() < 6; ++it)
      row.push_back(it->text);
    cells.push_back(row);
  }
  using Row = std::vector<std::string>;
  EXPECT_EQ(cells[0], (Row{"1", "0", "0.400", "0.400", "0.231", "rough"}));
  EXPECT_EQ(cells[1], (Row{"1", "1", "0.400", "0.400", "0.231", "rough"}));
  EXPECT_EQ(cells[2], (Row{"2", "0", "0.700", "0.300", "0.404", "rough"}));
  EXPECT_EQ(cells[3], (Row{"2", "1", "0.700", "0.300", "0.404", "rough"}));
  EXPECT_EQ(cells[4], (Row{"3", "0", "0.900", "0.200", "0.520", "finish"}));
  // Depth ruler: the surface, D and the pass depths.
  const std::vector<std::string> ruler = texts_with_class(d, "depth-label");
  for (const char* t : {"0", "D 0.900", "0.400", "0.700"})
    EXPECT_NE(std::find(ruler.begin(), ruler.end(), t), ruler.end()) << t;
  // A pass number at every tip: the starts' grooves are apart, so 5 labels.
  std::vector<std::string> tips = texts_with_class(d, "tip-label");
  std::sort(tips.begin(), tips.end());
  EXPECT_EQ(tips, (std::vector<std::string>{"1", "1", "2", "2", "3"}));
  // Tooltips.
  EXPECT_TRUE(has_text(d, "pass 2, start 1: depth 0.700, shift 0.404 (rough)"));
  EXPECT_TRUE(has_text(d, "two-start test"));
  EXPECT_TRUE(has_text(d, "start 1"));  // legend entry for the second start
}

TEST(ThreadSectionSvg, SpringPassSharesTheFinishTipLabel) {
  // M16x1.5 external, OPTION 1 at 29.5 deg: 0.5, 0.8, finish 0.92, spring 0.92.
  ThreadSection s;
  s.title = "M16x1.5";
  s.pitch = 1.5;
  s.lead = 1.5;
  s.depth = 0.92;
  const double k = std::tan(radians(29.5));
  s.passes = {{1, 0, 0.5, 0.5 * k, PassKind::kRough},
              {2, 0, 0.8, 0.8 * k, PassKind::kRough},
              {3, 0, 0.92, 0.92 * k, PassKind::kFinish},
              {4, 0, 0.92, 0.92 * k, PassKind::kSpring}};
  const XmlDoc d = parsed(thread_section_svg(s));
  EXPECT_EQ(d.with_class("pass").size(), 4u);
  std::vector<std::string> tips = texts_with_class(d, "tip-label");
  std::sort(tips.begin(), tips.end());
  EXPECT_EQ(tips, (std::vector<std::string>{"1", "2", "3,4"}));
  // Shifts: 0.5 tan 29.5 = 0.28290, 0.8 tan 29.5 = 0.45264, 0.92 tan 29.5 = 0.52054.
  EXPECT_TRUE(has_text(d, "0.283"));
  EXPECT_TRUE(has_text(d, "0.453"));
  EXPECT_TRUE(has_text(d, "0.521"));
  EXPECT_TRUE(has_text(d, "spring"));
  EXPECT_TRUE(has_text(d, "0.5 mm"));  // scale bar: a quarter of the 3 mm window, rounded down
}

TEST(ThreadSectionSvg, InchUnitsAndEscapedTitle) {
  ThreadSection s;
  s.title = "1/4-20 <UNC> & \"B\" 'x'";
  s.units = LengthUnit::kInch;
  s.pitch = 0.05;
  s.lead = 0.05;
  s.depth = 0.0307;
  s.passes = {{1, 0, 0.02, 0, PassKind::kRough}, {2, 0, 0.0307, 0, PassKind::kFinish}};
  const std::string svg = thread_section_svg(s);
  EXPECT_NE(svg.find("1/4-20 &lt;UNC&gt; &amp; &quot;B&quot; &apos;x&apos;"), std::string::npos);
  const XmlDoc d = parsed(svg);
  EXPECT_TRUE(has_text(d, "1/4-20 <UNC> & \"B\" 'x'"));
  EXPECT_TRUE(has_text(d, "0.0307"));
  EXPECT_TRUE(has_text(d, "0.0200"));
  EXPECT_TRUE(has_text(d, "Passes in cutting order (in)"));
  EXPECT_TRUE(has_text(d, "0.02 in"));  // scale bar: 0.1 in window / 4 = 0.025 -> 0.02
}

// The strip under the section: the cut Z 2 to Z -30 (32 long) as a bar from x 16 to the width
// less 16, the run-in 5.965031 and the run-out 1.65 hatched at its ends.
TEST(ThreadSectionSvg, LeadStripHatchesTheRunInAndRunOut) {
  ThreadSection s = five_passes_two_starts();
  EXPECT_TRUE(parsed(thread_section_svg(s)).with_class("lead-cut").empty());  // speed not known
  const double plain_height = thread_section_size(s).height;
  s.zones = {true, true, 2, -30, -3.965031, -28.35, true, 5.965031, 1.65, 1500, 9, 10};
  const SvgSize size = thread_section_size(s);
  EXPECT_DOUBLE_EQ(size.height, plain_height + 66);
  const XmlDoc d = parsed(thread_section_svg(s));
  const double bar = size.width - 32;
  ASSERT_EQ(d.with_class("lead-run-in").size(), 1u);
  const XmlElement& in = *d.with_class("lead-run-in")[0];
  EXPECT_NEAR(std::stod(in.attr("x")), 16, 0.01);
  EXPECT_NEAR(std::stod(in.attr("width")), bar * 5.965031 / 32, 0.01);
  ASSERT_EQ(d.with_class("lead-run-out").size(), 1u);
  const XmlElement& out = *d.with_class("lead-run-out")[0];
  EXPECT_NEAR(std::stod(out.attr("x")), 16 + bar * 30.35 / 32, 0.01);
  EXPECT_NEAR(std::stod(out.attr("width")), bar * 1.65 / 32, 0.01);
  EXPECT_TRUE(has_text(d,
                       "lead not yet right (mm): run-in 5.965, run-out 1.650 at 1500 rpm; "
                       "right from Z -3.965 to Z -28.350"));
  EXPECT_TRUE(has_text(d, "Z 2.000"));
  EXPECT_TRUE(has_text(d, "Z -30.000"));
  EXPECT_TRUE(has_text(d, "Z -3.965"));
  // No length right: the whole bar is hatched.
  s.zones.any = false;
  const XmlDoc none = parsed(thread_section_svg(s));
  ASSERT_EQ(none.with_class("lead-none").size(), 1u);
  EXPECT_NEAR(std::stod(none.with_class("lead-none")[0]->attr("width")), bar, 0.01);
  EXPECT_TRUE(none.with_class("lead-run-in").empty());
}

TEST(ThreadSectionSvg, EmptyAndHostileSectionsStillDraw) {
  ThreadSection empty;
  const XmlDoc a = parsed(thread_section_svg(empty));
  EXPECT_EQ(a.with_class("pass").size(), 0u);
  EXPECT_EQ(a.with_class("part").size(), 1u);

  ThreadSection bad;
  bad.pitch = std::nan("");
  bad.depth = -1;
  bad.tool_angle = 400;
  bad.starts = 1000;
  bad.passes = {{1, 0, std::nan(""), 0, PassKind::kRough}, {2, 5, 0.3, 0.1, PassKind::kFinish}};
  const std::string svg = thread_section_svg(bad);
  const XmlDoc b = parsed(svg);
  EXPECT_EQ(b.with_class("pass").size(), 1u);  // the NaN pass is listed, not drawn
  EXPECT_EQ(b.with_class("pass-row").size(), 2u);
  EXPECT_EQ(svg.find("nan"), std::string::npos);
  EXPECT_EQ(svg.find("inf"), std::string::npos);
}

}  // namespace
}  // namespace clpost

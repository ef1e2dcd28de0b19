// The SVG builder: numbers, escaping, element nesting, path data; and the XML checker the other
// plot tests rely on.
#include "plot/svg_writer.h"

#include <gtest/gtest.h>

#include <cmath>
#include <limits>
#include <numbers>
#include <string>

#include "plot/nice_step.h"
#include "plot/svg_test_util.h"

namespace clpost {
namespace {

using testing::check_xml;

TEST(SvgNum, FixedSmallPrecision) {
  EXPECT_EQ(svg_num(12.5), "12.5");
  EXPECT_EQ(svg_num(std::numbers::pi), "3.14");
  EXPECT_EQ(svg_num(2.0), "2");
  EXPECT_EQ(svg_num(-0.001), "0");  // never "-0"
  EXPECT_EQ(svg_num(-1.005, 1), "-1");
  EXPECT_EQ(svg_num(0.1234567, 6), "0.123457");
  EXPECT_EQ(svg_num(1200), "1200");
  EXPECT_EQ(svg_num(std::nan("")), "0");
  EXPECT_EQ(svg_num(std::numeric_limits<double>::infinity()), "0");
}

TEST(FixedText, KeepsZerosForColumns) {
  EXPECT_EQ(fixed_text(0.92, 3), "0.920");
  EXPECT_EQ(fixed_text(0.9200001, 3), "0.920");
  EXPECT_EQ(fixed_text(0.51962, 3), "0.520");
  EXPECT_EQ(fixed_text(0.04, 4), "0.0400");
  EXPECT_EQ(fixed_text(-0.0001, 3), "0.000");  // never "-0.000"
  EXPECT_EQ(fixed_text(-0.25, 3), "-0.250");
  EXPECT_EQ(fixed_text(std::nan(""), 3), "-");
}

TEST(XmlEscape, FiveCharactersAndBadBytes) {
  EXPECT_EQ(xml_escape("a<b>&\"c'"), "a&lt;b&gt;&amp;&quot;c&apos;");
  EXPECT_EQ(xml_escape("M16x1.5 \xC2\xB0"), "M16x1.5 \xC2\xB0");  // valid UTF-8 is kept
  EXPECT_EQ(xml_escape("a\xFF"
                       "b"),
            "a\xEF\xBF\xBD"
            "b");                                                 // invalid byte -> U+FFFD
  EXPECT_EQ(xml_escape("a\x01\tb\n"), "a\tb\n");                  // control chars dropped
  EXPECT_EQ(xml_escape("\xE2\x82"), "\xEF\xBF\xBD\xEF\xBF\xBD");  // truncated sequence
}

TEST(SvgWriter, NestsEscapesAndCloses) {
  SvgWriter w(300, 200.5);
  w.open("g", {{"class", "a&b"}});
  w.text("text", {{"x", svg_num(10)}, {"y", "20"}}, "1 < 2 & \"3\"");
  w.empty("rect", {{"width", "5"}, {"height", "6"}});
  w.open("g");  // left open: finish() closes it
  const std::string doc = w.finish();
  EXPECT_EQ(doc.rfind("<?xml version=\"1.0\" encoding=\"UTF-8\"?>\n<svg ", 0), 0u);
  EXPECT_NE(doc.find("width=\"300\" height=\"200.5\" viewBox=\"0 0 300 200.5\""),
            std::string::npos);
  EXPECT_NE(doc.find("<g class=\"a&amp;b\">"), std::string::npos);
  EXPECT_NE(doc.find("<text x=\"10\" y=\"20\">1 &lt; 2 &amp; &quot;3&quot;</text>"),
            std::string::npos);
  EXPECT_NE(doc.find("<rect width=\"5\" height=\"6\"/>"), std::string::npos);
  const testing::XmlDoc x = check_xml(doc);
  ASSERT_TRUE(x.ok) << x.error << "\n" << doc;
  ASSERT_EQ(x.elements.size(), 5u);  // svg g text rect g
  EXPECT_EQ(x.elements[0].tag, "svg");
  EXPECT_EQ(x.elements[1].attr("class"), "a&b");
  EXPECT_EQ(x.elements[2].text, "1 < 2 & \"3\"");
}

TEST(SvgPath, SegmentsAndJoins) {
  SvgPath p;
  p.line_to(1, 2);  // no current point: starts a subpath
  p.line_to(3.456, 4);
  p.move_to(3.456, 4);  // already there: nothing written
  p.arc_to(5, true, false, 10, 4);
  p.move_to(0, 0);
  p.line_to(1, 0);
  p.close_path();
  EXPECT_EQ(p.data(), "M1 2 L3.46 4 A5 5 0 1 0 10 4 M0 0 L1 0 Z");
  EXPECT_EQ(p.segments(), 3u);
  EXPECT_TRUE(SvgPath().empty());
}

TEST(XmlCheck, CatchesBrokenDocuments) {
  EXPECT_TRUE(check_xml("<svg><g a=\"1\"/></svg>").ok);
  EXPECT_FALSE(check_xml("<svg><g></svg>").ok);                 // unbalanced
  EXPECT_FALSE(check_xml("<svg><g a=1/></svg>").ok);            // unquoted
  EXPECT_FALSE(check_xml("<svg><text>a & b</text></svg>").ok);  // raw &
  EXPECT_FALSE(check_xml("<svg><text>a < b</text></svg>").ok);  // raw <
  EXPECT_FALSE(check_xml("<svg a=\"<\"/>").ok);
  EXPECT_FALSE(check_xml("<svg/><svg/>").ok);            // two roots
  EXPECT_FALSE(check_xml("<svg a=\"1\" a=\"2\"/>").ok);  // duplicate attribute
}

TEST(NiceStep, RoundNumbers) {
  EXPECT_DOUBLE_EQ(nice_step(0.3), 0.5);
  EXPECT_DOUBLE_EQ(nice_step(7), 10);
  EXPECT_DOUBLE_EQ(nice_step(2), 2);
  EXPECT_DOUBLE_EQ(nice_step(0.011), 0.02);
  EXPECT_DOUBLE_EQ(nice_step(-1), 1);
  EXPECT_DOUBLE_EQ(nice_floor(0.8), 0.5);
  EXPECT_DOUBLE_EQ(nice_floor(30), 20);
  EXPECT_DOUBLE_EQ(nice_floor(5), 5);
  EXPECT_DOUBLE_EQ(nice_floor(0.75), 0.5);
  EXPECT_DOUBLE_EQ(nice_floor(std::nan("")), 1);
}

}  // namespace
}  // namespace clpost

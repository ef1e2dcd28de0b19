// The sheet's pieces on hand-made data: escaping, the text of feeds and speeds, the date, and
// the page's sections for a program without threads or holes.
#include "sheet/sheet.h"

#include <gtest/gtest.h>

#include "sheet/html_text.h"
#include "sheet/sheet_text.h"

namespace clpost {
namespace {

TEST(SheetText, EscapesWhatTheClSays) {
  EXPECT_EQ(esc("<script>&\"'"), "&lt;script&gt;&amp;&quot;&apos;");
  EXPECT_EQ(row({{"<b>"}, {"1.5", true}}),
            "<tr><td>&lt;b&gt;</td><td class=\"num\">1.5</td></tr>\n");
  EXPECT_EQ(fact("Part", "A&B"), "<tr><th>Part</th><td>A&amp;B</td></tr>\n");
}

TEST(SheetText, InlineSvgDropsTheXmlDeclaration) {
  EXPECT_EQ(inline_svg("<?xml version=\"1.0\" encoding=\"UTF-8\"?>\n<svg/>\n"), "<svg/>\n");
  EXPECT_EQ(inline_svg("<svg/>"), "<svg/>");
}

TEST(SheetText, FeedsAndSpeeds) {
  EXPECT_EQ(feed_text({0.2, FeedMode::kPerRev}, LengthUnit::kMm), "0.2 mm/rev");
  EXPECT_EQ(feed_text({450, FeedMode::kPerMinute}, LengthUnit::kMm), "450 mm/min");
  EXPECT_EQ(feed_text({0.008, FeedMode::kPerRev}, LengthUnit::kInch), "0.008 in/rev");
  EXPECT_EQ(speed_text({800, false}, LengthUnit::kMm), "800 rpm");
  EXPECT_EQ(speed_text({200, true}, LengthUnit::kMm), "200 m/min");
  EXPECT_EQ(speed_text({600, true}, LengthUnit::kInch), "600 ft/min");
}

TEST(SheetText, ReachAsCheckPrintsIt) {
  ToolTime t;
  EXPECT_EQ(reach_text(t, true), "");  // never moved
  t.x_min = 6, t.x_max = 16, t.z_min = -42, t.z_max = 2;
  EXPECT_EQ(reach_text(t, true), "X12.000 to X32.000, Z-42.000 to Z2.000");
  EXPECT_EQ(reach_text(t, false), "X6.000 to X16.000, Z-42.000 to Z2.000");
}

TEST(SheetDate, GivenThenEpochThenNow) {
  std::string date, err;
  ASSERT_TRUE(sheet_date("Monday", "0", date, err));
  EXPECT_EQ(date, "Monday");
  ASSERT_TRUE(sheet_date("", "0", date, err));
  EXPECT_EQ(date, "1970-01-01 00:00 UTC");
  ASSERT_TRUE(sheet_date("", "1700000000", date, err));  // 2023-11-14 22:13:20 UTC
  EXPECT_EQ(date, "2023-11-14 22:13 UTC");
  EXPECT_FALSE(sheet_date("", "12x", date, err));
  EXPECT_EQ(err, "SOURCE_DATE_EPOCH '12x' is not a whole number of seconds");
  EXPECT_FALSE(sheet_date("", "-5", date, err));
  ASSERT_TRUE(sheet_date("", nullptr, date, err));
  EXPECT_EQ(date.size(), std::string("2026-01-01 00:00 UTC").size());
}

TEST(SheetHtml, ToolsAndTotalsWithoutThreadsOrHoles) {
  SheetData d;
  d.program = "a<b>.cl";
  d.machine = "m";
  d.date = "today";
  ToolTime t;
  t.tool = 3;
  t.offset = 13;
  t.text = "DRILL 8.5 & <more>";
  t.seconds = 62.25;  // shown as time_text() gives it, as check does
  t.cutting_seconds = 40;
  t.first_nc_line = 7;
  t.last_nc_line = 19;
  t.feeds = {{0.12, FeedMode::kPerRev}};
  t.speeds = {{900, false}};
  d.cycle_time.tools.push_back(t);
  const std::string html = sheet_html(d);
  EXPECT_NE(html.find("<h1>Setup sheet: a&lt;b&gt;.cl</h1>"), std::string::npos);
  EXPECT_NE(html.find("<td>T3</td><td class=\"num\">13</td><td>DRILL 8.5 &amp; &lt;more&gt;</td>"
                      "<td class=\"num\">-</td><td class=\"num\">7-19</td>"
                      "<td class=\"num\">0:40.0</td><td class=\"num\">" +
                      time_text(62.25) +
                      "</td><td><span class=\"nw\">0.12 mm/rev</span></td>"
                      "<td><span class=\"nw\">900 rpm</span></td>"),
            std::string::npos)
      << html;
  EXPECT_NE(html.find("<p>No holes on the spindle axis.</p>"), std::string::npos);
  EXPECT_EQ(html.find("id=\"thread-"), std::string::npos);
  EXPECT_EQ(html.find("<script"), std::string::npos);
  const std::string json = sheet_json(d);
  EXPECT_NE(json.find("\"first_nc_line\": 7, \"last_nc_line\": 19, \"cutting_seconds\": 40, "
                      "\"seconds\": 62.25"),
            std::string::npos)
      << json;
  EXPECT_NE(json.find("\"program\": \"a<b>.cl\""), std::string::npos);
}

}  // namespace
}  // namespace clpost

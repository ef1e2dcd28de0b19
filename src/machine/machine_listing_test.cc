#include "machine/machine_listing.h"

#include <gtest/gtest.h>

#include "machine/machine_loader.h"
#include "machine/machine_schema.h"
#include "machine/machine_test_util.h"
#include "machine/schema_json.h"

namespace clpost {
namespace {

TEST(MachineListing, TextIsQuotedOnlyWhenYamlWouldMisreadIt) {
  EXPECT_EQ(yaml_scalar("G0"), "G0");
  EXPECT_EQ(yaml_scalar("("), "(");
  EXPECT_EQ(yaml_scalar(""), "\"\"");
  EXPECT_EQ(yaml_scalar("; "), "\"; \"");
  EXPECT_EQ(yaml_scalar("N "), "\"N \"");
  EXPECT_EQ(yaml_scalar("[METRIC]"), "\"[METRIC]\"");
  EXPECT_EQ(yaml_scalar("1"), "\"1\"");
  EXPECT_EQ(yaml_scalar("yes"), "\"yes\"");
  EXPECT_EQ(yaml_scalar("SF="), "SF=");
}

TEST(MachineListing, OriginsOfThePostTheMachineAndSet) {
  Machine m;
  std::string errors;
  KeyOrigins o;
  ASSERT_TRUE(load_machine("generic-lathe", {CLPOST_SOURCE_DIR}, {"limits.max_rpm=2500"},
                           shipped_controls(), m, errors, &o))
      << errors;
  const std::string dir = CLPOST_SOURCE_DIR;
  EXPECT_EQ(o.at("limits.max_rpm"), "--set");
  EXPECT_EQ(o.at("limits.max_feed"), dir + "/machines/generic-lathe.yaml:7");
  EXPECT_EQ(o.at("codes.thread"), dir + "/posts/iso-lathe.yaml:32");
  EXPECT_EQ(o.at("formats.X.decimals"), dir + "/posts/iso-lathe.yaml:17");
  EXPECT_EQ(o.at("templates.dwell"), dir + "/posts/iso-lathe.yaml:58");
  EXPECT_EQ(o.count("limits.max_feed_x"), 0u);  // the default
  std::vector<MachineValue> v = machine_values(m);
  EXPECT_EQ(v.front().key, "extends");
  EXPECT_EQ(v.front().value, "iso-lathe");
}

TEST(SchemaJson, TemplateLinesMayUseOnlyTheirFields) {
  const std::string s = schema_json(schema({}));
  EXPECT_NE(
      s.find(
          R"("pattern": "^(?:[^{}]|\\{\\{|\\}\\}|\\{(?:tool|offset|tool_name)(?:[:!][^{}]*)?\\})*$")"),
      std::string::npos);
  EXPECT_NE(s.find(R"("pattern": "^(?:[^{}]|\\{\\{|\\}\\})*$")"),
            std::string::npos);  // spindle_stop
  EXPECT_NE(s.find(R"(          "minimum": 0,
          "maximum": 4,
          "default": 0)"),
            std::string::npos);  // threading.option
}

}  // namespace
}  // namespace clpost

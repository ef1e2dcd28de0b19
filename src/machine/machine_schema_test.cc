#include "machine/machine_schema.h"

#include <fmt/format.h>
#include <gtest/gtest.h>

#include <fstream>
#include <sstream>

#include "controls/fanuc/fanuc_templates.h"
#include "controls/registry.h"
#include "machine/machine_loader.h"
#include "machine/schema_markdown.h"

namespace clpost {
namespace {

std::string read_text(const std::string& path) {
  std::ifstream in(path);
  std::ostringstream s;
  s << in.rdbuf();
  return s.str();
}

// docs/machines.md's tables are the schema's: regenerate them with
//   build/clpost schema --markdown
// and paste the output over the block between the markers.
// Every key has a row in the docs' tables: a key of a section the tables do not list would not.
TEST(MachineSchema, EveryKeyIsInTheDocsTables) {
  const std::string md = schema_markdown();
  for (const KeySpec& k : machine_keys())
    EXPECT_NE(md.find(fmt::format("| `{}` |", k.path)), std::string::npos) << k.path;
}

TEST(MachineSchema, DocsTablesAreTheSchemas) {
  const std::string docs = read_text(std::string(CLPOST_SOURCE_DIR) + "/docs/machines.md");
  const size_t begin = docs.find(kSchemaDocBegin);
  const size_t end = docs.find(kSchemaDocEnd);
  ASSERT_NE(begin, std::string::npos);
  ASSERT_NE(end, std::string::npos);
  const std::string block = docs.substr(begin, end - begin + std::string(kSchemaDocEnd).size());
  EXPECT_EQ(block + "\n", schema_markdown())
      << "docs/machines.md is stale: run build/clpost schema --markdown";
}

// Every key's default, written back as a machine file, loads: the schema's rendering and the
// loader agree, and every declared key is one the loader takes.
TEST(MachineSchema, DefaultsRoundTripThroughTheLoader) {
  const Machine defaults;
  for (const KeySpec& k : machine_keys()) {
    if (k.machine_only) continue;
    std::string value = key_value_text(k, defaults);
    if (k.type == KeyType::kString) value = "\"" + value + "\"";
    // Dotted paths as nested flow maps: a.b: v -> a: {b: v}
    std::string line;
    size_t depth = 0, start = 0;
    for (size_t dot; (dot = k.path.find('.', start)) != std::string_view::npos;
         start = dot + 1, ++depth)
      line += std::string(k.path.substr(start, dot - start)) + ": {";
    line += std::string(k.path.substr(start)) + ": " + value + std::string(depth, '}');
    Machine m;
    std::string errors;
    EXPECT_TRUE(apply_machine_yaml("d.yaml", line + "\n", false, m, errors)) << line << errors;
    EXPECT_EQ(key_value_text(k, m), key_value_text(k, defaults)) << k.path;
  }
}

TEST(MachineSchema, ValuesAsAMachineFileWritesThem) {
  Machine m;
  m.thread_strategy = ThreadStrategy::kLoop;
  m.line_ending = "\r\n";
  m.cycle_shifted_end = true;
  m.run_in.value = 2.5;
  EXPECT_EQ(key_value_text(*find_key("threading.strategy"), m), "loop");
  EXPECT_EQ(key_value_text(*find_key("output.line_ending"), m), "crlf");
  EXPECT_EQ(key_value_text(*find_key("threading.cycle_pass_end"), m), "shifted");
  EXPECT_EQ(key_value_text(*find_key("threading.run_in"), m), "2.5");
  m.run_in.automatic = true;
  EXPECT_EQ(key_value_text(*find_key("threading.run_in"), m), "auto");
  EXPECT_EQ(key_value_text(*find_key("block_numbers.skip"), m), "[\"%\", \"O\"]");
  EXPECT_EQ(find_key("threading.strategi"), nullptr);
}

TEST(MachineSchema, WhichTemplatesAMachineNeeds) {
  Machine m;
  EXPECT_TRUE(template_required(tmpl::kProgramStart, m));
  EXPECT_FALSE(template_required(tmpl::kSpindleCss, m));  // only SPINDL/…,SMM reaches it
  EXPECT_FALSE(template_required(tmpl::kFanucG76, m));
  m.control = find_control(shipped_controls(), "fanuc_g76");
  EXPECT_TRUE(template_required(tmpl::kFanucG76, m));
  EXPECT_FALSE(template_required(tmpl::kG92, m));
  m.thread_loop = ThreadLoop::kG92;
  EXPECT_TRUE(template_required(tmpl::kG92, m));
  EXPECT_TRUE(template_required(tmpl::kG92Next, m));
  // Compile-time field lookup.
  static_assert(tmpl::kFanucG76.field("lead", FieldKind::kText) == 10);
  static_assert(tmpl::kToolChange.field("tool", FieldKind::kWhole) == 0);
}

}  // namespace
}  // namespace clpost

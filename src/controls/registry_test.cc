// The registry: each control is whole, and the schema of its controls is the one docs/machines.md
// documents.
#include "controls/registry.h"

#include <fmt/format.h>
#include <gtest/gtest.h>

#include <fstream>
#include <set>
#include <sstream>
#include <string>

#include "emitters/emitter.h"
#include "machine/machine_schema.h"
#include "machine/schema_markdown.h"
#include "simulator/control_readback.h"

namespace clpost {
namespace {

std::string read_text(const std::string& path) {
  std::ifstream in(path);
  std::ostringstream s;
  s << in.rdbuf();
  return s.str();
}

// docs/machines.md's tables are the shipped controls' schema: regenerate them with
//   build/clpost schema --markdown
// and paste the output over the block between the markers.
// Every key has a row in the docs' tables: a key of a section the tables do not list would not.
TEST(Registry, EveryKeyIsInTheDocsTables) {
  const Schema s = schema(shipped_controls());
  const std::string md = schema_markdown(s);
  for (const KeySpec& k : s.keys)
    EXPECT_NE(md.find(fmt::format("| `{}` |", k.path)), std::string::npos) << k.path;
}

TEST(Registry, DocsTablesAreTheSchemas) {
  const std::string docs = read_text(std::string(CLPOST_SOURCE_DIR) + "/docs/machines.md");
  const size_t begin = docs.find(kSchemaDocBegin);
  const size_t end = docs.find(kSchemaDocEnd);
  ASSERT_NE(begin, std::string::npos);
  ASSERT_NE(end, std::string::npos);
  const std::string block = docs.substr(begin, end - begin + std::string(kSchemaDocEnd).size());
  EXPECT_EQ(block + "\n", schema_markdown(schema(shipped_controls())))
      << "docs/machines.md is stale: run build/clpost schema --markdown";
}

// threading.cycle chooses among "none" and the shipped cycles, threading.loop among "g33" and
// the shipped loop blocks, each once: no two controls take one name.
TEST(Registry, TheSchemaListsEveryShippedCycleAndLoopOnce) {
  const Schema s = schema(shipped_controls());
  for (const char* key : {"threading.cycle", "threading.loop"}) {
    std::set<std::string_view> names;
    for (const Choice& c : find_key(s, key)->choices)
      EXPECT_TRUE(names.insert(c.name).second) << key << ": " << c.name << " twice";
  }
  for (const Control* c : shipped_controls()) {
    EXPECT_EQ(find_control(shipped_controls(), c->cycle), c) << c->name;
    for (const LoopBlock& l : c->loops) EXPECT_EQ(find_loop(shipped_controls(), l.name), &l);
  }
}

TEST(Registry, EveryControlWritesAndReadsBackItsCycle) {
  std::set<std::string_view> names;
  for (const Control* c : shipped_controls()) {
    EXPECT_TRUE(names.insert(c->name).second) << c->name << " registered twice";
    ASSERT_NE(c->cycle_emitter, nullptr) << c->name;
    EXPECT_NE(c->cycle_emitter(), nullptr) << c->name;
    ASSERT_NE(c->readback, nullptr) << c->name;
    EXPECT_TRUE(c->readback->cycle != nullptr || c->readback->call != nullptr)
        << c->name << " writes a cycle that nothing reads back";
    for (const LoopBlock& l : c->loops) {
      ASSERT_NE(l.emitter, nullptr) << c->name << " " << l.name;
      EXPECT_NE(l.emitter(), nullptr) << c->name << " " << l.name;
      EXPECT_NE(l.readback, nullptr) << c->name << " writes " << l.name << ", which nothing reads";
    }
  }
  EXPECT_EQ(find_control(shipped_controls(), "fanuc_g76")->name, "fanuc");
  EXPECT_EQ(find_control(shipped_controls(), "none"), nullptr);
  EXPECT_EQ(find_loop(shipped_controls(), "g92"),
            &find_control(shipped_controls(), "fanuc_g76")->loops[0]);
}

}  // namespace
}  // namespace clpost

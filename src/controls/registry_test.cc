// The registry: what the schema documents for threading.cycle is what the shipped controls are,
// and each control is whole.
#include "controls/registry.h"

#include <gtest/gtest.h>

#include <set>
#include <string>

#include "emitters/emitter.h"
#include "simulator/control_readback.h"

namespace clpost {
namespace {

TEST(Registry, TheSchemaListsEveryShippedCycle) {
  std::vector<std::string_view> cycles = {"none"};
  for (const Control* c : shipped_controls()) cycles.push_back(c->cycle);
  EXPECT_EQ(cycles, std::vector<std::string_view>(kShippedCycles.begin(), kShippedCycles.end()));
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
  }
  EXPECT_EQ(find_control(shipped_controls(), "fanuc_g76")->name, "fanuc");
  EXPECT_EQ(find_control(shipped_controls(), "none"), nullptr);
}

}  // namespace
}  // namespace clpost

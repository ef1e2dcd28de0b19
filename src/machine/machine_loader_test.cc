#include "machine/machine_loader.h"

#include <gtest/gtest.h>

namespace clpost {
namespace {

const std::vector<std::string> kDirs = {CLPOST_SOURCE_DIR};

TEST(MachineLoader, ShippedMachinesLoad) {
  for (const MachineInfo& mi : list_machines(kDirs)) {
    Machine m;
    std::string errors;
    EXPECT_TRUE(load_machine(mi.name, kDirs, {}, m, errors)) << mi.name << "\n" << errors;
    EXPECT_EQ(errors, "");
    EXPECT_FALSE(mi.description.empty()) << mi.name;
  }
}

TEST(MachineLoader, GenericLatheTakesPostThenMachineKeys) {
  Machine m;
  std::string errors;
  ASSERT_TRUE(load_machine("generic-lathe", kDirs, {}, m, errors)) << errors;
  EXPECT_EQ(m.name, "generic-lathe");
  EXPECT_EQ(m.post, "iso-lathe");
  EXPECT_EQ(m.code("thread"), "G33");  // from the post
  EXPECT_DOUBLE_EQ(m.max_rpm, 4000);   // from the machine
  EXPECT_EQ(m.extension, ".nc");
  EXPECT_TRUE(m.block_numbers);
}

TEST(MachineLoader, SetOverridesAKey) {
  Machine m;
  std::string errors;
  ASSERT_TRUE(load_machine("generic-lathe", kDirs,
                           {"block_numbers.enabled=false", "limits.max_rpm=2500"}, m, errors))
      << errors;
  EXPECT_FALSE(m.block_numbers);
  EXPECT_DOUBLE_EQ(m.max_rpm, 2500);
}

TEST(MachineLoader, UnknownKeySuggestsTheClosest) {
  Machine m;
  std::string errors;
  EXPECT_FALSE(apply_machine_yaml("m.yaml", "limits:\n  max_rmp: 3000\n", false, m, errors));
  EXPECT_EQ(errors,
            "m.yaml:2:3: error: unknown key 'limits.max_rmp' (did you mean 'max_rpm'?)\n"
            "    max_rmp: 3000\n"
            "    ^\n");
}

TEST(MachineLoader, WrongTypeAndRange) {
  Machine m;
  std::string errors;
  EXPECT_FALSE(apply_machine_yaml("m.yaml", "threading:\n  option: 7\n  strategy: cycel\n", false,
                                  m, errors));
  EXPECT_EQ(errors,
            "m.yaml:2:11: error: 'threading.option' is 7 but must be between 0 and 4\n"
            "    option: 7\n"
            "            ^\n"
            "m.yaml:3:13: error: 'threading.strategy' must be one of cycle, loop, emulate, not "
            "'cycel' (did you mean 'cycle'?)\n"
            "    strategy: cycel\n"
            "              ^\n");
}

TEST(MachineLoader, BadTemplateFieldIsCaughtAtLoad) {
  Machine m;
  std::string errors;
  EXPECT_FALSE(apply_machine_yaml("m.yaml", "templates:\n  tool_change: [\"T{tool}{ofset}\"]\n",
                                  false, m, errors));
  EXPECT_EQ(
      errors,
      "m.yaml:2:17: error: bad template line 'T{tool}{ofset}' in 'tool_change': argument not found "
      "(fields: {tool}, {offset}, {tool_name})\n"
      "    tool_change: [\"T{tool}{ofset}\"]\n"
      "                  ^\n");
}

TEST(MachineLoader, InvalidYamlHasALocation) {
  Machine m;
  std::string errors;
  EXPECT_FALSE(apply_machine_yaml("m.yaml", "units: mm\nlimits: [1, 2\n", false, m, errors));
  EXPECT_NE(errors.find("m.yaml:3:1: error: invalid YAML: "), std::string::npos) << errors;
}

TEST(MachineLoader, UnknownMachineListsShippedOnes) {
  Machine m;
  std::string errors;
  EXPECT_FALSE(load_machine("generic-lath", kDirs, {}, m, errors));
  EXPECT_EQ(errors.rfind("clpost: error: unknown machine 'generic-lath' (did you mean "
                         "'generic-lathe'?); shipped machines: ",
                         0),
            0u)
      << errors;
}

}  // namespace
}  // namespace clpost

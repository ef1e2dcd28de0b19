#include "machine/machine_loader.h"
#include "machine/machine_test_util.h"

#include <gtest/gtest.h>

#include <fstream>

#include <cstdio>

namespace clpost {
namespace {

const std::vector<std::string> kDirs = {CLPOST_SOURCE_DIR};

TEST(MachineLoader, ShippedMachinesLoad) {
  for (const MachineInfo& mi : list_machines(kDirs)) {
    Machine m;
    std::string errors;
    EXPECT_TRUE(load_machine(mi.name, kDirs, {}, shipped_controls(), m, errors)) << mi.name << "\n"
                                                                                 << errors;
    EXPECT_EQ(errors, "");
    EXPECT_FALSE(mi.description.empty()) << mi.name;
  }
}

TEST(MachineLoader, GenericLatheTakesPostThenMachineKeys) {
  Machine m;
  std::string errors;
  ASSERT_TRUE(load_machine("generic-lathe", kDirs, {}, shipped_controls(), m, errors)) << errors;
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
                           {"block_numbers.enabled=false", "limits.max_rpm=2500"},
                           shipped_controls(), m, errors))
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

// An empty value is said to be one, never ''; a map or a list is named as such.
TEST(MachineLoader, EmptyValuesAreNamed) {
  Machine m;
  std::string errors;
  EXPECT_FALSE(apply_machine_yaml(
      "m.yaml", "limits:\n  max_rpm: ''\nblock_numbers:\n  enabled: []\n  step: {}\n", false, m,
      errors));
  EXPECT_EQ(errors,
            "m.yaml:2:12: error: 'limits.max_rpm' must be a number, not an empty value\n"
            "    max_rpm: ''\n"
            "             ^\n"
            "m.yaml:4:12: error: 'block_numbers.enabled' must be true or false, not a list\n"
            "    enabled: []\n"
            "             ^\n"
            "m.yaml:5:9: error: 'block_numbers.step' must be a number, not a map\n"
            "    step: {}\n"
            "          ^\n");
}

TEST(MachineLoader, BadTemplateFieldIsCaughtAtLoad) {
  Machine m;
  std::string errors;
  EXPECT_FALSE(apply_machine_yaml("m.yaml", "templates:\n  tool_change: [\"T{tool}{ofset}\"]\n",
                                  false, m, errors));
  EXPECT_EQ(
      errors,
      "m.yaml:2:25: error: bad template line 'T{tool}{ofset}' in 'tool_change': unknown field "
      "'{ofset}' (did you mean 'offset'?) (fields: {tool}, {offset}, {tool_name})\n"
      "    tool_change: [\"T{tool}{ofset}\"]\n"
      "                          ^\n");
}

// Fuzzer find: a template field's width is how many characters fmt writes, so
// `{tool:>1000000000}` made a 1 GB line at load time and again for every block.
TEST(MachineLoader, HugeTemplateWidthIsCaughtAtLoad) {
  Machine m;
  std::string errors;
  EXPECT_FALSE(apply_machine_yaml(
      "m.yaml", "templates:\n  tool_change: [\"T{tool:>1000000000}\"]\n", false, m, errors));
  EXPECT_EQ(errors,
            "m.yaml:2:17: error: bad template line 'T{tool:>1000000000}' in 'tool_change': width "
            "or precision 1000000000 is too large (at most 99)\n"
            "    tool_change: [\"T{tool:>1000000000}\"]\n"
            "                  ^\n");
  errors.clear();
  EXPECT_FALSE(apply_machine_yaml("m.yaml", "templates:\n  dwell: \"G4 P{seconds:.{seconds}}\"\n",
                                  false, m, errors));
  EXPECT_EQ(errors,
            "m.yaml:2:10: error: bad template line 'G4 P{seconds:.{seconds}}' in 'dwell': a width "
            "or precision cannot be taken from a field\n"
            "    dwell: \"G4 P{seconds:.{seconds}}\"\n"
            "           ^\n");
  // Two digits are fine, a zero fill too; '{{' is a literal brace.
  errors.clear();
  EXPECT_TRUE(apply_machine_yaml(
      "m.yaml", "templates:\n  tool_change: [\"{{T{tool:0>99}{offset:02}}}\"]\n", false, m, errors))
      << errors;
}

TEST(MachineLoader, InvalidYamlHasALocation) {
  Machine m;
  std::string errors;
  EXPECT_FALSE(apply_machine_yaml("m.yaml", "units: mm\nlimits: [1, 2\n", false, m, errors));
  EXPECT_EQ(errors, "m.yaml:3:1: error: invalid YAML: end of sequence flow not found\n");
}

// 5000 nested flow maps: yaml-cpp gives up with "bad file"; the diagnostic says why, and where.
TEST(MachineLoader, DeeplyNestedYamlIsAnErrorNotACrash) {
  std::string text = "x: ";
  for (int i = 0; i < 5000; ++i) text += "{a: ";
  text += "1" + std::string(5000, '}') + "\n";
  Machine m;
  std::string errors;
  EXPECT_FALSE(apply_machine_yaml("m.yaml", text, false, m, errors));
  EXPECT_TRUE(
      errors.starts_with("m.yaml:1:1995: error: invalid YAML: nested too deeply (a "
                         "machine or post file needs a few levels, the YAML reader stops "
                         "at 2000)\n  ... {a: {a: "))
      << errors.substr(0, 400);
  // The line is shown from column 1915, so the caret stands 80 characters into the window.
  EXPECT_TRUE(errors.ends_with("{a:...\n" + std::string(2 + 3 + 80, ' ') + "^\n"));
}

TEST(MachineLoader, UnknownMachineListsShippedOnes) {
  Machine m;
  std::string errors;
  EXPECT_FALSE(load_machine("generic-lath", kDirs, {}, shipped_controls(), m, errors));
  EXPECT_EQ(errors.rfind("clpost: error: unknown machine 'generic-lath' (did you mean "
                         "'generic-lathe'?); shipped machines: ",
                         0),
            0u)
      << errors;
}

}  // namespace
}  // namespace clpost

namespace clpost {
namespace {

std::string write_temp(const std::string& name, const std::string& text) {
  std::string path = ::testing::TempDir() + name;
  FILE* f = std::fopen(path.c_str(), "w");
  std::fwrite(text.data(), 1, text.size(), f);
  std::fclose(f);
  return path;
}

TEST(MachineLoader, MachineWithoutPostMissesRequiredKeys) {
  std::string path = write_temp("lonely.yaml", "description: no post\nunits: mm\n");
  Machine m;
  std::string errors;
  EXPECT_FALSE(load_machine(path, kDirs, {}, shipped_controls(), m, errors));
  EXPECT_EQ(errors, path +
                        ":1:1: error: missing required keys 'codes.rapid', 'codes.linear', "
                        "'codes.arc_cw', 'codes.arc_ccw', 'codes.thread', 'codes.metric', "
                        "'codes.inch', 'codes.spindle_cw', 'codes.spindle_ccw', "
                        "'templates.program_start', 'templates.program_end', "
                        "'templates.tool_change', 'templates.spindle_rpm', "
                        "'templates.spindle_stop' (a machine file normally 'extends' a post from "
                        "posts/ that defines them)\n"
                        "  description: no post\n"
                        "  ^\n");
}

TEST(MachineLoader, EmptiedRequiredCodeIsAnError) {
  std::string path =
      write_temp("emptied.yaml", "# no thread code\nextends: iso-lathe\ncodes: {thread: ''}\n");
  Machine m;
  std::string errors;
  EXPECT_FALSE(load_machine(path, kDirs, {}, shipped_controls(), m, errors));
  EXPECT_EQ(errors, path +
                        ":2:1: error: missing required key 'codes.thread': empty or absent in "
                        "this machine and its post 'iso-lathe'\n"
                        "  extends: iso-lathe\n"
                        "  ^\n");
}

TEST(MachineLoader, ThreadingCycleKeysAreChecked) {
  Machine m;
  m.controls = shipped_controls();
  std::string errors;
  EXPECT_FALSE(apply_machine_yaml("m.yaml", "threading: {cycle: g76}\n", false, m, errors));
  EXPECT_NE(errors.find("m.yaml:1:20: error: 'threading.cycle' must be one of"), std::string::npos)
      << errors;
  errors.clear();
  EXPECT_TRUE(apply_machine_yaml("m.yaml",
                                 "threading: {cycle: fanuc_g76, loop: g92, run_in: 2.5, "
                                 "tolerance: 0.005, extra_spring_passes: true, tpi_address: E, "
                                 "lead_address_x: I}\n",
                                 false, m, errors))
      << errors;
  ASSERT_NE(m.control, nullptr);
  EXPECT_EQ(m.control->cycle, "fanuc_g76");
  ASSERT_NE(m.thread_loop, nullptr);
  EXPECT_EQ(m.thread_loop->name, "g92");
  EXPECT_DOUBLE_EQ(m.run_in.value, 2.5);
  EXPECT_DOUBLE_EQ(m.thread_tolerance, 0.005);
  EXPECT_TRUE(m.extra_spring_passes);
  EXPECT_EQ(m.tpi_address, "E");
  EXPECT_EQ(m.thread_lead_address_x, "I");
  // run_in is a number (above) or auto; anything else is an error naming both.
  EXPECT_FALSE(m.run_in.automatic);
  EXPECT_TRUE(apply_machine_yaml("m.yaml", "threading: {run_in: auto}\n", false, m, errors))
      << errors;
  EXPECT_TRUE(m.run_in.automatic);
  EXPECT_FALSE(apply_machine_yaml("m.yaml", "threading: {run_in: -1}\n", false, m, errors));
  EXPECT_NE(errors.find("m.yaml:1:21: error: 'threading.run_in' is -1 but must be between 0 and "
                        "1000"),
            std::string::npos)
      << errors;
  EXPECT_FALSE(apply_machine_yaml("m.yaml", "threading: {run_in: [1]}\n", false, m, errors));
  EXPECT_NE(errors.find("'threading.run_in' must be a number or auto, not 'a collection'"),
            std::string::npos)
      << errors;
}

// Issue 14: every name under codes, formats and templates is declared; an unknown one is an
// error at its line and column with the closest declared name.
TEST(MachineLoader, UnknownCodeFormatAndTemplateNames) {
  Machine m;
  std::string errors;
  EXPECT_FALSE(apply_machine_yaml("m.yaml",
                                  "codes:\n  rapdi: G0\nformats:\n  dwel: {decimals: 2}\n"
                                  "templates:\n  spindle_cs: [\"G96\"]\n",
                                  false, m, errors));
  EXPECT_EQ(errors,
            "m.yaml:2:3: error: unknown code 'codes.rapdi' (did you mean 'rapid'?)\n"
            "    rapdi: G0\n"
            "    ^\n"
            "m.yaml:4:3: error: unknown format 'formats.dwel' (did you mean 'dwell'?): a format is "
            "an address the machine writes or a named format (docs/machines.md)\n"
            "    dwel: {decimals: 2}\n"
            "    ^\n"
            "m.yaml:6:3: error: unknown template 'templates.spindle_cs' (did you mean "
            "'spindle_css'?)\n"
            "    spindle_cs: [\"G96\"]\n"
            "    ^\n");
}

// A format for an address a key of the machine names (here H, the start-angle word) is known.
TEST(MachineLoader, FormatOfAnAddressTheMachineNames) {
  Machine m;
  std::string errors;
  EXPECT_TRUE(apply_machine_yaml(
      "m.yaml", "formats:\n  H: {decimals: 1}\nthreading: {start_angle_address: H}\n", false, m,
      errors))
      << errors;
  EXPECT_EQ(m.format_for("H").decimals, 1);
  EXPECT_FALSE(apply_machine_yaml("m.yaml", "formats:\n  W: {decimals: 1}\n", false, m, errors));
}

TEST(MachineLoader, SetOfAnUnknownCodeOrFormatIsAnError) {
  Machine m;
  std::string errors;
  EXPECT_FALSE(
      load_machine("generic-lathe", kDirs, {"codes.rapdi=G0"}, shipped_controls(), m, errors));
  EXPECT_EQ(errors,
            "--set codes.rapdi=G0: error: unknown code 'codes.rapdi' (did you mean 'rapid'?)\n");
  errors.clear();
  EXPECT_FALSE(load_machine("generic-lathe", kDirs, {"formats.x.decimals=4"}, shipped_controls(), m,
                            errors));
  EXPECT_EQ(errors,
            "--set formats.x.decimals=4: error: unknown format 'formats.x' (did you mean 'X'?): a "
            "format is an address the machine writes or a named format (docs/machines.md)\n");
  errors.clear();
  EXPECT_TRUE(load_machine("generic-lathe", kDirs,
                           {"codes.coolant_air=M12", "formats.X.decimals=4"}, shipped_controls(), m,
                           errors))
      << errors;
  EXPECT_EQ(m.code("coolant_air"), "M12");
}

// A template that a setting selects is required when it selects it.
TEST(MachineLoader, TemplateSelectedBySettingIsRequired) {
  Machine m;
  std::string errors;
  EXPECT_FALSE(load_machine("generic-lathe", kDirs, {"threading.cycle=fanuc_g76"},
                            shipped_controls(), m, errors));
  EXPECT_EQ(errors, std::string(CLPOST_SOURCE_DIR) +
                        "/machines/generic-lathe.yaml:3:1: error: threading.cycle is 'fanuc_g76', "
                        "which writes template 'templates.fanuc_g76': absent in this machine and "
                        "its post 'iso-lathe'\n"
                        "  extends: iso-lathe\n"
                        "  ^\n");
  errors.clear();
  EXPECT_FALSE(
      load_machine("generic-lathe", kDirs, {"threading.loop=g92"}, shipped_controls(), m, errors));
  EXPECT_NE(errors.find("threading.loop is 'g92', which writes template 'templates.g92':"),
            std::string::npos)
      << errors;
  EXPECT_NE(errors.find("threading.loop is 'g92', which writes template 'templates.g92_next':"),
            std::string::npos)
      << errors;
  errors.clear();
  // The Fanuc control's cycle brings its codes' meanings: G32, G98, G99 (FixedCode).
  EXPECT_TRUE(load_machine("generic-lathe", kDirs,
                           {"threading.cycle=fanuc_g76", "templates.fanuc_g76=[\"G76 X{x} Z{z}\"]",
                            "codes.thread=G32", "codes.feed_per_min=G98", "codes.feed_per_rev=G99"},
                           shipped_controls(), m, errors))
      << errors;
}

// One case per template a machine must have: the five every program reaches, each missing in
// turn from a machine of its own, and the cycle templates a setting selects.
TEST(MachineLoader, EveryRequiredTemplateIsRequired) {
  const std::string codes =
      "codes: {rapid: G0, linear: G1, arc_cw: G2, arc_ccw: G3, thread: G33, metric: G21, inch: "
      "G20, spindle_cw: M3, spindle_ccw: M4}\n";
  const std::vector<std::string> always = {"program_start", "program_end", "tool_change",
                                           "spindle_rpm", "spindle_stop"};
  for (const std::string& left_out : always) {
    std::string text = codes + "templates:\n";
    for (const std::string& t : always)
      if (t != left_out) text += "  " + t + ": []\n";
    const std::string path = write_temp("one-less.yaml", text);
    Machine m;
    std::string errors;
    EXPECT_FALSE(load_machine(path, kDirs, {}, shipped_controls(), m, errors));
    EXPECT_EQ(errors, path + ":1:1: error: missing required key 'templates." + left_out +
                          "' (a machine file normally 'extends' a post from posts/ that defines "
                          "them)\n  " +
                          codes.substr(0, codes.find('\n')) + "\n  ^\n");
  }
  const std::vector<std::pair<std::string, std::string>> selected = {
      {"threading.cycle=cycle99",
       "threading.cycle is 'cycle99', which writes template "
       "'templates.cycle99'"},
      {"threading.cycle=fanuc_g76",
       "threading.cycle is 'fanuc_g76', which writes template "
       "'templates.fanuc_g76'"},
      {"threading.cycle=haas_g76",
       "threading.cycle is 'haas_g76', which writes template "
       "'templates.haas_g76'"},
      {"threading.cycle=heidenhain_g31",
       "threading.cycle is 'heidenhain_g31', which writes "
       "template 'templates.heidenhain_g31'"},
      {"threading.cycle=linuxcnc_g76",
       "threading.cycle is 'linuxcnc_g76', which writes template "
       "'templates.linuxcnc_g76'"},
      {"threading.cycle=linuxcnc_g76",
       "threading.cycle is 'linuxcnc_g76', which writes template "
       "'templates.linuxcnc_g76_taper'"},
      {"threading.loop=g92", "threading.loop is 'g92', which writes template 'templates.g92'"},
      {"threading.loop=g92",
       "threading.loop is 'g92', which writes template "
       "'templates.g92_next'"},
  };
  const std::string dir = CLPOST_SOURCE_DIR;
  for (const auto& [set, message] : selected) {
    Machine m;
    std::string errors;
    EXPECT_FALSE(load_machine("generic-lathe", kDirs, {set}, shipped_controls(), m, errors));
    const std::string line = dir + "/machines/generic-lathe.yaml:3:1: error: " + message +
                             ": absent in this machine and its post 'iso-lathe'\n"
                             "  extends: iso-lathe\n"
                             "  ^\n";
    EXPECT_NE(errors.find(line), std::string::npos) << set << "\n" << errors;
  }
}

// `dwell: []` is the integrator's choice to write nothing; a template selected by a setting may
// be that too.
TEST(MachineLoader, AnEmptyTemplateIsPresent) {
  Machine m;
  std::string errors;
  EXPECT_TRUE(load_machine(
      "generic-lathe", kDirs,
      {"templates.dwell=[]", "threading.loop=g92", "templates.g92=[]", "templates.g92_next=[]"},
      shipped_controls(), m, errors))
      << errors;
  EXPECT_TRUE(m.templates.at("dwell").empty());
}

}  // namespace
}  // namespace clpost

namespace clpost {
namespace {

// A control's own codes are its meaning (machine/control.h: FixedCode): a machine file or --set
// that redefines one fails to load, naming the key and the control's meaning; builder codes
// (coolant) stay machine data.
TEST(MachineLoader, AControlsFixedCodesCannotBeRedefined) {
  Machine m;
  std::string errors;
  EXPECT_FALSE(load_machine("fanuc-0i-t", {CLPOST_SOURCE_DIR}, {"codes.spindle_cw=M4"},
                            shipped_controls(), m, errors));
  EXPECT_EQ(errors,
            "--set: error: codes.spindle_cw is 'M4', but on the fanuc control M3 starts the "
            "spindle clockwise: a control's own codes are its meaning, not machine data\n");
  errors.clear();
  const std::string path = ::testing::TempDir() + "/fixed-codes.yaml";
  std::ofstream(path) << "extends: linuxcnc\ncodes:\n  feed_per_rev: G99\n";
  EXPECT_FALSE(load_machine(path, {CLPOST_SOURCE_DIR}, {}, shipped_controls(), m, errors));
  EXPECT_EQ(errors, path +
                        ":3:3: error: codes.feed_per_rev is 'G99', but on the linuxcnc control "
                        "G95 is feed per revolution: a control's own codes are its meaning, not "
                        "machine data\n    feed_per_rev: G99\n    ^\n");
  errors.clear();
  EXPECT_TRUE(load_machine("fanuc-0i-t", {CLPOST_SOURCE_DIR}, {"codes.coolant_flood=M7"},
                           shipped_controls(), m, errors))
      << errors;
  // A machine without a control of the registry (plain ISO) keeps every code its own.
  EXPECT_TRUE(load_machine("generic-lathe", {CLPOST_SOURCE_DIR}, {"codes.spindle_cw=M4"},
                           shipped_controls(), m, errors))
      << errors;
}

}  // namespace
}  // namespace clpost

#include "machine/machine_schema.h"

#include <gtest/gtest.h>

#include "machine/control.h"
#include "machine/machine_loader.h"

namespace clpost {
namespace {

using enum FieldKind;
using enum Need;

// A control of this test's own, declaring a key, a code, a format, two templates and a loop block.
constexpr KeySpec kProbeKeys[] = {{"threading.probe_depth", "Control facts", KeyType::kNumber,
                                   ControlSlot{.initial = 2.5}, "the probe's depth", 0, 10}};
constexpr NameSpec kProbeCodes[] = {{"probe_on", "the probe's own code"}};
constexpr NameSpec kProbeFormats[] = {{"probe_depth", "the probe cycle's depth"}};
constexpr TemplateField kProbeFields[] = {{"depth", kText, "depth, format probe_depth"}};
constexpr TemplateSpec kProbeCycle{"probe_cycle",       kProbeFields,      kSetting,
                                   "the probe's cycle", "threading.cycle", "probe_g1"};
constexpr TemplateSpec kProbeNote{"probe_note", {}, kOptional, "a note", {}, {}, "PPRINT"};
constexpr TemplateSpec kProbeLoop{"probe_loop", {}, kSetting, "a loop", "threading.loop", "p1"};
constexpr const TemplateSpec* kProbeTemplates[] = {&kProbeCycle, &kProbeNote, &kProbeLoop};
constexpr LoopBlock kProbeLoops[] = {{"p1"}};
constexpr Control kProbe{.name = "probe",
                         .cycle = "probe_g1",
                         .keys = kProbeKeys,
                         .codes = kProbeCodes,
                         .formats = kProbeFormats,
                         .templates = kProbeTemplates,
                         .loops = kProbeLoops};
constexpr const Control* kProbeSet[] = {&kProbe};

// The set's declarations join the program's own: each after the program's that come before the
// controls' (the codes before live_spindle_cw, the templates before the holes'), threading.cycle
// choosing among "none" and the set's cycles.
TEST(MachineSchema, IsBuiltFromTheSetOfControls) {
  const Schema none = schema({});
  const Schema probe = schema(kProbeSet);
  EXPECT_EQ(find_code(none, "probe_on"), nullptr);
  ASSERT_NE(find_code(probe, "probe_on"), nullptr);
  ASSERT_EQ(probe.codes.size(), none.codes.size() + 1);
  EXPECT_EQ(probe.codes[22].name, "thread_decreasing");
  EXPECT_EQ(probe.codes[23].name, "probe_on");
  EXPECT_EQ(probe.codes[24].name, "live_spindle_cw");
  EXPECT_NE(find_format(probe, "probe_depth"), nullptr);
  EXPECT_EQ(probe.formats.back().name, "probe_depth");
  EXPECT_EQ(find_template(none, "probe_cycle"), nullptr);
  EXPECT_EQ(find_template(probe, "probe_cycle"), &kProbeCycle);
  EXPECT_EQ(probe.templates[7], &kProbeCycle);  // after program_start … dwell
  EXPECT_EQ(probe.templates[8], &kProbeNote);
  EXPECT_EQ(probe.templates[9], &kProbeLoop);
  EXPECT_EQ(probe.templates[10]->name, "hole_drill");
  const KeySpec* cycle = find_key(probe, "threading.cycle");
  ASSERT_NE(cycle, nullptr);
  ASSERT_EQ(cycle->choices.size(), 2u);
  EXPECT_EQ(cycle->choices[0].name, "none");
  EXPECT_EQ(cycle->choices[1].name, "probe_g1");
  EXPECT_EQ(find_key(none, "threading.cycle")->choices.size(), 1u);
  const KeySpec* loop = find_key(probe, "threading.loop");
  ASSERT_NE(loop, nullptr);
  ASSERT_EQ(loop->choices.size(), 2u);
  EXPECT_EQ(loop->choices[0].name, "g33");
  EXPECT_EQ(loop->choices[1].name, "p1");
  EXPECT_EQ(find_key(none, "threading.loop")->choices.size(), 1u);
  EXPECT_EQ(find_loop(kProbeSet, "p1"), &kProbeLoops[0]);
  EXPECT_EQ(find_loop(kProbeSet, "g33"), nullptr);
  EXPECT_TRUE(declared_code(kProbeSet, "probe_on"));
  EXPECT_TRUE(declared_code({}, "rapid"));
  EXPECT_FALSE(declared_code({}, "probe_on"));
}

// A control's key is kept by its slot: its initial value until a file sets it, read by the
// control through the key (control_value).
TEST(MachineSchema, AControlsKeyIsKeptInItsSlot) {
  const Schema s = schema(kProbeSet);
  const KeySpec* k = find_key(s, "threading.probe_depth");
  ASSERT_NE(k, nullptr);
  EXPECT_EQ(std::get<ControlSlot>(k->member).index, 0u);
  EXPECT_EQ(s.control_defaults, std::vector<double>{2.5});
  Machine m;
  m.controls = kProbeSet;
  EXPECT_EQ(key_value_text(*k, m), "2.5");
  std::string errors;
  ASSERT_TRUE(apply_machine_yaml("m.yaml", "threading: {cycle: probe_g1}\n", false, m, errors))
      << errors;
  EXPECT_EQ(control_value(m, kProbeKeys[0]), 2.5);
  ASSERT_TRUE(apply_machine_yaml("m.yaml", "threading: {probe_depth: 4}\n", false, m, errors))
      << errors;
  EXPECT_EQ(control_value(m, kProbeKeys[0]), 4);
  EXPECT_EQ(key_value_text(*k, m), "4");
  EXPECT_FALSE(apply_machine_yaml("m.yaml", "threading: {probe_depth: 11}\n", false, m, errors));
  EXPECT_NE(errors.find("'threading.probe_depth' is 11 but must be between 0 and 10"),
            std::string::npos)
      << errors;
  EXPECT_EQ(find_key(schema({}), "threading.probe_depth"), nullptr);
}

// Behind another control's keys, the probe's key has the next slot, and the probe reads its own.
TEST(MachineSchema, EachControlReadsItsOwnSlots) {
  static constexpr KeySpec kGaugeKeys[] = {
      {"threading.gauge_a", "Control facts", KeyType::kNumber, ControlSlot{}, "a", 0, 10},
      {"threading.gauge_b", "Control facts", KeyType::kNumber, ControlSlot{.initial = 1}, "b", 0,
       10}};
  static constexpr Control kGauge{.name = "gauge", .cycle = "gauge_g1", .keys = kGaugeKeys};
  constexpr const Control* kBoth[] = {&kGauge, &kProbe};
  const Schema s = schema(kBoth);
  EXPECT_EQ(s.control_defaults, (std::vector<double>{0, 1, 2.5}));
  EXPECT_EQ(std::get<ControlSlot>(find_key(s, "threading.probe_depth")->member).index, 2u);
  EXPECT_EQ(first_slot(kBoth, &kProbe), 2u);
  Machine m;
  m.controls = kBoth;
  std::string errors;
  ASSERT_TRUE(apply_machine_yaml(
      "m.yaml", "threading: {cycle: probe_g1, gauge_b: 7, probe_depth: 3}\n", false, m, errors))
      << errors;
  EXPECT_EQ(m.control_values, (std::vector<double>{0, 7, 3}));
  EXPECT_EQ(control_value(m, kProbeKeys[0]), 3);
}

// A machine loaded with the set may use what the set declares; one without it may not.
TEST(MachineSchema, AMachineFileMayUseWhatItsSetDeclares) {
  const std::string doc =
      "threading: {cycle: probe_g1, loop: p1}\ncodes: {probe_on: M77}\nformats: {probe_depth: "
      "{decimals: "
      "4}}\ntemplates: {probe_cycle: \"G1 Z{depth}\"}\n";
  Machine m;
  m.controls = kProbeSet;
  std::string errors;
  EXPECT_TRUE(apply_machine_yaml("m.yaml", doc, false, m, errors)) << errors;
  EXPECT_EQ(m.control, &kProbe);
  EXPECT_EQ(m.thread_loop, &kProbeLoops[0]);
  EXPECT_EQ(m.code("probe_on"), "M77");
  EXPECT_EQ(m.format_for("probe_depth").decimals, 4);
  Machine plain;
  errors.clear();
  EXPECT_FALSE(apply_machine_yaml("m.yaml", doc, false, plain, errors));
  EXPECT_NE(errors.find("m.yaml:1:20: error: 'threading.cycle' must be one of none, not "
                        "'probe_g1'"),
            std::string::npos)
      << errors;
  EXPECT_NE(errors.find("m.yaml:1:36: error: 'threading.loop' must be one of g33, not 'p1'"),
            std::string::npos)
      << errors;
  EXPECT_NE(errors.find("m.yaml:2:9: error: unknown code 'codes.probe_on'"), std::string::npos)
      << errors;
  EXPECT_NE(errors.find("m.yaml:3:11: error: unknown format 'formats.probe_depth'"),
            std::string::npos)
      << errors;
  EXPECT_NE(errors.find("m.yaml:4:13: error: unknown template 'templates.probe_cycle'"),
            std::string::npos)
      << errors;
}

// Every key's default, written back as a machine file, loads: the schema's rendering and the
// loader agree, and every declared key is one the loader takes.
TEST(MachineSchema, DefaultsRoundTripThroughTheLoader) {
  const Machine defaults;
  for (const KeySpec& k : schema(kProbeSet).keys) {
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
    m.controls = kProbeSet;
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
  const Schema s = schema({});
  EXPECT_EQ(key_value_text(*find_key(s, "threading.strategy"), m), "loop");
  EXPECT_EQ(key_value_text(*find_key(s, "output.line_ending"), m), "crlf");
  EXPECT_EQ(key_value_text(*find_key(s, "threading.cycle_pass_end"), m), "shifted");
  EXPECT_EQ(key_value_text(*find_key(s, "threading.run_in"), m), "2.5");
  m.run_in.automatic = true;
  EXPECT_EQ(key_value_text(*find_key(s, "threading.run_in"), m), "auto");
  EXPECT_EQ(key_value_text(*find_key(s, "block_numbers.skip"), m), "[\"%\", \"O\"]");
  EXPECT_EQ(find_key(s, "threading.strategi"), nullptr);
}

TEST(MachineSchema, WhichTemplatesAMachineNeeds) {
  const Schema s = schema(kProbeSet);
  Machine m;
  EXPECT_TRUE(template_required(s, tmpl::kProgramStart, m));
  EXPECT_FALSE(template_required(s, tmpl::kSpindleCss, m));  // only SPINDL/…,SMM reaches it
  EXPECT_FALSE(template_required(s, kProbeCycle, m));
  m.control = &kProbe;
  EXPECT_TRUE(template_required(s, kProbeCycle, m));
  EXPECT_FALSE(template_required(s, kProbeNote, m));
  EXPECT_FALSE(template_required(s, kProbeLoop, m));
  m.thread_loop = &kProbeLoops[0];
  EXPECT_TRUE(template_required(s, kProbeLoop, m));
  // Compile-time field lookup.
  static_assert(kProbeCycle.field("depth", FieldKind::kText) == 0);
  static_assert(tmpl::kToolChange.field("tool", FieldKind::kWhole) == 0);
}

}  // namespace
}  // namespace clpost

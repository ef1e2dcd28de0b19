// A control that is not shipped, registered in this test's own set of controls (the shipped ones
// and the toy), declares its templates, a machine key, a code and a loop block, posts a thread
// with its cycle and with its loop block, and verifies both: the path a new control takes
// (docs/adding-a-control.md), end to end, with no file outside tests/toy_control/.
#include <gtest/gtest.h>

#include <filesystem>
#include <fstream>
#include <vector>

#include "controls/registry.h"
#include "interpreter/post.h"
#include "machine/machine_loader.h"
#include "machine/machine_schema.h"
#include "reader/line_source.h"
#include "toy_control/toy_control.h"
#include "verify/program_verify.h"

namespace clpost {
namespace {

// OPTION 0 (radial infeed): four roughing passes and a finish pass, each one block.
constexpr const char* kCl =
    "UNITS/MM\nLOADTL/1\nSPINDL/500,RPM,CLW\nFEDRAT/0.2,MMPR\nRAPID\nGOTO/15,0,5\n"
    "THREAD/ON,DEPTH,1.2,CUTS,4,FINCUT,1,0.1,OPTION,0,MMPR,2\nGOTO/10,0,2\nGOTO/10,0,-20\n"
    "THREAD/OFF\nRAPID\nGOTO/50,0,50\nFINI\n";

// The toy's lines and its code, as a machine file gives them.
constexpr const char* kToyLines =
    "codes: {toy_cycle_end: M178}\n"
    "templates:\n"
    "  toy_g177: \"G177 X{x} Z{z} K{k} F{f}\"\n"
    "  toy_g178: \"G178 X{x} Z{z}{f}\"\n";

std::vector<const Control*> with_toy() {
  std::vector<const Control*> set(shipped_controls().begin(), shipped_controls().end());
  set.push_back(&toy::kControl);
  return set;
}

std::string toy_machine_file(const std::string& threading) {
  const std::string path = ::testing::TempDir() + "/toy-lathe.yaml";
  std::ofstream(path) << "extends: iso-lathe\ndescription: a lathe with the toy control\n"
                      << "block_numbers: {enabled: false}\n"
                      << kToyLines << "threading: " << threading << "\n";
  return path;
}

Machine toy_machine(ControlSet controls, const std::string& threading,
                    const std::vector<std::string>& sets = {}) {
  Machine m;
  std::string errors;
  EXPECT_TRUE(
      load_machine(toy_machine_file(threading), {CLPOST_SOURCE_DIR}, sets, controls, m, errors))
      << errors;
  return m;
}

size_t count(const std::string& text, const std::string& what) {
  size_t n = 0;
  for (size_t at = 0; (at = text.find(what, at)) != std::string::npos; ++at) ++n;
  return n;
}

// Posts kCl on `m` and verifies the program: five passes planned, five cut.
std::string post_and_verify(const Machine& m) {
  PostOptions opts;
  opts.keep_motions = true;
  const PostedText posted = post_text(kCl, m, "toy.cl", opts);
  EXPECT_EQ(posted.diags.error_count(), 0u) << posted.diags.render_all();
  reader::LineSource src{std::string_view(posted.program)};
  const ClExpected expected{posted.summary.holes, posted.summary.path, posted.summary.mill};
  const VerifyOutcome v =
      verify_program(src, "toy.nc", posted.plans, &expected, "toy.cl", m, 0.001);
  EXPECT_TRUE(v.ok) << v.report << v.diagnostics << posted.program;
  EXPECT_NE(v.report.find("5 passes planned, 5 cut"), std::string::npos) << v.report;
  return posted.program;
}

TEST(ToyControl, PostsItsCycleAndVerifies) {
  const std::vector<const Control*> controls = with_toy();
  const Machine m = toy_machine(controls, "{strategy: cycle, cycle: toy_g177, fallback: emulate}");
  ASSERT_EQ(m.control, &toy::kControl);
  const std::string program = post_and_verify(m);
  // Five passes, one block each through the template, the first 0.44 deep (X 2 x 9.56), the
  // last at the full depth 1.2 below the crest (radius 10, so X is the diameter 2 x 8.8 = 17.6),
  // each from K2 (the plan's start Z); then the toy's code.
  EXPECT_EQ(count(program, "G177 X"), 5u) << program;
  EXPECT_NE(program.find("G177 X19.12 Z-20. K2. F2.\n"), std::string::npos) << program;
  EXPECT_NE(program.find("G177 X17.6 Z-20. K2. F2.\nM178\n"), std::string::npos) << program;
}

// Parameter 7 (threading.toy_run_in, the toy's key) moves where G177 starts its cut: one lead
// (F2.) before K, away from Z, so the emitter writes K 2 mm nearer Z for the plan's start Z2,
// and the read-back, reading the same key, finds the same passes.
TEST(ToyControl, ItsKeyIsReadByItsLawBothWays) {
  const std::vector<const Control*> controls = with_toy();
  const Machine m = toy_machine(controls, "{strategy: cycle, cycle: toy_g177, fallback: emulate}",
                                {"threading.toy_run_in=1"});
  EXPECT_EQ(control_value(m, toy::kControl.keys[0]), 1);
  const std::string program = post_and_verify(m);
  EXPECT_EQ(count(program, "G177 X"), 5u) << program;
  EXPECT_NE(program.find("G177 X17.6 Z-20. K0. F2.\n"), std::string::npos) << program;
}

// The loop block: all five passes from one start point S (radial infeed: one start Z), one
// G178 block each, F only in the first (the read-back keeps it in the toy's read-back state), no
// move between them (each block returns to S). The passes' depths are the plan's: roughing to
// 1.2 - 0.1 = 1.1 in four cuts of 4, 3, 2 and 1 tenths of it (0.44, 0.77, 0.99, 1.1), then 1.2:
// X = 2 x (10 - depth).
TEST(ToyControl, PostsItsLoopBlockAndVerifies) {
  const std::vector<const Control*> controls = with_toy();
  const Machine m = toy_machine(controls, "{strategy: loop, loop: toy_g178, fallback: emulate}");
  ASSERT_NE(m.thread_loop, nullptr);
  EXPECT_EQ(m.thread_loop->name, "toy_g178");
  const std::string program = post_and_verify(m);
  EXPECT_NE(program.find("G178 X19.12 Z-20. F2.\nG178 X18.46 Z-20.\nG178 X18.02 Z-20.\n"
                         "G178 X17.8 Z-20.\nG178 X17.6 Z-20.\nM178\n"),
            std::string::npos)
      << program;
}

TEST(ToyControl, ACycleItCannotSayFallsBackWithItsReason) {
  const std::vector<const Control*> controls = with_toy();
  const Machine m = toy_machine(controls, "{strategy: cycle, cycle: toy_g177, fallback: emulate}");
  std::string cl = kCl;
  cl.replace(cl.find("OPTION,0"), 8, "OPTION,0,CHAMFR,2");  // a pull-out: G177 has none
  const PostedText posted = post_text(cl, m, "toy.cl");
  ASSERT_EQ(posted.diags.error_count(), 0u) << posted.diags.render_all();
  EXPECT_NE(posted.program.find("(G177 not used: a pull-out. emulation instead)"),
            std::string::npos)
      << posted.program;
}

// Its code's meaning is its own: a machine file or --set may not change it.
TEST(ToyControl, ItsFixedCodeIsItsMeaning) {
  Machine m;
  std::string errors;
  EXPECT_FALSE(load_machine(toy_machine_file("{cycle: toy_g177}"), {CLPOST_SOURCE_DIR},
                            {"codes.toy_cycle_end=M179"}, with_toy(), m, errors));
  EXPECT_NE(errors.find("--set: error: codes.toy_cycle_end is 'M179', but on the toy control "
                        "M178 ends a run of G177 or G178 blocks"),
            std::string::npos)
      << errors;
}

// The schema of the toy's set has what it declares, after the program's own.
TEST(ToyControl, TheSchemaOfItsSetHasWhatItDeclares) {
  const std::vector<const Control*> controls = with_toy();
  const Schema s = schema(controls);
  EXPECT_NE(find_key(s, "threading.toy_run_in"), nullptr);
  EXPECT_NE(find_code(s, "toy_cycle_end"), nullptr);
  EXPECT_NE(find_template(s, "toy_g177"), nullptr);
  EXPECT_NE(find_template(s, "toy_g178"), nullptr);
  EXPECT_EQ(find_key(s, "threading.loop")->choices.back().name, "toy_g178");
  EXPECT_EQ(find_key(s, "threading.cycle")->choices.back().name, "toy_g177");
}

// The shipped set knows none of it: the cycle, the loop, the key, the code and the templates are
// errors there, each naming what the set has.
TEST(ToyControl, OnlyASetThatRegistersItCanSelectIt) {
  Machine m;
  std::string errors;
  EXPECT_FALSE(load_machine(
      toy_machine_file("{strategy: cycle, cycle: toy_g177, loop: toy_g178, toy_run_in: 1}"),
      {CLPOST_SOURCE_DIR}, {}, shipped_controls(), m, errors));
  // threading.cycle's and threading.loop's choices in the shipped set: the registry's.
  std::string cycles = "none", loops = "g33";
  for (const Control* c : shipped_controls()) {
    cycles += ", " + std::string(c->cycle);
    for (const LoopBlock& l : c->loops) loops += ", " + std::string(l.name);
  }
  EXPECT_NE(errors.find("error: 'threading.cycle' must be one of " + cycles + ", not 'toy_g177'"),
            std::string::npos)
      << errors;
  EXPECT_NE(errors.find("error: 'threading.loop' must be one of " + loops + ", not 'toy_g178'"),
            std::string::npos)
      << errors;
  for (const char* e :
       {"error: unknown key 'threading.toy_run_in'", "error: unknown code 'codes.toy_cycle_end'",
        "error: unknown template 'templates.toy_g177'",
        "error: unknown template 'templates.toy_g178'"})
    EXPECT_NE(errors.find(e), std::string::npos) << e << "\n" << errors;
}

}  // namespace
}  // namespace clpost

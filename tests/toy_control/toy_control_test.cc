// A control that is not shipped, registered through the registry's type (a ControlSet of the
// shipped controls and the toy), posts a thread with its own cycle and verifies it: the path a
// new control takes (docs/adding-a-control.md), end to end.
#include <gtest/gtest.h>

#include <filesystem>
#include <fstream>
#include <vector>

#include "controls/registry.h"
#include "interpreter/post.h"
#include "machine/machine_loader.h"
#include "reader/line_source.h"
#include "toy_control/toy_control.h"
#include "verify/program_verify.h"

namespace clpost {
namespace {

// OPTION 0 (radial infeed): four roughing passes and a finish pass, each one G177 block.
constexpr const char* kCl =
    "UNITS/MM\nLOADTL/1\nSPINDL/500,RPM,CLW\nFEDRAT/0.2,MMPR\nRAPID\nGOTO/15,0,5\n"
    "THREAD/ON,DEPTH,1.2,CUTS,4,FINCUT,1,0.1,OPTION,0,MMPR,2\nGOTO/10,0,2\nGOTO/10,0,-20\n"
    "THREAD/OFF\nRAPID\nGOTO/50,0,50\nFINI\n";

std::vector<const Control*> with_toy() {
  std::vector<const Control*> set(shipped_controls().begin(), shipped_controls().end());
  set.push_back(&toy::kControl);
  return set;
}

Machine toy_machine(ControlSet controls, const std::string& threading) {
  const std::string path = ::testing::TempDir() + "/toy-lathe.yaml";
  std::ofstream(path) << "extends: iso-lathe\ndescription: a lathe with the toy control\n"
                      << "block_numbers: {enabled: false}\nthreading: " << threading << "\n";
  Machine m;
  std::string errors;
  EXPECT_TRUE(load_machine(path, {CLPOST_SOURCE_DIR}, {}, controls, m, errors)) << errors;
  return m;
}

TEST(ToyControl, PostsItsCycleAndVerifies) {
  const std::vector<const Control*> controls = with_toy();
  const Machine m = toy_machine(controls, "{strategy: cycle, cycle: toy_g177, fallback: emulate}");
  ASSERT_EQ(m.control, &toy::kControl);
  PostOptions opts;
  opts.keep_motions = true;
  const PostedText posted = post_text(kCl, m, "toy.cl", opts);
  ASSERT_EQ(posted.diags.error_count(), 0u) << posted.diags.render_all();
  // Five passes, one block each; the last two at the full depth 1.2 below the crest (radius 10,
  // so X is the diameter 2 x 8.8 = 17.6), the first at 10 - 0.6 = 9.4 (radial infeed: the depth
  // ladder's first pass).
  size_t blocks = 0;
  for (size_t at = 0; (at = posted.program.find("G177 X", at)) != std::string::npos; ++at) ++blocks;
  EXPECT_EQ(blocks, 5u) << posted.program;
  EXPECT_NE(posted.program.find("G177 X17.6 Z-20. K2. F2.\n"), std::string::npos) << posted.program;

  reader::LineSource src{std::string_view(posted.program)};
  const ClExpected expected{posted.summary.holes, posted.summary.path, posted.summary.mill};
  const VerifyOutcome v =
      verify_program(src, "toy.nc", posted.plans, &expected, "toy.cl", m, 0.001);
  EXPECT_TRUE(v.ok) << v.report << v.diagnostics;
  EXPECT_NE(v.report.find("5 passes planned, 5 cut"), std::string::npos) << v.report;
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

TEST(ToyControl, OnlyASetThatRegistersItCanSelectIt) {
  Machine m;
  std::string errors;
  const std::string path = ::testing::TempDir() + "/toy-lathe-shipped.yaml";
  std::ofstream(path) << "extends: iso-lathe\nthreading: {strategy: cycle, cycle: toy_g177}\n";
  EXPECT_FALSE(load_machine(path, {CLPOST_SOURCE_DIR}, {}, shipped_controls(), m, errors));
  EXPECT_NE(errors.find("'threading.cycle' must be one of none, cycle99, fanuc_g76, haas_g76, "
                        "heidenhain_g31, linuxcnc_g76, not 'toy_g177'"),
            std::string::npos)
      << errors;
}

}  // namespace
}  // namespace clpost

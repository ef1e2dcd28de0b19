#include "writer/nc_program.h"

#include <gtest/gtest.h>

namespace clpost {
namespace {

Machine test_machine() {
  Machine m;
  m.codes = {{"rapid", "G0"},         {"linear", "G1"},  {"arc_cw", "G2"},
             {"arc_ccw", "G3"},       {"thread", "G33"}, {"feed_per_rev", "G95"},
             {"feed_per_min", "G94"}, {"metric", "G21"}, {"coolant_flood", "M8"},
             {"coolant_off", "M9"}};
  m.templates["program_start"] = {"%", "O{program_number:04}", "G18 {units_code}"};
  m.templates["spindle_rpm"] = {"G97 S{rpm} {direction}"};
  m.codes["spindle_cw"] = "M3";
  m.formats["S"] = NumberFormat{0, false, true, true, 1};
  return m;
}

TEST(NcProgram, ModalWordsAndDiameterOutput) {
  Machine m = test_machine();
  StringSink out;
  NcProgram p(m, out);
  p.start("", false, "x.cl");
  p.spindle_rpm(1200, SpindleDir::kCw);
  p.rapid({22, 2});  // radius 22 -> X44.
  p.rapid({22, 0});  // only Z changes
  p.set_feed(0.2, FeedMode::kPerRev);
  p.linear({-0.4, 0});  // G1, X-0.8, G95 F0.2 on the first feed move
  p.linear({-0.4, 1});  // only Z
  p.set_feed(0.15, FeedMode::kPerRev);
  p.linear({15, 1});  // new F only
  EXPECT_EQ(out.out,
            "%\nO0001\nG18 G21\nG97 S1200 M3\nG0 X44. Z2.\nZ0.\nG1 X-0.8 G95 F0.2\nZ1.\n"
            "X30. F0.15\n");
}

TEST(NcProgram, BlockNumbersWrap) {
  Machine m = test_machine();
  m.block_numbers = true;
  m.block_start = 10;
  m.block_step = 10;
  m.block_max = 30;
  StringSink out;
  NcProgram p(m, out);
  p.rapid({1, 1});
  p.rapid({2, 1});
  p.rapid({3, 1});
  p.rapid({4, 1});
  p.comment("(done)");
  EXPECT_EQ(out.out, "N10 G0 X2. Z1.\nN20 X4.\nN30 X6.\nN10 X8.\nN20 (done)\n");
}

TEST(NcProgram, ArcCentreIsIncrementalRadius) {
  Machine m = test_machine();
  StringSink out;
  NcProgram p(m, out);
  p.set_feed(0.15, FeedMode::kPerRev);
  p.linear({15, -20});
  // Fillet R2 from (r15, z-20) to (r17, z-22) about (r17, z-20): I = 17-15 = 2, K = -20-(-20) = 0.
  p.arc({17, -22}, {17, -20}, false);
  EXPECT_EQ(out.out, "G1 X30. Z-20. G95 F0.15\nG2 X34. Z-22. I2. K0.\n");
}

TEST(NcProgram, ThreadLeadInFRestatesTheFeedAfterwards) {
  Machine m = test_machine();
  m.thread_lead_address = "F";
  StringSink out;
  NcProgram p(m, out);
  p.set_feed(0.2, FeedMode::kPerRev);
  p.linear({10, 0});
  p.thread({10, -20}, 1.5);
  p.linear({12, -20});  // F0.2 again: F1.5 replaced it on the control
  EXPECT_EQ(out.out, "G1 X20. Z0. G95 F0.2\nG33 Z-20. F1.5\nG1 X24. F0.2\n");
}

}  // namespace
}  // namespace clpost

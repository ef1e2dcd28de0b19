// The modal state read back from a program through each shipped post's codes and templates
// (modal_words.cc): tool and offset, feed mode and F, spindle direction, RPM or CSS, the speed
// and the CSS limit, each as the move after it is made with.
#include <gtest/gtest.h>

#include "simulator/control_sim.h"
#include "simulator/sim_test_util.h"

namespace clpost {
namespace {

using testing::shipped;

// The states of a program's moves, each move's in order.
std::vector<CutState> move_states(const std::string& machine, std::string_view program,
                                  StateReadback* readback = nullptr) {
  const Machine m = shipped(machine);
  Diagnostics d("p.nc");
  reader::LineSource src(program);
  Simulation sim;
  EXPECT_TRUE(simulate_nc(src, m, d, sim)) << d.render_all();
  if (readback != nullptr) *readback = sim.path.readback;
  std::vector<CutState> out;
  for (const Toolpath::Entry& e : sim.path.entries)
    out.push_back(sim.path.states[e.move.state].state);
  for (const Move& mv : sim.path.moves) out.push_back(sim.path.states[mv.state].state);
  return out;
}

CutState state(double feed, int per_rev, SpindleRun run, bool css, double speed, double max_rpm,
               int tool, int offset) {
  CutState s;
  s.feed = feed, s.per_rev = static_cast<int8_t>(per_rev), s.spindle = run, s.css = css;
  s.speed = speed, s.max_rpm = max_rpm, s.tool = tool, s.offset = offset;
  return s;
}

TEST(ModalWords, FanucToolWordSplitsByWidthAndG50SetsTheLimit) {
  StateReadback rb;
  // T0312: tool 03, offset 12 ("T{tool:02}{offset:02}"); G50 S2800 is the CSS limit, not a
  // speed; G96 S180 M4 the surface speed, counter-clockwise; G99 F0.15 per revolution.
  const std::vector<CutState> s = move_states(
      "fanuc-0i-t",
      "%\nO0001\nT0312\nG50 S2800\nG96 S180 M4\nG0 X40. Z2.\nG1 Z-10. G99 F0.15\nM5\nG0 X50.\n",
      &rb);
  EXPECT_TRUE(rb.tool && rb.offset && rb.feed_mode && rb.spindle && rb.css && rb.max_rpm);
  ASSERT_EQ(s.size(), 3u);
  EXPECT_EQ(s[0], state(0, -1, SpindleRun::kCcw, true, 180, 2800, 3, 12));
  EXPECT_EQ(s[1], state(0.15, 1, SpindleRun::kCcw, true, 180, 2800, 3, 12));
  EXPECT_EQ(s[2], state(0.15, 1, SpindleRun::kOff, true, 180, 2800, 3, 12));
}

TEST(ModalWords, SiemensToolAndOffsetWordsAndLims) {
  const std::vector<CutState> s =
      move_states("sinumerik-840d",
                  "T4 D7\nLIMS=3200\nG96 S150 M3\nG0 X30 Z2\nG1 Z-5 F0.2\nG97 S900 M3\n"
                  "G1 X32 G94 F120\nG96 S150\nX34 G961 F120\nX36 G94\n");
  ASSERT_EQ(s.size(), 5u);
  // G96 is feed per revolution at constant cutting speed (SINUMERIK's group 15).
  EXPECT_EQ(s[1], state(0.2, 1, SpindleRun::kCw, true, 150, 3200, 4, 7));
  EXPECT_EQ(s[2], state(120, 0, SpindleRun::kCw, false, 900, 3200, 4, 7));
  // G961 per minute at constant cutting speed; G94 ends constant cutting speed.
  EXPECT_EQ(s[3], state(120, 0, SpindleRun::kCw, true, 150, 3200, 4, 7));
  EXPECT_EQ(s[4].css, false);
}

TEST(ModalWords, LinuxcncChangesToolsOnlyWithM6AndReadsG96D) {
  StateReadback rb;
  // T5 alone selects the tool; "T{tool} M6 G43 H{offset}" changes it, H the offset. G96 D2500
  // S120: D is the limit.
  const std::vector<CutState> s = move_states(
      "linuxcnc-lathe", "T5\nG0 X10 Z2\nT5 M6 G43 H12\nG96 D2500 S120 M3\nG1 Z0 G95 F0.1\n", &rb);
  EXPECT_TRUE(rb.tool);
  EXPECT_TRUE(rb.offset);  // G43 H{offset}
  ASSERT_EQ(s.size(), 2u);
  EXPECT_EQ(s[0], state(0, -1, SpindleRun::kOff, false, 0, 0, -1, -1));
  EXPECT_EQ(s[1], state(0.1, 1, SpindleRun::kCw, true, 120, 2500, 5, 12));
}

TEST(ModalWords, HeidenhainG26IsTheLimitAndG97TheRpm) {
  const std::vector<CutState> s = move_states(
      "heidenhain-pilot", "N 10 T2\nN 20 G26 S2500\nN 30 G97 S600 M3\nN 40 G0 X20. Z2.\n");
  ASSERT_EQ(s.size(), 1u);
  EXPECT_EQ(s[0], state(0, -1, SpindleRun::kCw, false, 600, 2500, 2, -1));
}

TEST(ModalWords, AnOffsetOutOfRangeIsAnErrorAtItsWord) {
  const Machine m = shipped("sinumerik-840d");
  Diagnostics d("p.mpf");
  reader::LineSource src(std::string_view("T2 D99999\nG0 X10 Z2\n"));
  Simulation sim;
  EXPECT_FALSE(simulate_nc(src, m, d, sim));
  EXPECT_EQ(d.render_all(),
            "p.mpf:1:4: error: the offset 99999: a whole number from 0 to 9999 expected\n"
            "  T2 D99999\n"
            "     ^\n");
}

}  // namespace
}  // namespace clpost

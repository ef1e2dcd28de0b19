// Chained threads (threading.md section 11) on every shipped machine: one synchronized block per
// segment with the lead on each and the start angle on the first only, and the cycles that cut
// one straight line falling back with their reason in a comment.
#include <gtest/gtest.h>

#include <algorithm>
#include <string>

#include "emitters/emitter_test_util.h"
#include "machine/machine_test_util.h"

namespace clpost {
namespace {

using testing::emit_on;
using testing::plan_for;
using testing::shipped_machine;

// A 30 mm cylinder 10 long, then a taper to diameter 32 at Z-20; depth 0.5 in one radial pass
// (OPTION 0), tool at X20 Z5: pass (X 14.5, Z 0) -> (X 14.5, Z -10) -> (X 15.5, Z -20).
const char* const kChain = "THREAD/ON,MMPR,1.5,DEPTH,0.5,OPTION,0,CHAIN";
const std::vector<Vec2> kContour = {{15, 0}, {15, -10}, {16, -20}};

std::string emitted(const std::string& machine, const char* on = kChain) {
  const Machine m = shipped_machine(machine);
  const testing::Emitted e = emit_on(m, plan_for(m, on, {20, 5}, kContour));
  EXPECT_TRUE(e.ok) << e.diags;
  return e.nc;
}

TEST(ChainOutput, G33BlockPerSegmentInEmulation) {
  EXPECT_EQ(emitted("generic-lathe"),
            "N10 (pass 1 depth 0.5000 rough)\n"
            "N20 G1 X40. Z0. G95 F0.2\n"
            "N30 X29.\n"
            "N40 G33 Z-10. F1.5\n"
            "N50 X31. Z-20. F1.5\n"
            "N60 G0 X40.\n"
            "N70 Z0.\n");
}

TEST(ChainOutput, CyclesFallBackWithTheirReason) {
  struct Case {
    const char* machine;
    const char* comment;  // the fallback comment ("" for a machine with no cycle)
    const char* first;    // the first synchronized block
    const char* second;   // the second
  };
  // Every shipped machine needs its row (checked below).
  const std::vector<Case> cases = {
      {"generic-lathe", "", "G33 Z-10. F1.5", "X31. Z-20. F1.5"},
      {"fanuc-0i-t",
       "(G76 NOT USED: A CHAINED THREAD: G76 CUTS ONE STRAIGHT THREAD LINE. EMULATION INSTEAD)",
       "G32 Z-10. F1.5", "X31. Z-20. F1.5"},
      {"haas-st",
       "(G76 NOT USED: A CHAINED THREAD: G76 CUTS ONE STRAIGHT THREAD LINE. EMULATION INSTEAD)",
       "G32 Z-10. F1.5", "X31. Z-20. F1.5"},
      // The live-tool machines thread as the lathes they extend.
      {"fanuc-0i-tf-live",
       "(G76 NOT USED: A CHAINED THREAD: G76 CUTS ONE STRAIGHT THREAD LINE. EMULATION INSTEAD)",
       "G32 Z-10. F1.5", "X31. Z-20. F1.5"},
      {"haas-st-20y",
       "(G76 NOT USED: A CHAINED THREAD: G76 CUTS ONE STRAIGHT THREAD LINE. EMULATION INSTEAD)",
       "G32 Z-10. F1.5", "X31. Z-20. F1.5"},
      {"linuxcnc-lathe",
       "(G76 not used: a chained thread: G76 cuts one straight thread line. emulation instead)",
       "G33 Z-10. K1.5", "X31. Z-20. K1.5"},
      {"linuxcnc-lathe-c",
       "(G76 not used: a chained thread: G76 cuts one straight thread line. emulation instead)",
       "G33 Z-10. K1.5", "X31. Z-20. K1.5"},
      {"heidenhain-pilot",
       "[G31 not used: a chained thread: clpost writes G31 for one straight thread line only. "
       "G33 loop instead]",
       "G33 Z-10. F1.5", "X31. Z-20. F1.5"},
      // CYCLE98 is tried first (OPTION 0 is not one of its laws), then the G33 loop.
      {"sinumerik-840d",
       "; CYCLE98 not used: OPTION 0, steps shrinking by a constant amount: CYCLE98 cuts constant "
       "infeed (VARI 1, 2) or constant cross-section (VARI 3, 4). G33 loop instead",
       "G33 Z-10 K1.5", "X31 Z-20 K1.5"},
      {"nct-2000t", "", "G33 Z-10. F1.5", "X31. Z-20. F1.5"},
  };
  const std::vector<std::string> machines = testing::shipped_machine_names();
  ASSERT_FALSE(machines.empty());
  for (const Case& c : cases)
    EXPECT_NE(std::find(machines.begin(), machines.end(), c.machine), machines.end())
        << "machine " << c.machine << " is not shipped: remove its row";
  for (const std::string& name : machines) {
    const auto row =
        std::find_if(cases.begin(), cases.end(), [&](const Case& c) { return c.machine == name; });
    if (row == cases.end()) {
      ADD_FAILURE() << "machine " << name << " has no expected chained-thread blocks: add them";
      continue;
    }
    const Case& c = *row;
    const std::string nc = emitted(c.machine);
    SCOPED_TRACE(c.machine);
    EXPECT_NE(nc.find(c.comment), std::string::npos) << nc;
    const size_t first = nc.find(std::string(c.first) + "\n");
    ASSERT_NE(first, std::string::npos) << nc;
    // The next block is the second segment: nothing between them, one synchronization.
    const size_t next = nc.find('\n', first) + 1;
    const std::string line = nc.substr(next, nc.find('\n', next) - next);
    EXPECT_NE(line.find(c.second), std::string::npos) << nc;
  }
}

// The seed's CYCLE98 thread (controllers.md) as a CL chain: pitch 2, diameter 30 from Z0 to
// Z-30, taper to 36 at Z-60, to 50 at Z-80, depth 0.92 in 5 constant cross-section cuts and one
// spring pass (NID 1), a 45 degree run-out of 10 (CHAMFR,-10: ROP 10). What differs from the
// seed's call is what the CL says otherwise: no run-in (APP 0), OPTION 1 infeeds along the flank
// (IANG 30 = TLANGL/2), one lead (PP 2, 2, 2), and the clear line (_VRT above the largest
// diameter). The run-out of the shallowest pass (depth 0.92 sqrt(1/5) = 0.411437) rises
// 10 (7, -20)/sqrt(449) + 10 (20, 7)/sqrt(449) = (X 12.742, Z -6.135) from its end at
// X 25 - 0.411437 - 10.562753 * 7/sqrt(449) = 21.099152 (slid back 0.92 tan 30 / (20/sqrt(449))
// + 10 along the last segment): the clear line is raised from P0's X 30 to 33.841 (diameter
// 67.682), 8.8412 outside X 25.
TEST(ChainOutput, Cycle98ForTheSeedsThread) {
  const Machine m = shipped_machine("sinumerik-840d");
  const ThreadPlan plan =
      plan_for(m, "THREAD/ON,MMPR,2,DEPTH,0.92,CUTS,5,FINCUT,1,OPTION,1,CHAMFR,-10,CHAIN", {30, 5},
               {{15, 0}, {15, -30}, {18, -60}, {25, -80}});
  const testing::Emitted e = emit_on(m, plan);
  ASSERT_TRUE(e.ok) << e.diags;
  EXPECT_EQ(e.nc,
            "N10 G1 X67.682 Z0 G95 F0.2\n"
            "N20 CYCLE98(0, 30, -30, 30, -60, 36, -80, 50, 0, 10, 0.92, 0, 30, 0, 5, 1, 2, 2, 2, "
            "3, 1, 8.8412)\n");
  // Two segments: the last point is written again as point 4.
  const ThreadPlan two = plan_for(m, "THREAD/ON,MMPR,2,DEPTH,0.92,CUTS,5,OPTION,3,CHAIN", {30, 5},
                                  {{15, 0}, {15, -30}, {18, -60}});
  const testing::Emitted e2 = emit_on(m, two);
  EXPECT_NE(e2.nc.find("CYCLE98(0, 30, -30, 30, -60, 36, -60, 36, 0, 0, 0.92, 0, 30, 0, 5, 0, 2, "
                       "2, 2, 1, 1, 12)\n"),
            std::string::npos)
      << e2.nc;
}

TEST(ChainOutput, Cycle98FallsBackWithItsReason) {
  const Machine m = shipped_machine("sinumerik-840d");
  struct Case {
    const char* on;
    std::vector<Vec2> gotos;
    const char* comment;
  };
  const Case cases[] = {
      {"THREAD/ON,MMPR,2,DEPTH,0.92,CUTS,5,OPTION,1,CHAIN",
       {{15, 0}, {15, -10}, {16, -20}, {17, -30}, {18, -40}},
       "; CYCLE98 not used: 4 segments: CYCLE98 cuts at most 3. G33 loop instead\n"},
      {"THREAD/ON,MMPR,2,DEPTH,0.92,CUTS,5,OPTION,0,CHAIN", kContour,
       "; CYCLE98 not used: OPTION 0, steps shrinking by a constant amount: CYCLE98 cuts constant "
       "infeed (VARI 1, 2) or constant cross-section (VARI 3, 4). G33 loop instead\n"},
      {"THREAD/ON,MMPR,2,DEPTH,0.92,CUTS,5,OPTION,2,CHAIN", kContour,
       "; CYCLE98 not used: OPTION 2 alternates the flanks: CYCLE98 infeeds along one flank "
       "(IANG). G33 loop instead\n"},
  };
  for (const Case& c : cases) {
    const testing::Emitted e = emit_on(m, plan_for(m, c.on, {30, 5}, c.gotos));
    EXPECT_TRUE(e.ok) << e.diags;
    EXPECT_NE(e.nc.find(c.comment), std::string::npos) << c.on << "\n" << e.nc;
  }
}

TEST(ChainOutput, StartAngleOnTheFirstSegmentOnly) {
  const std::string nc =
      emitted("sinumerik-840d", "THREAD/ON,MMPR,1.5,MULTRD,2,DEPTH,0.5,OPTION,0,CHAIN");
  EXPECT_NE(nc.find("G33 Z-10 K3 SF=180\nN"), std::string::npos) << nc;
  EXPECT_NE(nc.find(" X31 Z-20 K3\n"), std::string::npos) << nc;
  EXPECT_EQ(nc.find("Z-20 K3 SF="), std::string::npos) << nc;
}

}  // namespace
}  // namespace clpost

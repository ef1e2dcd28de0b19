// Chained threads (threading.md section 11) on every shipped machine: one synchronized block per
// segment with the lead on each and the start angle on the first only, and the cycles that cut
// one straight line falling back with their reason in a comment.
#include <gtest/gtest.h>

#include <string>

#include "emitters/emitter_test_util.h"

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
    const char* comment;  // the fallback comment
    const char* first;    // the first synchronized block
    const char* second;   // the second
  };
  const Case cases[] = {
      {"fanuc-0i-t",
       "(G76 NOT USED: A CHAINED THREAD: G76 CUTS ONE STRAIGHT THREAD LINE. EMULATION INSTEAD)",
       "G32 Z-10. F1.5", "X31. Z-20. F1.5"},
      {"haas-st",
       "(G76 NOT USED: A CHAINED THREAD: G76 CUTS ONE STRAIGHT THREAD LINE. EMULATION INSTEAD)",
       "G32 Z-10. F1.5", "X31. Z-20. F1.5"},
      {"linuxcnc-lathe",
       "(G76 not used: a chained thread: G76 cuts one straight thread line. emulation instead)",
       "G33 Z-10. K1.5", "X31. Z-20. K1.5"},
      {"heidenhain-pilot",
       "[G31 not used: a chained thread: clpost writes G31 for one straight thread line only. "
       "G33 loop instead]",
       "G33 Z-10. F1.5", "X31. Z-20. F1.5"},
      {"sinumerik-840d",
       "; CYCLE99 not used: a chained thread: CYCLE99 cuts one straight thread line. G33 loop "
       "instead",
       "G33 Z-10 K1.5", "X31 Z-20 K1.5"},
      {"nct-2000t", "", "G33 Z-10. F1.5", "X31. Z-20. F1.5"},
  };
  for (const Case& c : cases) {
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

TEST(ChainOutput, StartAngleOnTheFirstSegmentOnly) {
  const std::string nc =
      emitted("sinumerik-840d", "THREAD/ON,MMPR,1.5,MULTRD,2,DEPTH,0.5,OPTION,0,CHAIN");
  EXPECT_NE(nc.find("G33 Z-10 K3 SF=180\nN"), std::string::npos) << nc;
  EXPECT_NE(nc.find(" X31 Z-20 K3\n"), std::string::npos) << nc;
  EXPECT_EQ(nc.find("Z-20 K3 SF="), std::string::npos) << nc;
}

}  // namespace
}  // namespace clpost

// A thread posted whole: its lead as every output writes it, checked over the thread's turns
// (laws/written_value.h, lead_mismatch).
#include <gtest/gtest.h>

#include "interpreter/post.h"
#include "machine/machine_loader.h"
#include "machine/machine_test_util.h"

namespace clpost {
namespace {

// The lead as a synchronized move writes it, checked over the thread's length like a cycle's:
// 9 TPI in a metric file is a lead of 25.4 / 9 = 2.8222222 mm, written F2.8222 with Fanuc's four
// decimals (2.8222000), 0.0000222 short per turn. Over 703 mm (Z3 to Z-700) that is
// 703 / 2.8222222 = 249.09 turns and 0.0000222 x 249.09 = 0.005535 at the end, beyond the
// tolerance 0.005 (one least increment of Z on fanuc-0i-t): G76, G92 and the plain G32 moves all
// write F, so no output cuts it and the error says why once for the three.
TEST(ThreadLead, ALeadTheFormatRoundsAwayOverALongThreadIsAnError) {
  Machine m;
  std::string errors;
  ASSERT_TRUE(load_machine("fanuc-0i-t", {CLPOST_SOURCE_DIR}, {}, shipped_controls(), m, errors))
      << errors;
  const PostedText r = post_text(
      "UNITS/MM\nLOADTL/1\nSPINDL/300,RPM,CLW\nRAPID\nGOTO/30,0,5\n"
      "THREAD/ON,TPI,9,DEPTH,1.7,CUTS,4,OPTION,1\nGOTO/25,0,3\nGOTO/25,0,-700\nTHREAD/OFF\n"
      "FINI\n",
      m, "t.cl");
  EXPECT_EQ(r.diags.render_all(),
            "t.cl:6:1: error: machine 'fanuc-0i-t': no threading output can cut this thread: "
            "G76, G92, emulation not used: the lead 2.822222 is written F2.8222, 2.822200 "
            "(formats.F: 4 decimals): 0.005535 off over the thread's 249.1 turns, more than the "
            "tolerance 0.005\n"
            "  THREAD/ON,TPI,9,DEPTH,1.7,CUTS,4,OPTION,1\n"
            "  ^\n");
}

// The same thread over 300 mm (106.3 turns, 0.002362 off) is within the tolerance: it posts.
TEST(ThreadLead, ALeadWithinTheToleranceOverTheThreadPosts) {
  Machine m;
  std::string errors;
  ASSERT_TRUE(load_machine("fanuc-0i-t", {CLPOST_SOURCE_DIR}, {}, shipped_controls(), m, errors))
      << errors;
  const PostedText r = post_text(
      "UNITS/MM\nLOADTL/1\nSPINDL/300,RPM,CLW\nRAPID\nGOTO/30,0,5\n"
      "THREAD/ON,TPI,9,DEPTH,1.7,CUTS,4,OPTION,1\nGOTO/25,0,3\nGOTO/25,0,-297\nTHREAD/OFF\n"
      "FINI\n",
      m, "t.cl");
  EXPECT_EQ(r.diags.error_count(), 0u) << r.diags.render_all();
}

}  // namespace
}  // namespace clpost

// What the setup sheet shows for the output that wrote a hole (hole_output_text): the cycle as
// its reader calls it and the code the machine's template writes, read off the shipped
// machines' templates.
#include "emitters/hole_output.h"

#include <gtest/gtest.h>

#include "emitters/emitter_test_util.h"

namespace clpost {
namespace {

using testing::shipped_machine;

Hole hole(HoleKind kind) {
  Hole h;
  h.kind = kind;
  return h;
}

// The cycle's code is the template's, not the CL's word: Fanuc's lathe drills with G83 (no Q),
// its dwell is G83 P; LinuxCNC's G81 follows G98 and {feed_mode}; Sinumerik's is a CYCLE call;
// Heidenhain's DIN drilling cycle is G71 after a G0 to the R plane.
TEST(HoleOutputText, TheCycleAndItsCode) {
  const Machine fanuc = shipped_machine("fanuc-0i-t");
  EXPECT_EQ(hole_output_text(fanuc, hole(HoleKind::kDrill), "hole_drill"), "drilling (G83)");
  Hole dwell = hole(HoleKind::kDrill);
  dwell.dwell = 0.5;
  EXPECT_EQ(hole_output_text(fanuc, dwell, "hole_dwell"), "drilling with a dwell (G83)");
  EXPECT_EQ(hole_output_text(fanuc, hole(HoleKind::kDeep), "hole_peck"), "peck drilling (G83)");
  EXPECT_EQ(hole_output_text(fanuc, hole(HoleKind::kTap), "hole_tap_rigid"), "rigid tapping (G84)");
  EXPECT_EQ(
      hole_output_text(shipped_machine("linuxcnc-lathe"), hole(HoleKind::kDrill), "hole_drill"),
      "drilling (G81)");
  EXPECT_EQ(hole_output_text(shipped_machine("sinumerik-840d"), hole(HoleKind::kChipBreak),
                             "hole_chip_break"),
            "chip-breaking drilling (CYCLE83)");
  EXPECT_EQ(
      hole_output_text(shipped_machine("heidenhain-pilot"), hole(HoleKind::kDrill), "hole_drill"),
      "drilling (G71)");
  EXPECT_EQ(hole_output_text(shipped_machine("haas-st"), hole(HoleKind::kReam), "hole_bore"),
            "reaming (G85)");
}

// A live tool's radial holes: LinuxCNC's G81 after G19, Haas's left-hand G196 after a G0 to the
// R plane; LinuxCNC's G33.1 tap.
TEST(HoleOutputText, RadialAndLiveHoles) {
  Hole radial = hole(HoleKind::kDrill);
  radial.radial = true;
  radial.c = 90;
  EXPECT_EQ(hole_output_text(shipped_machine("linuxcnc-lathe-c"), radial, "hole_radial_drill"),
            "radial drilling (G81)");
  Hole left = hole(HoleKind::kTap);
  left.radial = true;
  left.c = 0;
  left.spindle = SpindleDir::kCcw;
  EXPECT_EQ(hole_output_text(shipped_machine("haas-st-20y"), left, "hole_radial_tap_left"),
            "radial left-hand tapping (G196)");
  Hole face = hole(HoleKind::kTap);
  face.c = 0;
  EXPECT_EQ(hole_output_text(shipped_machine("linuxcnc-lathe-c"), face, "hole_live_tap"),
            "tapping (G33.1)");
}

// Moves are the machine's rapid and feed codes; a name that is not the hole's output is shown
// as it is.
TEST(HoleOutputText, MovesAndOtherNames) {
  const Machine m = shipped_machine("fanuc-0i-t");
  EXPECT_EQ(hole_output_text(m, hole(HoleKind::kDeep), "moves"), "G0/G1 moves");
  EXPECT_EQ(hole_output_text(m, hole(HoleKind::kDeep), "hole_drill"), "hole_drill");
}

}  // namespace
}  // namespace clpost

// The oracle's reader of NCT lathe programs (Dialect::kNct) on small hand-written programs, each
// event's numbers computed by hand (mm, X a radius): what NCT says differently from Fanuc (G94/G95,
// G92 S, G33 with F or E and Q, a G33 block continuing the thread) and what it refuses.
#include <gtest/gtest.h>

#include <filesystem>
#include <fstream>
#include <iterator>

#include "fanuc_reader.h"

namespace oracle {
namespace {

std::string program(const std::string& body) {
  return "%\nO0001\nN10 G18 G21 G40 G90\nT0101\nG97 S800 M3\nG0 X20. Z2.\n" + body + "M30\n%\n";
}

ControlRun read(const std::string& body) {
  return fanuc_events(program(body), Dialect::kNct, false);
}

// G94 per minute, G95 per revolution; G92 S the CSS clamp; T0312 tool 3, offset 12.
TEST(OracleNctReader, FeedModesAndTheClamp) {
  const ControlRun r = read("T0312\nG92 S2500\nG96 S200 M4\nG1 X10. G95 F0.2\nZ-5. G94 F150.\n");
  ASSERT_EQ(r.error, "");
  ASSERT_EQ(r.events.size(), 3u);
  const Event& rev = r.events[1];
  EXPECT_DOUBLE_EQ(rev.x, 5);  // X10. is a diameter
  EXPECT_EQ(rev.state.feed_mode, FeedMode::kPerRev);
  EXPECT_DOUBLE_EQ(rev.state.feed, 0.2);
  EXPECT_EQ(rev.state.tool, 3);
  EXPECT_EQ(rev.state.offset, 12);
  EXPECT_TRUE(rev.state.spindle.css);
  EXPECT_EQ(rev.state.spindle.dir, SpindleDir::kCcw);
  EXPECT_DOUBLE_EQ(rev.state.spindle.speed, 200);
  EXPECT_DOUBLE_EQ(rev.state.spindle.limit, 2500);
  EXPECT_EQ(r.events[2].state.feed_mode, FeedMode::kPerMinute);
  EXPECT_DOUBLE_EQ(r.events[2].state.feed, 150);
  // "X325 means e.g. 325 mm": a coordinate without a point is in whole units.
  EXPECT_DOUBLE_EQ(read("X30\n").events[1].x, 15);
}

// G33 F: the lead in mm/rev, or inch/rev after G20 (F0.0625 = 1.5875 mm). G33 E: threads per
// inch, E8. a 25.4/8 = 3.175 mm lead in G21 and in G20 alike; E16 (no point, as the manual's E3)
// 1.5875 mm.
TEST(OracleNctReader, G33LeadByFOrByThreadsPerInch) {
  const ControlRun f = read("G33 Z-20. F1.5\nG0 X24.\nG20\nG33 Z-1. F0.0625\n");
  ASSERT_EQ(f.error, "");
  ASSERT_EQ(f.events.size(), 4u);
  EXPECT_EQ(f.events[1].motion, MotionKind::kThread);
  EXPECT_DOUBLE_EQ(f.events[1].z, -20);
  EXPECT_DOUBLE_EQ(f.events[1].lead, 1.5);
  EXPECT_NEAR(f.events[3].z, -25.4, 1e-9);
  EXPECT_NEAR(f.events[3].lead, 1.5875, 1e-12);
  const ControlRun e = read("G33 Z-20. E8.\nG0 X24.\nG20\nG33 Z-1. E8.\nG0 X1.\nG33 Z-2. E16\n");
  ASSERT_EQ(e.error, "");
  ASSERT_EQ(e.events.size(), 6u);
  EXPECT_NEAR(e.events[1].lead, 3.175, 1e-12);
  EXPECT_NEAR(e.events[3].lead, 3.175, 1e-12);
  EXPECT_NEAR(e.events[5].lead, 1.5875, 1e-12);
  EXPECT_EQ(read("G33 Z-20. F1.5 E8.\n").error, "G33 needs one of F (lead) and E (TPI)");
  EXPECT_EQ(read("G33 Z-20.\n").error, "G33 needs one of F (lead) and E (TPI)");
  EXPECT_EQ(read("G33 Z-20. E0.\n").error, "G33 E that is not a number of threads per inch");
  EXPECT_EQ(read("M5\nG33 Z-20. F1.5\n").error, "G33 with the spindle stopped");
}

// Q: the start angle in degrees (Q180. the second start of a double thread), in the block that
// synchronises only. A chamfer pull-out is the next G33 block: one continuous thread, no Q.
// From radius 10 at Z2: the thread to Z-20 at radius 9.13 (X18.26), then the 45° chamfer of 1.5
// to radius 10.63, Z-21.5 at the same lead.
TEST(OracleNctReader, StartAngleAndTheChamferContinuation) {
  const ControlRun r = read("X18.26\nG33 Z-20. F1.5 Q180.\nX21.26 Z-21.5 F1.5\nG0 X24.\n");
  ASSERT_EQ(r.error, "");
  ASSERT_EQ(r.events.size(), 5u);
  const Event& chamfer = r.events[3];
  EXPECT_EQ(chamfer.motion, MotionKind::kThread);
  EXPECT_NEAR(chamfer.x, 10.63, 1e-12);
  EXPECT_DOUBLE_EQ(chamfer.z, -21.5);
  EXPECT_DOUBLE_EQ(chamfer.lead, 1.5);
  EXPECT_EQ(r.events[4].motion, MotionKind::kRapid);
  // A Q in the continuing block: only the first block synchronises.
  const ControlRun q = read("G33 Z-20. F1.5\nX23. Z-21.5 F1.5 Q90.\n");
  EXPECT_EQ(q.error, "Q in a G33 block that continues a thread");
  EXPECT_EQ(q.error_line, 8);
  // After a G0 the next G33 synchronises again and may shift its start.
  EXPECT_EQ(read("G33 Z-20. F1.5\nG0 X24.\nZ2.\nX20.\nG33 Z-20. F1.5 Q180\n").error, "");
  EXPECT_EQ(read("G33 Z-20. F1.5 Q360.\n").error, "G33 Q outside 0-360 degrees");
  EXPECT_EQ(read("G1 X10. G95 F0.1 Q90.\n").error, "address Q is not read");
}

// G33's F is the lead; whether it is the feed afterwards is not documented: a feed move after it
// gives its own F. E leaves F alone.
TEST(OracleNctReader, AFeedAfterG33GivesItsOwnF) {
  const std::string feed = "G1 X30. G95 F0.2\nG0 X20.\n";
  EXPECT_EQ(read(feed + "G33 Z-20. F1.5\nG0 X24.\nG1 X30.\n").error,
            "a feed move after G33's F without its own F (not documented for NCT)");
  const ControlRun own = read(feed + "G33 Z-20. F1.5\nG0 X24.\nG1 X30. F0.1\n");
  ASSERT_EQ(own.error, "");
  EXPECT_DOUBLE_EQ(own.events.back().state.feed, 0.1);
  const ControlRun e = read(feed + "G33 Z-20. E16.\nG0 X24.\nG1 X30.\n");
  ASSERT_EQ(e.error, "");
  EXPECT_DOUBLE_EQ(e.events.back().state.feed, 0.2);
}

// Fanuc's and Haas's codes that NCT gives another meaning or none, and what its sources do not
// name, are refused.
TEST(OracleNctReader, OtherControlsCodesAreRefused) {
  EXPECT_EQ(read("G50 S2000\n").error, "G50 is not read by the oracle");
  EXPECT_EQ(read("G1 X10. G99 F0.1\n").error, "G99 is not read by the oracle");
  EXPECT_EQ(read("G32 Z-5. F1.\n").error, "G32 is not read by the oracle");
  EXPECT_EQ(read("G28 U0.\n").error, "G28 is not read by the oracle");
  EXPECT_EQ(read("G0 U2.\n").error, "address U is not read");
  EXPECT_EQ(read("G4 P1500\n").error, "address P is not read");
  EXPECT_EQ(read("G92 X10. Z5.\n").error,
            "G92 without S (a coordinate system setting is not read by the oracle)");
  EXPECT_EQ(read("G1 X10.\n").error, "a feed move before F, G94 or G95");
  // The dwell as the ISO post writes it (an assumption): G4 X<seconds>.
  EXPECT_DOUBLE_EQ(read("G4 X1.5\n").events[1].seconds, 1.5);
  // The Fanuc reader keeps G50 S and G98/G99.
  EXPECT_EQ(fanuc_events("%\nO0001\nG18 G21 G40\nT0101\nG50 S2000\nG96 S100 M3\nG0 X20. Z2.\n"
                         "G1 X10. G99 F0.1\nM30\n%\n",
                         Dialect::kFanuc, false)
                .error,
            "");
}

// Every thread program clpost writes for nct-2000t (samples/golden/nct-2000t/thread*.nc: multi-
// start threads with Q, chamfer pull-outs as a second G33 block, E in inch, tapers and faces,
// chains) is one the reader takes to its end.
TEST(OracleNctReader, ReadsEveryThreadGolden) {
  int files = 0;
  const std::filesystem::path dir =
      std::filesystem::path(CLPOST_SOURCE_DIR) / "samples/golden/nct-2000t";
  for (const auto& entry : std::filesystem::directory_iterator(dir)) {
    const std::string name = entry.path().filename().string();
    if (name.rfind("thread", 0) != 0) continue;
    std::ifstream in(entry.path());
    const std::string text((std::istreambuf_iterator<char>(in)), std::istreambuf_iterator<char>());
    const ControlRun r = fanuc_events(text, Dialect::kNct, false);
    EXPECT_EQ(r.error, "") << name << " line " << r.error_line;
    size_t g33 = 0, threads = 0;
    for (size_t at = text.find("G33"); at != std::string::npos; at = text.find("G33", at + 1))
      ++g33;
    for (const Event& e : r.events) threads += e.motion == MotionKind::kThread ? 1 : 0;
    // Every pass a G33 block; a chamfer pull-out continues it in a block without G33.
    EXPECT_GE(threads, g33) << name;
    if (name == "threads-pullouts.nc" || name == "thread-m20.nc") {
      EXPECT_GT(threads, g33) << name;
    }
    ++files;
  }
  EXPECT_EQ(files, 11);
}

}  // namespace
}  // namespace oracle

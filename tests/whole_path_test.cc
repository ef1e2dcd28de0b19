// Verify of the whole program (verify/path_verify.h): besides threads and holes, every CL motion's
// end point in order, each arc's sense and centre, and the tool, feed and spindle each motion is
// made with, read back through the machine's codes and templates. Each case edits one word of a
// reviewed golden and expects the exact first error: the NC line, the CL line and both values.
#include <gtest/gtest.h>

#include <algorithm>
#include <cstdio>
#include <sstream>

#include "test_util.h"

namespace clpost::test {
namespace {

struct Edit {
  const char* machine;
  const char* golden;  // under samples/golden/<machine>/
  const char* cl;      // under samples/
  const char* from;    // the text edited (its first occurrence)
  const char* to;
  int nc_line;          // where the first error is
  const char* message;  // the first error's message
  int errors;           // how many errors in all
};

const Edit kEdits[] = {
    // End points: a cut to the wrong place; a rapid written as a feed.
    {"generic-lathe", "part-turned.nc", "part-turned.apt", "N110 G1 Z-42.\n", "N110 G1 Z-41.\n", 21,
     "motion at samples/part-turned.apt:19: X24.0000 Z-42.0000 is not reached by the program in "
     "order",
     2},
    {"generic-lathe", "part-turned.nc", "part-turned.apt", "N130 G0 Z2.\n", "N130 G1 Z2.\n", 23,
     "motion at samples/part-turned.apt:22: X32.0000 Z2.0000 is reached by a feed move, the CL "
     "rapids there",
     1},
    // Spindle: SPINDL/800,RPM,CLW (CL line 7) is in force from the first motion (line 11); it is
    // compared at the first feed move, GOTO/0,0,0 at CL line 14, NC line 10.
    {"fanuc-0i-t", "part-turned.nc", "part-turned.apt", "N40 G97 S800 M3", "N40 G97 S900 M3", 18,
     "spindle at samples/part-turned.apt:14: CL CW at 800 rpm (set at CL line 7), program CW at "
     "900 rpm",
     1},
    {"fanuc-0i-t", "part-turned.nc", "part-turned.apt", "N40 G97 S800 M3", "N40 G97 S800 M4", 18,
     "spindle at samples/part-turned.apt:14: CL CW at 800 rpm (set at CL line 7), program CCW at "
     "800 rpm",
     1},
    {"haas-st", "part-turned.nc", "part-turned.apt", "G97 S700 M3", "M5", 88,
     "spindle at samples/part-turned.apt:65: CL CW at 700 rpm (set at CL line 61), program stopped",
     1},
    // Feed: FEDRAT/0.2,MMPR as F0.2 with G99 (per revolution on a Fanuc).
    {"fanuc-0i-t", "part-turned.nc", "part-turned.apt", "G99 F0.2", "G99 F0.25", 18,
     "feed at samples/part-turned.apt:14: CL 0.2 mm/rev (set at CL line 9), program 0.25 mm/rev",
     1},
    {"fanuc-0i-t", "part-turned.nc", "part-turned.apt", "G99 F0.2", "G98 F0.2", 18,
     "feed at samples/part-turned.apt:14: CL 0.2 mm/rev (set at CL line 9), program 0.2 mm/min", 1},
    // Tool: LOADTL/6,ADJUST,6 as T0606; T0605 is tool 6 with offset 5, reported once although
    // the CL's state changes at the next motion.
    {"fanuc-0i-t", "part-turned.nc", "part-turned.apt", "N420 T0606", "N420 T0605", 54,
     "tool at samples/part-turned.apt:64: CL tool 6 offset 6 (set at CL line 60), program tool 6 "
     "offset 5",
     1},
    {"sinumerik-840d", "bushing-creo.mpf", "bushing-creo.ncl", "T2 D2", "T2 D1", 10,
     "tool at samples/bushing-creo.ncl:15: CL tool 2 offset 2 (set at CL line 7), program tool 2 "
     "offset 1",
     1},
    // LinuxCNC: T2 without M6 selects the tool but does not change it.
    {"linuxcnc-lathe", "bushing-creo.ngc", "bushing-creo.ncl", "T2 M6 G43 H2", "T2 G43 H2", 10,
     "tool at samples/bushing-creo.ncl:15: CL tool 2 offset 2 (set at CL line 7), program no tool",
     1},
    // LinuxCNC: G43 H{offset} selects the offset (LOADTL/…,ADJUST).
    {"linuxcnc-lathe", "bushing-creo.ngc", "bushing-creo.ncl", "T2 M6 G43 H2", "T2 M6 G43 H12", 10,
     "tool at samples/bushing-creo.ncl:15: CL tool 2 offset 2 (set at CL line 7), program tool 2 "
     "offset 12",
     1},
    // Constant surface speed: SPINDL/SFM,400,CLW,MAXRPM,2500 in an inch file.
    {"fanuc-0i-t", "bushing-creo.nc", "bushing-creo.ncl", "G50 S2500", "G50 S2000", 13,
     "spindle at samples/bushing-creo.ncl:17: CL CW at 400 ft/min CSS, limit 2500 rpm (set at CL "
     "line 12), program CW at 400 ft/min CSS, limit 2000 rpm",
     1},
    {"fanuc-0i-t", "bushing-creo.nc", "bushing-creo.ncl", "G96 S400", "G97 S400", 13,
     "spindle at samples/bushing-creo.ncl:17: CL CW at 400 ft/min CSS, limit 2500 rpm (set at CL "
     "line 12), program CW at 400 rpm",
     1},
    {"sinumerik-840d", "bushing-creo.mpf", "bushing-creo.ncl", "LIMS=2500", "LIMS=3000", 11,
     "spindle at samples/bushing-creo.ncl:17: CL CW at 400 ft/min CSS, limit 2500 rpm (set at CL "
     "line 12), program CW at 400 ft/min CSS, limit 3000 rpm",
     1},
    {"linuxcnc-lathe", "bushing-creo.ngc", "bushing-creo.ncl", "D2500 S400", "D2500 S410", 11,
     "spindle at samples/bushing-creo.ncl:17: CL CW at 400 ft/min CSS, limit 2500 rpm (set at CL "
     "line 12), program CW at 410 ft/min CSS, limit 2500 rpm",
     1},
    // (bushing-creo is an inch file, which a HEIDENHAIN machine in mm refuses.)
    {"heidenhain-pilot", "pin-apt.nc", "pin-apt.apt", "G26 S2500", "G26 S2400", 14,
     "spindle at samples/pin-apt.apt:12: CL CW at 180 m/min CSS, limit 2500 rpm (set at CL line "
     "7), program CW at 180 m/min CSS, limit 2400 rpm",
     1},
    // Arcs: the CL's CIRCLE (centre X0.4 radius, Z-0.05: I0.05 K0 from X0.35 Z-0.05) ends at
    // X0.8 Z0 turning counter-clockwise.
    {"fanuc-0i-t", "bushing-creo.nc", "bushing-creo.ncl", "G3 X0.8 Z0. I0.05 K0.",
     "G2 X0.8 Z0. I0.05 K0.", 16,
     "motion at samples/bushing-creo.ncl:22: the CL cuts a counter-clockwise arc (G3) to X0.8000 "
     "Z0.0000, the program a clockwise arc (G2)",
     1},
    {"fanuc-0i-t", "bushing-creo.nc", "bushing-creo.ncl", "G3 X0.8 Z0. I0.05 K0.",
     "G3 X0.8 Z0. I0.05 K0.01", 16,
     "arc at samples/bushing-creo.ncl:22: the CL turns around X0.8000 Z-0.0500, the program around "
     "X0.8000 Z-0.0400",
     1},
    {"fanuc-0i-t", "bushing-creo.nc", "bushing-creo.ncl", "G3 X0.8 Z0. I0.05 K0.", "G1 X0.8 Z0.",
     16,
     "motion at samples/bushing-creo.ncl:22: the CL cuts a counter-clockwise arc (G3) to X0.8000 "
     "Z0.0000, the program a straight line (G1)",
     1},
};

class WholePath : public ::testing::TestWithParam<Edit> {};

TEST_P(WholePath, AnEditedWordFailsAtItsLine) {
  const Edit& e = GetParam();
  const std::string golden =
      source_dir() + "/samples/golden/" + e.machine + "/" + std::string(e.golden);
  std::string text = read_file(golden);
  const size_t at = text.find(e.from);
  ASSERT_NE(at, std::string::npos) << e.from << " not in " << golden;
  text.replace(at, std::string(e.from).size(), e.to);
  const std::string path = temp_dir() + "/" + e.golden;
  write_file(path, text);
  const RunResult r = run("cd " + quote(source_dir()) + " && " + quote(clpost_bin()) +
                          " verify -m " + e.machine + " " + quote(path) + " --cl samples/" + e.cl);
  EXPECT_EQ(r.exit_code, 1) << r.out << r.err;
  EXPECT_EQ(r.err.substr(0, r.err.find('\n')),
            path + ":" + std::to_string(e.nc_line) + ":1: error: " + e.message);
  const std::string failed =
      "FAILED: " + std::to_string(e.errors) + " difference" + (e.errors == 1 ? "" : "s") + " over ";
  EXPECT_NE(r.out.find(failed), std::string::npos) << r.out;
}

INSTANTIATE_TEST_SUITE_P(Edits, WholePath, ::testing::ValuesIn(kEdits));

// The goldens as written pass, and the report says what was compared: the part's 17 GOTOs, its
// 3 holes' exits and its thread's (21 end points), 6 states (a tool change each); the bushing's 6
// motions, its one arc, and 2 states (its first motion, a rapid, comes before its FEDRAT).
TEST(WholePathGoldens, EveryGoldenCutsTheCl) {
  struct Case {
    const char* machine;
    const char* tolerance;
    bool offset;  // the tool_change template writes the offset
  };
  // What each machine's report says (a shipped machine needs its row: checked below).
  const std::vector<Case> cases = {
      {"generic-lathe", "0.001", true},     {"fanuc-0i-t", "0.005", true},
      {"haas-st", "0.005", true},           {"sinumerik-840d", "0.001", true},
      {"heidenhain-pilot", "0.001", false}, {"linuxcnc-lathe", "1e-05", true},
      {"linuxcnc-lathe-c", "1e-05", true},  {"fanuc-0i-tf-live", "0.005", true},
      {"haas-st-20y", "0.005", true},       {"nct-2000t", "0.001", true}};
  const std::vector<std::string> machines = shipped_machine_names();
  ASSERT_FALSE(machines.empty());
  for (const Case& c : cases)
    EXPECT_NE(std::find(machines.begin(), machines.end(), c.machine), machines.end())
        << "machine " << c.machine << " is not shipped: remove its row";
  const std::string not_compared =
      "; not compared: the offset (template tool_change has no {offset})";
  for (const std::string& name : machines) {
    const auto row =
        std::find_if(cases.begin(), cases.end(), [&](const Case& c) { return c.machine == name; });
    if (row == cases.end()) {
      ADD_FAILURE() << "machine " << name
                    << " has no expected tolerance and offset in EveryGoldenCutsTheCl: add one";
      continue;
    }
    const Case& c = *row;
    const Machine m = shipped_machine(name);
    const std::string tail = c.offset ? "\n" : not_compared + "\n";
    const auto check = [&](const std::string& sample, const std::string& expected) {
      const RunResult r =
          run("cd " + quote(source_dir()) + " && " + quote(clpost_bin()) + " verify -m " +
              c.machine + " " + golden_path(m, sample) + " --cl samples/" + sample);
      EXPECT_EQ(r.exit_code, 0) << c.machine << " " << sample << "\n" << r.out << r.err;
      EXPECT_NE(r.out.find(expected), std::string::npos) << c.machine << "\n" << r.out;
    };
    check("part-turned.apt",
          std::string("motions: 21 CL end points, every one reached in order, within ") +
              c.tolerance +
              "; 0 arcs by their centre; feed, spindle and tool as the CL (6 states)" + tail);
    // An inch file: HEIDENHAIN DIN reads a program in its one unit, the machine's mm (the post
    // refuses it: ClMeaning.HeidenhainReadsAProgramInOneUnit).
    if (m.control && m.control->one_unit_per_program && m.default_units == "mm") continue;
    check("bushing-creo.ncl",
          std::string("motions: 6 CL end points, every one reached in order, within ") +
              c.tolerance + "; 1 arc by its centre; feed, spindle and tool as the CL (2 states)" +
              tail);
  }
}

// A machine whose tool change is a comment: the tool cannot be read back, and the report says
// so instead of passing it silently.
TEST(WholePathGoldens, AToolChangeWithoutAToolWordIsNotCompared) {
  const std::string dir = temp_dir();
  write_file(dir + "/comment-tool.yaml", read_file(source_dir() + "/machines/fanuc-0i-t.yaml") +
                                             "templates: {tool_change: [\"(TOOL CHANGE)\"]}\n");
  const std::string machine = quote(dir + "/comment-tool.yaml");
  const RunResult r =
      run("cd " + quote(source_dir()) + " && " + quote(clpost_bin()) + " -m " + machine +
          " samples/part-turned.apt --verify -o " + quote(dir + "/part.nc"));
  EXPECT_EQ(r.exit_code, 0) << r.out << r.err;
  const RunResult v =
      run("cd " + quote(source_dir()) + " && " + quote(clpost_bin()) + " verify -m " + machine +
          " " + quote(dir + "/part.nc") + " --cl samples/part-turned.apt");
  EXPECT_EQ(v.exit_code, 0) << v.out << v.err;
  EXPECT_NE(v.out.find("feed, spindle and tool as the CL (6 states); not compared: the tool "
                       "(template tool_change has no {tool} word to read)\n"),
            std::string::npos)
      << v.out;
}

// Posts `cl` with --verify on every shipped machine: each posts and verifies (exit 0).
void posts_and_verifies_everywhere(const std::string& cl) {
  const std::string dir = temp_dir();
  write_file(dir + "/t.cl", cl);
  for (const std::string& m : shipped_machine_names()) {
    const RunResult r = run(quote(clpost_bin()) + " -m " + m + " " + quote(dir + "/t.cl") +
                            " --verify -o " + quote(dir + "/t.nc"));
    EXPECT_EQ(r.exit_code, 0) << m << "\n" << r.err;
  }
}

// A CL motion to where the tool already is writes no block (nothing moves; it used to write a
// motionless "G0" alone), and verify takes it as reached there, whatever its kind. Found by the
// round-trip fuzzer (a RAPID, GOTO to the point just reached).
TEST(WholePathGoldens, AMotionToWhereTheToolIsNeedsNoBlock) {
  const std::string dir = temp_dir();
  write_file(dir + "/same.cl",
             "UNITS/MM\nLOADTL/1\nSPINDL/800,RPM,CLW\nFEDRAT/0.2,MMPR\nRAPID\nGOTO/16,0,2\n"
             "GOTO/12,0,-10\nRAPID\nGOTO/12,0,-10\nRAPID\nGOTO/16,0,2\nFINI\n");
  const RunResult r = run(quote(clpost_bin()) + " -m haas-st " + quote(dir + "/same.cl") +
                          " --verify -o " + quote(dir + "/same.nc"));
  EXPECT_EQ(r.exit_code, 0) << r.err;
  const std::string nc = read_file(dir + "/same.nc");
  EXPECT_NE(nc.find("G1 X24. Z-10. G99 F0.2\nG0 X32. Z2.\n"), std::string::npos) << nc;
  EXPECT_NE(r.err.find("motions: 4 CL end points, every one reached in order"), std::string::npos)
      << r.err;
}

// The hole marker the post writes ("hole at CL line N: ...") in a comment of the user's is not a
// hole: not in the middle of a comment, and not at its start when no feed into a hole follows.
// Found by the round-trip fuzzer (a tool name holding the words).
TEST(WholePathGoldens, AUserCommentWithTheHoleMarkerIsNoHole) {
  const std::string dir = temp_dir();
  write_file(dir + "/note.cl",
             "UNITS/MM\nPPRINT TOOL NOTE HOLE AT CL LINE 7\nPPRINT hole at CL line 9: none\n"
             "LOADTL/1\nSPINDL/800,RPM,CLW\nFEDRAT/0.2,MMPR\nRAPID\nGOTO/16,0,2\n"
             "GOTO/12,0,-10\nFINI\n");
  const RunResult r = run(quote(clpost_bin()) + " -m fanuc-0i-t " + quote(dir + "/note.cl") +
                          " --verify -o " + quote(dir + "/note.nc"));
  EXPECT_EQ(r.exit_code, 0) << r.err;
  EXPECT_NE(read_file(dir + "/note.nc").find("(HOLE AT CL LINE 9: NONE)"), std::string::npos);
  EXPECT_EQ(r.err.find("holes on the centre line"), std::string::npos) << r.err;
}

// Two holes from the same start point and then a GOTO to the first hole's R plane: the GOTO after
// each tool change to where the tool already is (Z10) moves nothing, and the last GOTO (Z2) must
// be matched with the program's own block, not with the first hole's rapid to its R plane at Z2
// (under the first tool). Found by the round-trip fuzzer; on every machine.
TEST(WholePathGoldens, AGotoToAnEarlierHolesRPlaneIsItsOwnBlock) {
  const std::string dir = temp_dir();
  write_file(dir + "/h.cl",
             "UNITS/MM\nLOADTL/2,ADJUST,2\nSPINDL/1500,RPM,CLW\nRAPID\nGOTO/0,0,10\n"
             "CYCLE/DRILL,DEPTH,3,MMPR,0.05,CLEAR,2,DWELL,0.5\nGOTO/0,0,0\nCYCLE/OFF\n"
             "LOADTL/4,ADJUST,4\nSPINDL/300,RPM,CLW\nRAPID\nGOTO/0,0,10\n"
             "CYCLE/TAP,DEPTH,16,PITCH,1.5,MMPM,450,CLEAR,5\nGOTO/0,0,0\nCYCLE/OFF\nRAPID\n"
             "GOTO/0,0,2\nRAPID\nGOTO/20,0,2\nFINI\n");
  for (const std::string& m : shipped_machine_names()) {
    const RunResult r = run(quote(clpost_bin()) + " -m " + m + " " + quote(dir + "/h.cl") +
                            " --verify -o " + quote(dir + "/h.nc"));
    EXPECT_EQ(r.exit_code, 0) << m << "\n" << r.err;
    EXPECT_NE(r.err.find("motions: 6 CL end points, every one reached in order"), std::string::npos)
        << m << "\n"
        << r.err;
  }
}

// A tap with no clearance plane written as moves (haas-st's G84 has no dwell) feeds back out to
// where it started: the hole leaves the tool there by a feed, which verify accepts for the hole's
// exit (a cycle's exit is a rapid). Found by the round-trip fuzzer.
TEST(WholePathGoldens, ATapWrittenAsMovesLeavesByAFeed) {
  const std::string dir = temp_dir();
  write_file(dir + "/t.cl",
             "UNITS/MM\nLOADTL/4,ADJUST,4\nSPINDL/300,RPM,CLW\nRAPID\nGOTO/0,0,2\n"
             "CYCLE/TAP,DEPTH,16,PITCH,1.5,DWELL,0.5\nGOTO/0,0,0\nCYCLE/OFF\nRAPID\n"
             "GOTO/20,0,2\nFINI\n");
  const RunResult r = run(quote(clpost_bin()) + " -m haas-st " + quote(dir + "/t.cl") +
                          " --verify -o " + quote(dir + "/t.nc"));
  EXPECT_EQ(r.exit_code, 0) << r.err;
  EXPECT_NE(read_file(dir + "/t.nc").find("G1 Z-16. G99 F1.5\nG4 P0.5\nG97 S300 M4\nZ2.\n"),
            std::string::npos);
}

// A drill whose R plane is where it starts (Z2), then a tap from there: the tap's exit at Z2 is
// matched after the tap reaches its bottom, not with the drill's rapid to its R plane at Z2
// (under the first tool). Found by the round-trip fuzzer; on every machine.
TEST(WholePathGoldens, AHoleExitIsMatchedAfterItsBottom) {
  posts_and_verifies_everywhere(
      "UNITS/MM\nLOADTL/1,ADJUST,1\nSPINDL/800,RPM,CLW\nRAPID\nGOTO/16,0,2\n"
      "CYCLE/DRILL,DEPTH,3,MMPR,0.05,CLEAR,2,DWELL,0.5\nGOTO/0,0,0\nCYCLE/OFF\n"
      "LOADTL/4,ADJUST,4\nSPINDL/300,RPM,CLW\n"
      "CYCLE/TAP,DEPTH,16,PITCH,1.5,MMPM,450,CLEAR,5\nGOTO/0,0,0\nCYCLE/OFF\nRAPID\n"
      "GOTO/20,0,2\nFINI\n");
}

// Two undercuts and two threads from the same point (X30 Z5), then a tool change and a GOTO
// there: where each cycle leaves the tool is a point of the path, so the GOTO after the tool
// change is matched with its own block, not with the first undercut's return to X30 Z5 (under
// the first tool). Found by the round-trip fuzzer; on every machine.
TEST(WholePathGoldens, WhereACycleLeavesTheToolIsAPointOfThePath) {
  const std::string dir = temp_dir();
  write_file(
      dir + "/u.cl",
      "UNITS/MM\nLOADTL/1\nSPINDL/400,RPM,CLW\nFEDRAT/0.15,MMPR\nRAPID\nGOTO/15,0,5\nCYCLE/"
      "UNDCUT,DIAM,24,AT,-36,FORM,A\nRAPID\nGOTO/15,0,5\nTHREAD/"
      "ON,MMPR,3,DEPTH,1.84,CUTS,6,FINCUT,2,0.05,OPTION,1\nGOTO/12,0,2\nGOTO/12,0,-30\nTHREAD/"
      "OFF\nCYCLE/UNDCUT,DIAM,24,AT,-36,FORM,A\nRAPID\nGOTO/15,0,5\nTHREAD/"
      "ON,MMPR,3,DEPTH,1.84,CUTS,6,FINCUT,2,0.05,OPTION,1\nGOTO/12,0,2\nGOTO/12,0,-30\nTHREAD/"
      "OFF\nLOADTL/3\nSPINDL/400,RPM,CLW\nRAPID\nGOTO/15,0,5\nRAPID\nGOTO/30,0,5\nFINI\n");
  for (const std::string& m : shipped_machine_names()) {
    const RunResult r = run(quote(clpost_bin()) + " -m " + m + " " + quote(dir + "/u.cl") +
                            " --verify -o " + quote(dir + "/u.nc"));
    EXPECT_EQ(r.exit_code, 0) << m << "\n" << r.err;
  }
}

// Three threads from the same start point, the third after a tool change: a thread cycle returns
// to its start after every pass, so where a thread leaves the tool is looked for after its
// synchronized cuts, and the third thread's exit is not matched inside the second's cycle (under
// the first tool). Found by the round-trip fuzzer; on every machine.
TEST(WholePathGoldens, AThreadsExitComesAfterItsCuts) {
  const std::string dir = temp_dir();
  write_file(
      dir + "/t.cl",
      "UNITS/MM\nLOADTL/5\nSPINDL/800,RPM,CLW\nFEDRAT/0.2,MMPR\nRAPID\nGOTO/10,0,5\nTHREAD/"
      "ON,MMPR,1.5,DEPTH,0.92,CUTS,6,OPTION,1\nGOTO/8,0,2\nGOTO/8,0,-20\nTHREAD/OFF\nRAPID\nGOTO/"
      "10,0,5\nTHREAD/ON,MMPR,1.5,DEPTH,0.92,CUTS,6,OPTION,1\nGOTO/8,0,2\nGOTO/8,0,-20\nTHREAD/"
      "OFF\nLOADTL/1\nSPINDL/800,RPM,CLW\nTHREAD/ON,MMPR,1.5,DEPTH,0.92,CUTS,6,OPTION,1\nGOTO/"
      "8,0,2\nGOTO/8,0,-20\nTHREAD/OFF\nFINI\n");
  for (const std::string& m : shipped_machine_names()) {
    const RunResult r = run(quote(clpost_bin()) + " -m " + m + " " + quote(dir + "/t.cl") +
                            " --verify -o " + quote(dir + "/t.nc"));
    EXPECT_EQ(r.exit_code, 0) << m << "\n" << r.err;
  }
}

// LinuxCNC's own interpreter agrees with what verify reads back: every feed move of the goldens
// outside spindle-synchronized motion (threads, the rigid tap) is made with the tool, spindle and
// feed the CL says, by hand from the CL files:
// - part-turned.apt: T1 SPINDL/800 FEDRAT/0.2,MMPR (face, turn); T2 1500 rpm, the centre drill's
//   MMPR 0.05; T3 900 rpm, the peck drill's 0.12; T6 700 rpm, FEDRAT/0.05,MMPR (part off);
// - bushing-creo.ncl: T2 SFM 400 with MAXRPM 2500, FEDRAT/0.006,IPR.
std::vector<std::string> rs274_feed_states(const std::string& ngc) {
  const RunResult r = run_rs274(source_dir() + "/samples/golden/linuxcnc-lathe", ngc);
  EXPECT_EQ(r.exit_code, 0) << r.err;
  std::vector<std::string> out;
  std::istringstream in(r.out);
  std::string line, tool = "?", mode = "rpm", speed = "?", dir = "stopped", feed_mode = "?",
                    feed = "?";
  bool synced = false;
  const auto arg = [](const std::string& l, const char* word) {
    const size_t at = l.find(word);
    if (at == std::string::npos) return std::string();
    const size_t open = l.find('(', at) + 1;
    return l.substr(open, l.find(')', open) - open);
  };
  while (std::getline(in, line)) {
    if (std::string a = arg(line, "CHANGE_TOOL("); !a.empty()) tool = "T" + a;
    if (std::string a = arg(line, "SET_SPINDLE_MODE("); !a.empty())
      mode = a.substr(a.find(' ') + 1) == "0.0000" ? "rpm" : "css max " + a.substr(a.find(' ') + 1);
    if (std::string a = arg(line, "SET_SPINDLE_SPEED("); !a.empty()) speed = a.substr(3);
    if (line.find("START_SPINDLE_CLOCKWISE") != std::string::npos) dir = "CW";
    if (line.find("START_SPINDLE_COUNTERCLOCKWISE") != std::string::npos) dir = "CCW";
    if (line.find("STOP_SPINDLE_TURNING") != std::string::npos) dir = "stopped";
    if (std::string a = arg(line, "SET_FEED_MODE("); !a.empty())
      feed_mode = a == "0, 1" ? "/rev" : "/min";
    if (std::string a = arg(line, "SET_FEED_RATE("); !a.empty()) feed = a;
    if (line.find("START_SPEED_FEED_SYNC") != std::string::npos) synced = true;
    if (line.find("STOP_SPEED_FEED_SYNCH") != std::string::npos) synced = false;
    const bool feeds = line.find("STRAIGHT_FEED(") != std::string::npos ||
                       line.find("ARC_FEED(") != std::string::npos;
    if (!feeds || synced) continue;
    std::string s = tool + " " + dir + " " + speed + " " + mode + " F" + feed + feed_mode;
    if (out.empty() || out.back() != s) out.push_back(std::move(s));
  }
  return out;
}

TEST(WholePathGoldens, Rs274FeedsWithTheClToolSpindleAndFeed) {
  if (!rs274_available()) GTEST_SKIP() << "rs274 not installed (apt-get install linuxcnc-uspace)";
  EXPECT_EQ(rs274_feed_states("part-turned.ngc"),
            (std::vector<std::string>{
                "T1 CW 800.0000 rpm F0.2000/rev", "T2 CW 1500.0000 rpm F0.0500/rev",
                "T3 CW 900.0000 rpm F0.1200/rev", "T6 CW 700.0000 rpm F0.0500/rev"}));
  EXPECT_EQ(rs274_feed_states("bushing-creo.ngc"),
            (std::vector<std::string>{"T2 CW 400.0000 css max 2500.0000 F0.0060/rev"}));
}

}  // namespace
}  // namespace clpost::test

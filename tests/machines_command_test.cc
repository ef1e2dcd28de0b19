// `clpost machines show`, `clpost machines diff` and `clpost schema` on the shipped machines
// (issue 19), exact lines.
#include <gtest/gtest.h>

#include <sstream>

#include "test_util.h"

namespace clpost::test {
namespace {

std::vector<std::string> lines_of(const std::string& text) {
  std::vector<std::string> out;
  std::istringstream in(text);
  for (std::string l; std::getline(in, l);) out.push_back(l);
  return out;
}

bool has_line(const std::vector<std::string>& lines, const std::string& line) {
  return std::find(lines.begin(), lines.end(), line) != lines.end();
}

TEST(MachinesShow, EveryKeyWithWhereItCameFrom) {
  const std::string dir = source_dir();
  RunResult r = run(quote(clpost_bin()) +
                    " machines show linuxcnc-lathe --origin --set threading.fallback=error");
  ASSERT_EQ(r.exit_code, 0) << r.err;
  const std::vector<std::string> lines = lines_of(r.out);
  const std::string machine = dir + "/machines/linuxcnc-lathe.yaml";
  const std::string post = dir + "/posts/linuxcnc.yaml";
  EXPECT_EQ(lines.at(0), "# machine linuxcnc-lathe: " + machine);
  EXPECT_EQ(lines.at(1), "extends: linuxcnc                               # " + machine + ":3");
  // From the machine file, from its post, from --set, and the default.
  for (const std::string& l :
       {"output.extension: .ngc                          # " + machine + ":7",
        "output.line_ending: lf                          # " + post + ":9",
        "threading.cycle: linuxcnc_g76                   # " + post + ":84",
        std::string("threading.fallback: error                       # --set"),
        std::string("threading.loop: g33                             # default"),
        std::string("millturn.face_holes: false                      # default"),
        "limits.max_rpm: 3000                            # " + machine + ":8",
        "formats.K.decimals: 8                           # " + post + ":19",
        std::string("formats.K.scale: 1                              # default"),
        "codes.thread: G33                               # " + post + ":37",
        "templates.linuxcnc_g76: [\"G76 P{p} Z{z} I{i} J{j} K{k} R{r} Q{q} H{h}\"] # " + post +
            ":68"})
    EXPECT_TRUE(has_line(lines, l)) << l << "\n" << r.out;
  // The heading, 77 keys (millturn.face_holes and xzc_tolerance, xzc_feed,
  // polar_interpolation, polar_address, polar_x, polar_rapid_feed, polar_arcs, time.rapid_c and
  // time.c_clamp among them), 12 formats (linuxcnc.yaml:
  // default X Z I K F S dwell g76_lead g76_depth g76_angle g76_taper) of 6 keys, 21 codes
  // (live_spindle_cw/ccw among them) and 18 templates (9, 6 hole cycles, auxfun, prefun and
  // program_header).
  EXPECT_EQ(lines.size(), 1u + 77 + 12 * 6 + 21 + 18);
}

TEST(MachinesShow, WithoutOriginAndAnUnknownMachine) {
  RunResult r = run(quote(clpost_bin()) + " machines show fanuc-0i-t");
  ASSERT_EQ(r.exit_code, 0) << r.err;
  const std::vector<std::string> lines = lines_of(r.out);
  EXPECT_TRUE(has_line(lines, "threading.cycle: fanuc_g76"));
  EXPECT_TRUE(has_line(lines, "comments.open: ("));
  EXPECT_TRUE(has_line(lines, "threading.lead_address_x: \"\""));
  EXPECT_TRUE(has_line(lines, "formats.g76_depth.scale: 1000"));
  EXPECT_TRUE(has_line(lines, "templates.g92_next: [\"X{x}{z}{taper}{start_angle}\"]"));
  r = run(quote(clpost_bin()) + " machines show fanuc-0i-t --set codes.rapdi=G0");
  EXPECT_EQ(r.exit_code, 2);
  EXPECT_EQ(r.err,
            "--set codes.rapdi=G0: error: unknown code 'codes.rapdi' (did you mean 'rapid'?)\n");
}

TEST(MachinesDiff, TheKeysWhoseValuesDiffer) {
  const std::string dir = source_dir();
  RunResult r = run(quote(clpost_bin()) + " machines diff generic-lathe nct-2000t");
  EXPECT_EQ(r.exit_code, 1);  // as diff: 1 when they differ
  EXPECT_EQ(
      r.out,
      "--- generic-lathe: " + dir +
          "/machines/generic-lathe.yaml\n"
          "+++ nct-2000t: " +
          dir +
          "/machines/nct-2000t.yaml\n"
          "extends: iso-lathe -> nct\n"
          "description: \"Generic 2-axis ISO lathe (G-code, diameter X, G33 emulated threads)\" "
          "-> \"NCT 2000T lathe (G33 loop, F lead / E threads per inch, Q start angle)\"\n"
          "comments.upper_case: false -> true\n"
          "limits.max_rpm: 4000 -> 3500\n"
          "limits.max_feed: 10000 -> 8000\n"
          "threading.strategy: emulate -> loop\n"
          "threading.fallback: error -> emulate\n"
          "threading.tpi_address: \"\" -> E\n"
          "threading.start_angle_word: false -> true\n"
          // NCT's CSS clamp is G92 S (posts/nct.yaml), the ISO post's G50 S.
          "templates.spindle_css: [\"G50 S{max_rpm}\", \"G96 S{speed} {direction}\"] -> "
          "[\"G92 S{max_rpm}\", \"G96 S{speed} {direction}\"]\n"
          "formats.E.decimals: (none) -> 6\n"
          "formats.E.trailing_zeros: (none) -> false\n"
          "formats.E.decimal_point: (none) -> true\n"
          "formats.E.leading_zero: (none) -> true\n"
          "formats.E.inch_decimals: (none) -> 6\n"
          "formats.E.scale: (none) -> 1\n"
          "16 keys differ\n");
  r = run(quote(clpost_bin()) + " machines diff haas-st haas-st");
  EXPECT_EQ(r.exit_code, 0);
  EXPECT_EQ(r.out, "--- haas-st: " + dir + "/machines/haas-st.yaml\n+++ haas-st: " + dir +
                       "/machines/haas-st.yaml\n0 keys differ\n");
  r = run(quote(clpost_bin()) + " machines diff haas-st hass-st");
  EXPECT_EQ(r.exit_code, 2);
  EXPECT_EQ(r.err.rfind("clpost: error: unknown machine 'hass-st' (did you mean 'haas-st'?)", 0),
            0u)
      << r.err;
}

TEST(Schema, JsonSchemaOfMachineFiles) {
  RunResult r = run(quote(clpost_bin()) + " schema");
  ASSERT_EQ(r.exit_code, 0) << r.err;
  const std::vector<std::string> lines = lines_of(r.out);
  EXPECT_EQ(lines.at(0), "{");
  EXPECT_EQ(lines.at(1), "  \"$schema\": \"https://json-schema.org/draft/2020-12/schema\",");
  EXPECT_EQ(lines.back(), "}");
  EXPECT_TRUE(has_line(lines, "          \"enum\": [\"cycle\", \"loop\", \"emulate\"],"));
  EXPECT_TRUE(has_line(lines,
                       "        \"rapid\": {\"type\": [\"string\", \"number\", "
                       "\"boolean\"], \"description\": \"rapid move (G0) (required)\"},"));
  RunResult md = run(quote(clpost_bin()) + " schema --markdown");
  EXPECT_EQ(md.exit_code, 0);
  EXPECT_EQ(md.out.rfind("<!-- BEGIN schema", 0), 0u);
}

}  // namespace
}  // namespace clpost::test

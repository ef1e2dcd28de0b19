// Machine files as an integrator meets them (issue 14): every name declared, and a template the
// program needs but the machine lacks is an error at the CL line that needs it.
#include <gtest/gtest.h>

#include <filesystem>

#include "test_util.h"

namespace clpost::test {
namespace {

namespace fs = std::filesystem;

// A machine of its own (no post) with the required codes and templates and nothing else.
constexpr const char* kBareMachine =
    "description: a lathe without constant surface speed\n"
    "codes: {rapid: G0, linear: G1, arc_cw: G2, arc_ccw: G3, thread: G33, metric: G21,\n"
    "        inch: G20, spindle_cw: M3, spindle_ccw: M4, feed_per_rev: G95}\n"
    "templates:\n"
    "  program_start: [\"%\"]\n"
    "  program_end: [\"M30\"]\n"
    "  tool_change: [\"T{tool}\"]\n"
    "  spindle_rpm: [\"G97 S{rpm} {direction}\"]\n"
    "  spindle_stop: [\"M5\"]\n";

constexpr const char* kCssPart =
    "UNITS/MM\n"
    "LOADTL/1\n"
    "SPINDL/200,SMM,MAXRPM,3000,CLW\n"
    "FEDRAT/0.2,MMPR\n"
    "GOTO/10,0,2\n"
    "FINI\n";

TEST(MachineFile, ConstantSurfaceSpeedWithoutItsTemplateIsAnErrorAtTheSpindlLine) {
  const std::string dir = temp_dir();
  write_file(dir + "/bare.yaml", kBareMachine);
  write_file(dir + "/css.cl", kCssPart);
  RunResult r = run(quote(clpost_bin()) + " -m " + quote(dir + "/bare.yaml") + " -o " +
                    quote(dir + "/css.nc") + " " + quote(dir + "/css.cl"));
  EXPECT_EQ(r.exit_code, 1);
  EXPECT_EQ(r.err, dir +
                       "/css.cl:3:1: error: machine 'bare' has no template 'spindle_css' "
                       "(templates.spindle_css in its machine or post file)\n"
                       "  SPINDL/200,SMM,MAXRPM,3000,CLW\n"
                       "  ^\n");
  EXPECT_FALSE(file_exists(dir + "/css.nc"));
  // The same part at a set RPM posts.
  write_file(dir + "/rpm.cl", "UNITS/MM\nLOADTL/1\nSPINDL/800,RPM,CLW\nFINI\n");
  r = run(quote(clpost_bin()) + " -m " + quote(dir + "/bare.yaml") + " " + quote(dir + "/rpm.cl"));
  EXPECT_EQ(r.exit_code, 0) << r.err;
  EXPECT_EQ(r.out, "%\nT1\nG97 S800. M3\nM30\n");
  fs::remove_all(dir);
}

TEST(MachineFile, SetOfAnUnknownCodeOrFormatExitsTwo) {
  const std::string part = quote(source_dir() + "/samples/pin-apt.apt");
  RunResult r = run(quote(clpost_bin()) + " --set codes.rapdi=G0 " + part);
  EXPECT_EQ(r.exit_code, 2);
  EXPECT_EQ(r.err,
            "--set codes.rapdi=G0: error: unknown code 'codes.rapdi' (did you mean 'rapid'?)\n");
  EXPECT_EQ(r.out, "");
  r = run(quote(clpost_bin()) + " --set formats.dwel.decimals=1 " + part);
  EXPECT_EQ(r.exit_code, 2);
  EXPECT_EQ(r.err,
            "--set formats.dwel.decimals=1: error: unknown format 'formats.dwel' (did you mean "
            "'dwell'?): a format is an address the machine writes or a named format "
            "(docs/machines.md)\n");
}

}  // namespace
}  // namespace clpost::test

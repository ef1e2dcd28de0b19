#pragma once
// Helpers for whole-program tests: run a command, read and write files.
#include <string>
#include <vector>

#include "machine/machine.h"
#include "machine/machine_test_util.h"

namespace clpost::test {

// Every shipped machine's name, sorted, as `clpost machines` lists them: a test that runs on every
// machine takes them from here and names none.
using ::clpost::testing::shipped_machine_names;
// Shipped machine `name` as clpost loads it (a machine that does not load fails the test).
Machine shipped_machine(const std::string& name);
// The reviewed golden of `sample` (a CL file under samples/) on shipped machine `m`, relative to
// the source tree: samples/golden/<machine>/<sample's stem><the machine's extension>.
std::string golden_path(const Machine& m, const std::string& sample);

struct RunResult {
  int exit_code = -1;  // 128 + signal when killed by a signal
  std::string out;
  std::string err;
};

// Runs `cmd` through /bin/sh with standard input from /dev/null (or `stdin_file`).
RunResult run(const std::string& cmd, const std::string& stdin_file = "/dev/null");

std::string read_file(const std::string& path);
void write_file(const std::string& path, const std::string& text);
bool file_exists(const std::string& path);
// A fresh empty directory under the system temp dir.
std::string temp_dir();
// Single-quoted for the shell.
std::string quote(const std::string& s);

inline std::string clpost_bin() {
  return CLPOST_BIN;
}
// rs274 crashes (SIGBUS) when two instances run at once, as ctest -j does: every call goes
// through one lock.
inline std::string rs274() {
  return "flock /tmp/clpost-rs274.lock rs274";
}
inline std::string source_dir() {
  return CLPOST_SOURCE_DIR;
}
inline std::string realcl_dir() {
  return std::string(CLPOST_SOURCE_DIR) + "/../shared/realcl";
}

// LinuxCNC's interpreter (Debian package linuxcnc-uspace) is installed.
bool rs274_available();
// `rs274 -t tests/data/lathe.tbl -g NGC` run in `dir` (under the lock above).
RunResult run_rs274(const std::string& dir, const std::string& ngc);

// A point of rs274's canonical output in the lathe's XZ plane: rs274 prints X as a radius even
// in G7 diameter mode, in the program's units.
struct CanonXZ {
  double x = 0, z = 0;
};
struct CanonSegment {
  CanonXZ from, to;
};
// The end point of every motion (traverse, feed, arc) of `rs274 -g` output, in order.
std::vector<CanonXZ> rs274_motion_ends(const std::string& canon);
inline std::string realcam_dir() {
  return std::string(CLPOST_SOURCE_DIR) + "/../shared/realcam";
}

// The spindle-synchronized feed moves of `rs274 -g` output (STRAIGHT_FEED between
// START_SPEED_FEED_SYNC and STOP_SPEED_FEED_SYNCH), each from where the previous straight move
// (traverse or feed) ended.
std::vector<CanonSegment> rs274_synced_moves(const std::string& canon);

}  // namespace clpost::test

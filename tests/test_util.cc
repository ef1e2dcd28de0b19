#include "test_util.h"
#include "controls/registry.h"

#include <gtest/gtest.h>
#include <sys/wait.h>
#include <unistd.h>

#include <cstdio>
#include <cstdlib>
#include <filesystem>
#include <fstream>
#include <sstream>

namespace clpost::test {

Machine shipped_machine(const std::string& name) {
  Machine m;
  std::string errors;
  EXPECT_TRUE(load_machine(name, {source_dir()}, {}, shipped_controls(), m, errors)) << errors;
  return m;
}

std::string golden_path(const Machine& m, const std::string& sample) {
  const std::string stem = std::filesystem::path(sample).stem().string();
  return "samples/golden/" + m.name + "/" + stem + m.extension;
}

std::string read_file(const std::string& path) {
  std::ifstream in(path, std::ios::binary);
  std::ostringstream ss;
  ss << in.rdbuf();
  return ss.str();
}

void write_file(const std::string& path, const std::string& text) {
  std::ofstream out(path, std::ios::binary);
  out << text;
}

bool file_exists(const std::string& path) {
  return std::filesystem::exists(path);
}

std::string temp_dir() {
  std::string templ = (std::filesystem::temp_directory_path() / "clpost-test-XXXXXX").string();
  char* d = ::mkdtemp(templ.data());
  return d ? std::string(d) : std::string();
}

std::string quote(const std::string& s) {
  std::string q = "'";
  for (char c : s) q += c == '\'' ? std::string("'\\''") : std::string(1, c);
  return q + "'";
}

RunResult run(const std::string& cmd, const std::string& stdin_file) {
  std::string dir = temp_dir();
  std::string out = dir + "/out", err = dir + "/err";
  std::string full = "(" + cmd + ") <" + quote(stdin_file) + " >" + quote(out) + " 2>" + quote(err);
  int status = std::system(full.c_str());
  RunResult r;
  if (WIFEXITED(status))
    r.exit_code = WEXITSTATUS(status);
  else if (WIFSIGNALED(status))
    r.exit_code = 128 + WTERMSIG(status);
  r.out = read_file(out);
  r.err = read_file(err);
  std::filesystem::remove_all(dir);
  return r;
}

bool rs274_available() {
  return run("command -v rs274").exit_code == 0;
}

RunResult run_rs274(const std::string& dir, const std::string& ngc) {
  return run("cd " + quote(dir) + " && " + rs274() + " -t " +
             quote(source_dir() + "/tests/data/lathe.tbl") + " -g " + quote(ngc));
}

std::vector<CanonXZ> rs274_motion_ends(const std::string& canon) {
  std::vector<CanonXZ> out;
  std::istringstream in(canon);
  std::string line;
  while (std::getline(in, line)) {
    double a[3] = {};
    size_t p;
    if ((p = line.find("STRAIGHT_TRAVERSE(")) != std::string::npos ||
        (p = line.find("STRAIGHT_FEED(")) != std::string::npos) {
      const char* s = line.c_str() + line.find('(', p) + 1;
      if (std::sscanf(s, "%lf, %lf, %lf", &a[0], &a[1], &a[2]) == 3) out.push_back({a[0], a[2]});
    } else if ((p = line.find("ARC_FEED(")) != std::string::npos) {
      // XZ plane: first axis Z, second axis X.
      const char* s = line.c_str() + p + 9;
      if (std::sscanf(s, "%lf, %lf", &a[0], &a[1]) == 2) out.push_back({a[1], a[0]});
    }
  }
  return out;
}

std::vector<CanonSegment> rs274_synced_moves(const std::string& canon) {
  std::vector<CanonSegment> out;
  std::istringstream in(canon);
  std::string line;
  CanonXZ pos;
  bool sync = false;
  while (std::getline(in, line)) {
    if (line.find("START_SPEED_FEED_SYNC") != std::string::npos) sync = true;
    if (line.find("STOP_SPEED_FEED_SYNCH") != std::string::npos) sync = false;
    size_t p = line.find("STRAIGHT_");
    if (p == std::string::npos) continue;
    double x, y, z;
    if (std::sscanf(line.c_str() + line.find('(', p) + 1, "%lf, %lf, %lf", &x, &y, &z) != 3)
      continue;
    CanonXZ to{x, z};
    if (sync && line.find("STRAIGHT_FEED") != std::string::npos) out.push_back({pos, to});
    pos = to;
  }
  return out;
}

}  // namespace clpost::test

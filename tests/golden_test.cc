// Every sample posts on every shipped machine exactly as its reviewed golden NC file says:
// samples/*.{cls,ncl,apt,cl} and the shared thread set samples/threads/*.apt on every machine,
// samples/machines/<machine>.* on its own machine, samples/millturn/*.apt on every machine with
// live tools (millturn.live_tools). Goldens: samples/golden/<machine>/<name><ext> (thread samples
// as threads-<stem>, mill-turn samples as millturn-<stem>). scripts/update-goldens.sh rewrites them
// (review the diff line by line before committing).
#include <gtest/gtest.h>

#include <filesystem>
#include <set>

#include "test_util.h"

namespace clpost::test {
namespace {

namespace fs = std::filesystem;

struct ShippedMachine {
  std::string name, ext;
  bool live_tools = false;
};

// Every shipped machine with its output extension.
std::vector<ShippedMachine> shipped_machines() {
  std::vector<ShippedMachine> out;
  for (const std::string& name : shipped_machine_names()) {
    const Machine m = shipped_machine(name);
    out.push_back({name, m.extension, m.live_tools});
  }
  return out;
}

bool is_cl(const fs::path& p) {
  std::string ext = p.extension().string();
  return ext == ".cls" || ext == ".ncl" || ext == ".apt" || ext == ".cl";
}

std::vector<fs::path> cl_files(const fs::path& dir) {
  std::vector<fs::path> out;
  for (const auto& e : fs::directory_iterator(dir))
    if (e.is_regular_file() && is_cl(e.path())) out.push_back(e.path());
  std::sort(out.begin(), out.end());
  return out;
}

struct Case {
  fs::path cl;
  std::string golden_name;  // without extension
};

std::vector<Case> golden_cases(const ShippedMachine& machine) {
  fs::path samples = source_dir() + "/samples";
  std::vector<Case> out;
  for (const fs::path& p : cl_files(samples)) out.push_back({p, p.stem().string()});
  for (const fs::path& p : cl_files(samples / "threads"))
    out.push_back({p, "threads-" + p.stem().string()});
  for (const fs::path& p : cl_files(samples / "machines"))
    if (p.stem() == machine.name) out.push_back({p, p.stem().string()});
  if (machine.live_tools)
    for (const fs::path& p : cl_files(samples / "millturn"))
      out.push_back({p, "millturn-" + p.stem().string()});
  return out;
}

// A sample the machine refuses (an inch file on a HEIDENHAIN machine in mm): its reviewed
// refusal, clpost's errors as written from the source tree, samples/golden/<machine>/<name>.err.
fs::path refusal_of(const ShippedMachine& m, const Case& c) {
  return fs::path(source_dir()) / "samples/golden" / m.name / (c.golden_name + ".err");
}

void expect_refused(const ShippedMachine& m, const Case& c, const std::string& out) {
  const fs::path rel = fs::relative(c.cl, source_dir());
  fs::remove(out);  // another machine's program of the sample
  RunResult r = run("cd " + quote(source_dir()) + " && " + quote(clpost_bin()) + " -m " + m.name +
                    " -o " + quote(out) + " " + quote(rel.string()));
  EXPECT_EQ(r.exit_code, 1) << c.cl << " on " << m.name;
  EXPECT_FALSE(fs::exists(out)) << out;
  EXPECT_EQ(r.err, read_file(refusal_of(m, c).string())) << c.cl << " on " << m.name;
}

TEST(Golden, EverySamplePostsAsReviewedOnEveryMachine) {
  std::vector<ShippedMachine> machines = shipped_machines();
  ASSERT_GE(machines.size(), 2u);
  std::string dir = temp_dir();
  int compared = 0;
  for (const ShippedMachine& m : machines) {
    std::vector<Case> cases = golden_cases(m);
    ASSERT_GE(cases.size(), 10u) << "four samples and the seven shared thread samples";
    for (const Case& c : cases) {
      fs::path golden =
          fs::path(source_dir()) / "samples/golden" / m.name / (c.golden_name + m.ext);
      std::string out = dir + "/" + c.golden_name + m.ext;
      if (fs::exists(refusal_of(m, c))) {
        expect_refused(m, c, out);
        ++compared;
        continue;
      }
      ASSERT_TRUE(fs::exists(golden)) << "missing golden " << golden;
      RunResult r = run(quote(clpost_bin()) + " -m " + m.name + " -o " + quote(out) + " " +
                        quote(c.cl.string()));
      EXPECT_EQ(r.exit_code, 0) << c.cl << " on " << m.name << "\n" << r.err;
      EXPECT_EQ(read_file(out), read_file(golden.string())) << c.cl << " on " << m.name;
      ++compared;
    }
  }
  EXPECT_GE(compared, 22);
  fs::remove_all(dir);
}

// Every reviewed program, read back through its control's laws (clpost verify), cuts exactly
// the plan of its sample: every thread, every pass.
TEST(Golden, EveryGoldenVerifiesAgainstItsSample) {
  int verified = 0;
  for (const ShippedMachine& m : shipped_machines()) {
    for (const Case& c : golden_cases(m)) {
      if (fs::exists(refusal_of(m, c))) continue;  // no program to verify
      fs::path golden =
          fs::path(source_dir()) / "samples/golden" / m.name / (c.golden_name + m.ext);
      RunResult r = run(quote(clpost_bin()) + " verify -m " + m.name + " " +
                        quote(golden.string()) + " --cl " + quote(c.cl.string()));
      EXPECT_EQ(r.exit_code, 0) << golden << "\n" << r.out << r.err;
      EXPECT_NE(r.out.find("\nok: every pass is cut as planned, within "), std::string::npos)
          << golden << "\n"
          << r.out;
      EXPECT_EQ(r.err, "") << golden;
      ++verified;
    }
  }
  EXPECT_GE(verified, 7 * 11 + 6);
}

// No golden without its sample: a renamed sample must not leave a stale reviewed file behind.
TEST(Golden, EveryGoldenHasItsSample) {
  for (const ShippedMachine& m : shipped_machines()) {
    std::set<std::string> expected;
    for (const Case& c : golden_cases(m))
      expected.insert(c.golden_name + (fs::exists(refusal_of(m, c)) ? ".err" : m.ext));
    for (const auto& e : fs::directory_iterator(source_dir() + "/samples/golden/" + m.name))
      EXPECT_TRUE(expected.count(e.path().filename().string()))
          << "stale golden " << e.path() << " (no sample posts to it)";
  }
}

}  // namespace
}  // namespace clpost::test

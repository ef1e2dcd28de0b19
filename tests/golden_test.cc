// Every sample posts on every shipped machine exactly as its reviewed golden NC file says.
// The goldens sit beside the samples as <stem>.<machine><extension>; scripts/update-goldens.sh
// rewrites them (review the diff line by line before committing).
#include <gtest/gtest.h>

#include <filesystem>

#include "test_util.h"

namespace clpost::test {
namespace {

namespace fs = std::filesystem;

struct MachineExt {
  const char* name;
  const char* ext;
};
constexpr MachineExt kMachines[] = {{"generic-lathe", ".nc"}, {"linuxcnc-lathe", ".ngc"}};

std::vector<fs::path> samples() {
  std::vector<fs::path> out;
  for (const auto& e : fs::directory_iterator(source_dir() + "/samples")) {
    std::string ext = e.path().extension().string();
    if (ext == ".cls" || ext == ".ncl" || ext == ".apt" || ext == ".cl") out.push_back(e.path());
  }
  std::sort(out.begin(), out.end());
  return out;
}

TEST(Golden, EverySamplePostsAsReviewed) {
  std::vector<fs::path> cls = samples();
  ASSERT_GE(cls.size(), 3u) << "at least three samples in different dialects";
  std::string dir = temp_dir();
  int compared = 0;
  for (const fs::path& cl : cls) {
    for (const MachineExt& m : kMachines) {
      fs::path golden = cl.parent_path() / (cl.stem().string() + "." + m.name + m.ext);
      ASSERT_TRUE(fs::exists(golden)) << "missing golden " << golden;
      std::string out = dir + "/" + cl.stem().string() + m.ext;
      RunResult r = run(quote(clpost_bin()) + " -m " + m.name + " -o " + quote(out) + " " +
                        quote(cl.string()));
      EXPECT_EQ(r.exit_code, 0) << cl << " on " << m.name << "\n" << r.err;
      EXPECT_EQ(read_file(out), read_file(golden.string())) << cl << " on " << m.name;
      ++compared;
    }
  }
  EXPECT_EQ(compared, static_cast<int>(cls.size() * std::size(kMachines)));
  fs::remove_all(dir);
}

}  // namespace
}  // namespace clpost::test

// Binary CLDATA through the binary (issue 18): a binary file posts to the same NC program as the
// APT text it was written from, and as its cl2apt text; the real APT360 file converts to the
// part program's path and posts with located diagnostics.
#include <gtest/gtest.h>

#include <cmath>
#include <filesystem>
#include <map>
#include <sstream>

#include "reader/cldata_writer.h"
#include "support/diagnostics.h"
#include "test_util.h"

namespace clpost::test {
namespace {

namespace fs = std::filesystem;

std::string realcam_tap() {
  return source_dir() + "/../shared/realcam/apt360_binary/cl.tap";
}

// Record k for line k (cldata_writer.h).
std::string encode(const std::string& apt) {
  Diagnostics diags("t.apt");
  std::string bin;
  EXPECT_TRUE(cldata::encode_apt(apt, diags, bin)) << diags.render_all();
  return bin;
}

RunResult post(const std::string& machine, const std::string& file) {
  return run(quote(clpost_bin()) + " -m " + machine + " " + quote(file));
}

// Every APT sample of the repository (the shared thread set, each machine's own program, the
// M20 part), written as binary records, posts to the same bytes as the text on two machines,
// and so does the binary file's cl2apt text. (Records of many points read as the same
// statements too: cldata_reader_test.cc.)
TEST(Cldata, BinaryPostsLikeItsAptText) {
  std::vector<std::string> samples = {source_dir() + "/samples/thread-m20.apt",
                                      source_dir() + "/samples/pin-apt.apt"};
  for (const auto& dir : {"/samples/threads", "/samples/machines"})
    for (const auto& e : fs::directory_iterator(source_dir() + dir))
      if (e.path().extension() == ".apt") samples.push_back(e.path().string());
  std::sort(samples.begin(), samples.end());
  ASSERT_EQ(samples.size(), 19u);
  const std::string dir = temp_dir();
  for (const std::string& apt_path : samples) {
    const std::string apt = read_file(apt_path);
    {
      const std::string bin = dir + "/part.cl";
      write_file(bin, encode(apt));
      // cl2apt's text of the binary file posts the same program too.
      const RunResult conv =
          run(quote(clpost_bin()) + " cl2apt -o " + quote(dir + "/back.apt") + " " + quote(bin));
      ASSERT_EQ(conv.exit_code, 0) << apt_path << "\n" << conv.err;
      // Each machine's own sample on its machine, the others on two.
      const std::string stem = fs::path(apt_path).stem().string();
      std::vector<std::string> machines = {"generic-lathe", "fanuc-0i-t"};
      if (apt_path.find("/machines/") != std::string::npos) machines = {stem};
      for (const std::string& machine : machines) {
        const RunResult want = post(machine, apt_path);
        const RunResult got = post(machine, bin);
        const RunResult back = post(machine, dir + "/back.apt");
        ASSERT_EQ(want.exit_code, 0) << apt_path << "\n" << want.err;
        EXPECT_EQ(got.exit_code, 0) << apt_path << " " << machine << "\n" << got.err;
        EXPECT_EQ(got.out, want.out) << apt_path << " " << machine;
        EXPECT_EQ(back.out, want.out) << apt_path << " " << machine;
        EXPECT_NE(want.out.find("G"), std::string::npos);
      }
    }
  }
}

// Found by CI's fuzz smoke run: a binary statement had no `source` (its text as written), so
// the words after COOLNT's were looked up in an empty string (an exception), and a statement
// written as a comment (GOHOME without a home) would have been an empty comment. Both say the
// record's APT text now, as the text file's post does.
TEST(Cldata, BinaryStatementsAreWrittenAsTheirAptText) {
  const std::string apt = "COOLNT/FLOOD,2\nGOHOME\nFINI\n";
  const std::string dir = temp_dir();
  write_file(dir + "/part.apt", apt);
  write_file(dir + "/part.cl", encode(apt));
  const RunResult text = post("generic-lathe", dir + "/part.apt");
  const RunResult bin = post("generic-lathe", dir + "/part.cl");
  EXPECT_EQ(bin.exit_code, 0) << bin.err;
  EXPECT_EQ(bin.out, text.out);
  EXPECT_NE(bin.err.find("warning: COOLNT/FLOOD: the words after it are not written ('2')"),
            std::string::npos)
      << bin.err;
  EXPECT_NE(bin.out.find("(GOHOME)"), std::string::npos) << bin.out;
}

// The points of cl.tap, checked against window.apt by hand: a 0.2 cutter (radius 0.1) from
// SPT=(4,0,0) down 0.2 (GODLTA), then inside C2 (centre 22,-3, radius 21.5: the tool centre at
// 21.4), around the fillet C4 (radius 0.25: 0.15), C1 (centre 0,0, radius 2, the tool outside
// the window's inner arc: 1.9) and C3 (0.15), then 0.2 deeper and around C2 again.
TEST(Cldata, RealApt360FileConvertsToThePartProgramsPath) {
  if (!file_exists(realcam_tap())) GTEST_SKIP() << "../shared/realcam not found";
  const RunResult r = run(quote(clpost_bin()) + " cl2apt " + quote(realcam_tap()));
  ASSERT_EQ(r.exit_code, 0) << r.err;
  EXPECT_EQ(r.err, realcam_tap() + ": record 64 (byte 4664): note: 1 bytes after FINI ignored\n");
  std::istringstream in(r.out);
  std::string line;
  std::vector<std::string> majors;
  std::map<std::string, size_t> points_on;  // surface name -> points checked on it
  std::string surface;
  double cx = 0, cy = 0, radius = 0;
  double z = 0, last_y = 0;
  while (std::getline(in, line)) {
    if (line.starts_with("$$ surface ")) {
      // $$ surface C2: CIRCLE/22,-3,0,0,0,1,21.5
      surface = line.substr(11, line.find(':') - 11);
      double cz, i, j, k;
      ASSERT_EQ(std::sscanf(line.c_str() + line.find('/') + 1, "%lf,%lf,%lf,%lf,%lf,%lf,%lf", &cx,
                            &cy, &cz, &i, &j, &k, &radius),
                7)
          << line;
      continue;
    }
    if (line.starts_with("$$ ISN ")) surface.clear();  // a new statement of window.apt
    if (line.starts_with("$$")) continue;
    majors.push_back(line.substr(0, line.find('/')));
    double x, y;
    if (std::sscanf(line.c_str(), "GOTO/%lf,%lf,%lf", &x, &y, &z) == 3) last_y = y;
    if (line.starts_with("GOTO/") && !surface.empty()) {
      EXPECT_NEAR(std::hypot(x - cx, y - cy), radius - 0.1, 5e-4) << surface << ": " << line;
      ++points_on[surface];
    }
  }
  EXPECT_EQ(majors.front(), "PARTNO A WINDOW");
  EXPECT_EQ(std::count(majors.begin(), majors.end(), "GOTO"), 91);
  EXPECT_NE(r.out.find("\nFROM/4,0,0\n"), std::string::npos);
  EXPECT_NE(r.out.find("\nGOTO/4,0,-0.2\n"), std::string::npos);  // GODLTA/0,0,-.2 from SPT
  EXPECT_NE(r.out.find("\nSPINDL/3000,CLW\n"), std::string::npos);
  EXPECT_NE(r.out.find("\nFEDRAT/30\n"), std::string::npos);
  EXPECT_NE(r.out.find("\nCOOLNT/OFF\n$$ ISN 44\nOPSTOP\n$$ ISN 45\nREWIND\n$$ ISN 54\nFINI\n"),
            std::string::npos);
  EXPECT_EQ(z, -0.4);  // the second pass, 0.2 deeper
  // GO/TO,C2: the first point on C2, before its surface record.
  EXPECT_NE(r.out.find("\nGOTO/0.8911700299921255,0.5181383283346455,-0.2\n"), std::string::npos);
  EXPECT_NEAR(std::hypot(0.8911700299921255 - 22, 0.5181383283346455 + 3), 21.4, 5e-4);
  // The last point: GOFWD/C2,PAST,L1 (the X axis) ends the tool radius past it.
  EXPECT_NEAR(last_y, -0.1, 1e-12);
  // GO/TO,C2 then the C2 arcs (9, 6 and 2 points), C4 and C3 (14 each), C1 (43).
  EXPECT_EQ(points_on,
            (std::map<std::string, size_t>{{"C1", 43}, {"C2", 17}, {"C3", 14}, {"C4", 14}}));
}

// It is a milling program (Y moves, CUTCOM/LENGTH): on a lathe it fails, each problem named by
// its record and byte, with the record's APT text; nothing is written.
TEST(Cldata, RealApt360FilePostsWithLocatedDiagnostics) {
  if (!file_exists(realcam_tap())) GTEST_SKIP() << "../shared/realcam not found";
  const std::string dir = temp_dir();
  const RunResult r =
      run(quote(clpost_bin()) + " -o " + quote(dir + "/out.nc") + " " + quote(realcam_tap()));
  EXPECT_EQ(r.exit_code, 1) << r.err;
  const std::string f = realcam_tap();
  EXPECT_NE(r.err.find(f + ": record 22 (byte 760): error: unknown CUTCOM word 'LENGTH': "
                           "expected LEFT, RIGHT or OFF\n  CUTCOM/LENGTH,1\n"),
            std::string::npos)
      << r.err;
  EXPECT_NE(r.err.find(f + ": record 31 (byte 1072): error: CL Y = 0.5181383283346455 but the "
                           "radius is CL X (found at line 14): the program moves in both, off "
                           "the lathe plane"),
            std::string::npos)
      << r.err;
  EXPECT_FALSE(file_exists(dir + "/out.nc"));
}

TEST(Cldata, Cl2AptRefusesTextAndDamagedFiles) {
  const std::string dir = temp_dir();
  write_file(dir + "/text.cl", "GOTO/1,0,0\nFINI\n");
  RunResult r = run(quote(clpost_bin()) + " cl2apt -o " + quote(dir + "/out.apt") + " " +
                    quote(dir + "/text.cl"));
  EXPECT_EQ(r.exit_code, 1);
  EXPECT_EQ(r.err, dir +
                       "/text.cl: error: not a binary CLDATA file (cl2apt converts binary CL "
                       "records to APT text)\n");
  EXPECT_FALSE(file_exists(dir + "/out.apt"));
  // A binary file cut in its last record: an error, and no output file (nor a temporary one).
  const std::string bin = encode("FEDRAT/0.2\nGOTO/1,0,0\nFINI\n");
  write_file(dir + "/cut.cl", bin.substr(0, bin.size() - 20));
  r = run(quote(clpost_bin()) + " cl2apt -o " + quote(dir + "/out.apt") + " " +
          quote(dir + "/cut.cl"));
  EXPECT_EQ(r.exit_code, 1);
  EXPECT_EQ(r.err, dir +
                       "/cut.cl: record 2 (byte 24): error: truncated record: type 5000 of 5 "
                       "words (40 bytes), 36 bytes left\n");
  EXPECT_EQ(std::distance(fs::directory_iterator(dir), fs::directory_iterator()), 2);
  // The whole file: line k is record k.
  write_file(dir + "/ok.cl", bin);
  r = run(quote(clpost_bin()) + " cl2apt -o " + quote(dir + "/out.apt") + " " +
          quote(dir + "/ok.cl"));
  EXPECT_EQ(r.exit_code, 0) << r.err;
  EXPECT_EQ(read_file(dir + "/out.apt"),
            "FEDRAT/0.2\nGOTO/1,0,0\nFINI\n$$ " + dir +
                "/ok.cl: binary CLDATA (APT360 layout), written as APT by clpost cl2apt\n");
}

}  // namespace
}  // namespace clpost::test

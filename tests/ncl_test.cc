// NCL's binary clfiles (../shared/ncl, read in place): `clpost cl2apt` gives the statements of the
// APT source NCL wrote beside each (.as), and each .cl posts as its .as does.
#include <gtest/gtest.h>

#include <cmath>
#include <cstdlib>
#include <filesystem>
#include <map>
#include <sstream>

#include "reader/cl_reader.h"
#include "test_util.h"

namespace clpost::test {
namespace {

namespace fs = std::filesystem;

std::string ncl_dir() {
  return source_dir() + "/../shared/ncl";
}

// A statement as compared: its form, major word, text, and arguments (numbers as written, for
// the precision the .as wrote them with).
struct Seen {
  Statement::Form form;
  std::string major, text;
  std::vector<std::pair<bool, std::string>> args;  // (is a number, text)
  uint32_t line = 0;
};

std::vector<Seen> statements(const std::string& apt) {
  Diagnostics diags("t.apt");
  ClReader r(apt, diags);
  std::vector<Seen> out;
  Statement st;
  while (r.next(st)) {
    Seen s{st.form, std::string(st.major), std::string(st.text), {}, st.loc.line};
    for (const Arg& a : st.args) s.args.emplace_back(a.is_number(), std::string(a.text));
    out.push_back(std::move(s));
  }
  EXPECT_EQ(diags.render_all(), "");
  return out;
}

// Half a unit of the last decimal `text` is written with: the .as's rounding.
double half_unit(const std::string& text) {
  const size_t dot = text.find('.');
  const size_t decimals = dot == std::string::npos ? 0 : text.size() - dot - 1;
  return 0.5 * std::pow(10.0, -static_cast<double>(decimals)) + 1e-12;
}

// The REMARK header each .cl begins with (the .as's is from its own run: its name ends in .as).
const std::map<std::string, std::string> kRemark = {
    {"Volumill_1a", "Volumill_1a      5-JAN-2021  17:05:20  NCLCAM     2020.00"},
    {"upside_down", "upside_down     14-FEB-2019   9:00:41  NCLCAM     2019.01"},
};

TEST(NclFiles, Cl2aptGivesTheStatementsOfTheAsTwin) {
  if (!fs::is_directory(ncl_dir())) GTEST_SKIP() << ncl_dir() << " not found: NCL files skipped";
  const std::string dir = temp_dir();
  const std::map<std::string, size_t> counts = {{"Volumill_1a", 4}, {"upside_down", 37}};
  for (const auto& [stem, count] : counts) {
    const std::string out = dir + "/" + stem + ".apt";
    const RunResult r = run(quote(clpost_bin()) + " cl2apt -o " + quote(out) + " " +
                            quote(ncl_dir() + "/" + stem + ".cl"));
    ASSERT_EQ(r.exit_code, 0) << stem << "\n" << r.err;
    const std::vector<Seen> got = statements(read_file(out));
    const std::vector<Seen> want = statements(read_file(ncl_dir() + "/" + stem + ".as"));
    ASSERT_EQ(got.size(), count) << stem;
    ASSERT_EQ(want.size(), count) << stem;
    EXPECT_EQ(got[0].major, "REMARK");
    EXPECT_EQ(got[0].text, kRemark.at(stem));
    for (size_t i = 0; i < count; ++i) {
      const Seen &g = got[i], &w = want[i];
      const std::string at = stem + ".as line " + std::to_string(w.line);
      EXPECT_EQ(g.line, i + 1) << at;  // line k of cl2apt's text is record k
      EXPECT_EQ(g.form, w.form) << at;
      EXPECT_EQ(g.major, w.major) << at;
      const auto trimmed = [](const std::string& t) {
        return t.substr(0, t.find_last_not_of(' ') + 1);
      };
      if (g.form == Statement::Form::kText && g.major != "REMARK") {
        EXPECT_EQ(trimmed(g.text), trimmed(w.text)) << at;
      }
      ASSERT_EQ(g.args.size(), w.args.size()) << at;
      for (size_t k = 0; k < g.args.size(); ++k) {
        ASSERT_EQ(g.args[k].first, w.args[k].first) << at << " argument " << k + 1;
        if (!w.args[k].first) {
          EXPECT_EQ(g.args[k].second, w.args[k].second) << at;
          continue;
        }
        const double a = std::strtod(g.args[k].second.c_str(), nullptr);
        const double b = std::strtod(w.args[k].second.c_str(), nullptr);
        EXPECT_LE(std::fabs(a - b), half_unit(w.args[k].second))
            << at << " argument " << k + 1 << ": " << g.args[k].second << " vs "
            << w.args[k].second;
      }
    }
  }
}

// The error messages of a post, in order, without their locations (a line of the .as, a record
// of the .cl).
std::vector<std::string> errors(const std::string& err) {
  std::vector<std::string> out;
  std::istringstream in(err);
  for (std::string l; std::getline(in, l);)
    if (const size_t p = l.find(": error: "); p != std::string::npos) out.push_back(l.substr(p));
  return out;
}

// Modal X, Z and F after each block of an NC program: the same path whichever words a block
// leaves out because they did not change.
std::vector<std::map<char, double>> positions(const std::string& nc) {
  std::vector<std::map<char, double>> out;
  std::map<char, double> at;
  std::istringstream in(nc);
  for (std::string l; std::getline(in, l);) {
    std::istringstream words(l);
    for (std::string w; words >> w;)
      if (w.size() > 1 && (w[0] == 'X' || w[0] == 'Z' || w[0] == 'F'))
        at[w[0]] = std::strtod(w.c_str() + 1, nullptr);
    out.push_back(at);
  }
  return out;
}

TEST(NclFiles, PostLikeTheirAsTwins) {
  if (!fs::is_directory(ncl_dir())) GTEST_SKIP() << ncl_dir() << " not found: NCL files skipped";
  const std::string post = quote(clpost_bin()) + " -m generic-lathe ";
  const auto file = [](const std::string& name) { return quote(ncl_dir() + "/" + name); };
  // Volumill_1a: header, MULTAX/ON twice, FINI: the same (empty) program.
  RunResult cl = run(post + file("Volumill_1a.cl")), as = run(post + file("Volumill_1a.as"));
  EXPECT_EQ(cl.exit_code, 0) << cl.err;
  EXPECT_EQ(as.exit_code, 0) << as.err;
  EXPECT_EQ(cl.out, as.out);
  EXPECT_EQ(cl.out,
            "%\nO0001\nN10 G18 G21 G40 G90\n(machine generic-lathe, program Volumill_1a)\n"
            "(cycle time 0:00.0, 0 tool changes)\nN20 M30\n%\n");
  // upside_down is a five-axis milling program with no feed: on a lathe (its Y ignored) both
  // stop on the same 23 feed moves, and neither writes a program.
  const std::string x = post + "--set cl.radial_axis=x ";
  cl = run(x + file("upside_down.cl"));
  as = run(x + file("upside_down.as"));
  EXPECT_EQ(cl.exit_code, 1);
  EXPECT_EQ(as.exit_code, 1);
  EXPECT_EQ(cl.out, "");
  EXPECT_EQ(errors(cl.err), errors(as.err));
  EXPECT_EQ(errors(cl.err),
            std::vector<std::string>(23,
                                     ": error: feed move before any FEDRAT/: the feed is "
                                     "unknown"));
  // Given a feed after its tool change, the .cl (as its cl2apt text) and the .as post the same
  // path: every X and Z within the program's least increment, 0.001 (the .as has 4 decimals).
  const std::string dir = temp_dir();
  const RunResult conv = run(quote(clpost_bin()) + " cl2apt -o " + quote(dir + "/cl.apt") + " " +
                             file("upside_down.cl"));
  ASSERT_EQ(conv.exit_code, 0) << conv.err;
  const auto with_feed = [](std::string apt, const std::string& loadtl) {
    const size_t at = apt.find(loadtl);
    if (at == std::string::npos) return std::string("no " + loadtl);
    return apt.insert(apt.find('\n', at) + 1, "FEDRAT/10,IPM\n");
  };
  write_file(dir + "/cl_feed.apt", with_feed(read_file(dir + "/cl.apt"), "LOADTL/1"));
  write_file(dir + "/as_feed.apt",
             with_feed(read_file(ncl_dir() + "/upside_down.as"), "LOADTL/         1"));
  cl = run(x + quote(dir + "/cl_feed.apt"));
  as = run(x + quote(dir + "/as_feed.apt"));
  ASSERT_EQ(cl.exit_code, 0) << cl.err;
  ASSERT_EQ(as.exit_code, 0) << as.err;
  const auto p = positions(cl.out), q = positions(as.out);
  ASSERT_EQ(p.size(), 35u);  // %, O0001, 29 numbered blocks, 3 header comments, %
  ASSERT_EQ(q.size(), p.size());
  size_t differ = 0;
  for (size_t i = 0; i < p.size(); ++i) {
    ASSERT_EQ(p[i].size(), q[i].size()) << "line " << i + 1;
    for (const auto& [axis, v] : p[i]) {
      EXPECT_NEAR(v, q[i].at(axis), 0.001 + 1e-9) << axis << " of line " << i + 1;
      differ += v != q[i].at(axis);
    }
  }
  // One Z: 2.2725412 in the .cl, 2.2725 in the .as, written 2.273 and 2.272 at N70; N80 goes to
  // 2.272 in both.
  EXPECT_EQ(differ, 1u);
}

}  // namespace
}  // namespace clpost::test

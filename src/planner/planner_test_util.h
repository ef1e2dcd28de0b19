#pragma once
// Test helpers for the planner: statements built from one line of CL text (without the reader,
// so the planner tests do not depend on it), and thread inputs built from them.
#include <cctype>
#include <cstdlib>
#include <deque>
#include <string>
#include <vector>

#include "planner/planner.h"
#include "reader/statement.h"
#include "support/diagnostics.h"

namespace clpost::testing {

// `MAJOR/arg, arg, ...` on one line: words upper-cased, numbers parsed, columns 1-based.
class TestStatement {
 public:
  explicit TestStatement(std::string line, uint32_t line_no = 1) : text_(std::move(line)) {
    st.first_line = line_no;
    st.lines.push_back(text_);
    const std::string_view all = text_;
    const size_t slash = all.find('/');
    const size_t major_end = slash == std::string_view::npos ? all.size() : slash;
    size_t b = 0;
    while (b < major_end && all[b] == ' ') ++b;
    size_t e = major_end;
    while (e > b && all[e - 1] == ' ') --e;
    st.major = store_upper(all.substr(b, e - b));
    st.loc = {line_no, static_cast<uint32_t>(b + 1)};
    st.form = slash == std::string_view::npos ? Statement::Form::kBare : Statement::Form::kRecord;
    if (slash == std::string_view::npos) return;
    size_t i = slash + 1;
    while (i <= all.size()) {
      size_t j = all.find(',', i);
      if (j == std::string_view::npos) j = all.size();
      size_t tb = i;
      while (tb < j && all[tb] == ' ') ++tb;
      size_t te = j;
      while (te > tb && all[te - 1] == ' ') --te;
      if (te > tb) {
        Arg a;
        a.loc = {line_no, static_cast<uint32_t>(tb + 1)};
        const std::string tok(all.substr(tb, te - tb));
        char* end = nullptr;
        const double v = std::strtod(tok.c_str(), &end);
        if (end == tok.c_str() + tok.size() && !std::isalpha(static_cast<unsigned char>(tok[0]))) {
          a.kind = Arg::Kind::kNumber;
          a.text = all.substr(tb, te - tb);
          a.number = v;
        } else {
          a.kind = Arg::Kind::kWord;
          a.text = store_upper(tok);
        }
        st.args.push_back(a);
      }
      i = j + 1;
    }
  }
  TestStatement(const TestStatement&) = delete;
  TestStatement& operator=(const TestStatement&) = delete;

  Statement st;
  SavedLines saved() const { return SavedLines::of(st); }

 private:
  std::string_view store_upper(std::string_view s) {
    std::string u(s);
    for (char& c : u) c = static_cast<char>(std::toupper(static_cast<unsigned char>(c)));
    words_.push_back(std::move(u));
    return words_.back();
  }
  std::string text_;
  std::deque<std::string> words_;
};

// A GOTO on line `line_no` (its text is `GOTO/x,0,z`, the location its major word).
inline ThreadGoto make_goto(Vec2 p, uint32_t line_no) {
  ThreadGoto g;
  g.point = p;
  g.loc = {line_no, 1};
  g.lines.first_line = line_no;
  g.lines.lines.push_back("GOTO/" + std::to_string(p.x) + ",0," + std::to_string(p.z));
  return g;
}

// A multi-pass thread: THREAD/ON statement `on` (line 2), P0 and the GOTOs (lines 3, 4, ...).
// Parses the words with parse_thread_words from `first_arg`; `parsed` tells whether that worked.
struct MultiCase {
  MultiThreadInput in;
  bool parsed = false;
};

inline MultiCase make_multi(const TestStatement& on, LengthUnit units, Vec2 p0,
                            const std::vector<Vec2>& gotos, Diagnostics& diags,
                            size_t first_arg = 1) {
  MultiCase c;
  c.in.units = units;
  c.in.p0 = p0;
  c.in.on_loc = on.st.loc;
  c.in.on_lines = on.saved();
  c.parsed = parse_thread_words(on.st, first_arg, units, c.in.words, diags);
  uint32_t line = on.st.first_line + 1;
  for (const Vec2& p : gotos) c.in.gotos.push_back(make_goto(p, line++));
  c.in.off_loc = {line, 1};
  return c;
}

// The first line of every kept diagnostic ("t.cl:2:1: error: ..."), one per line.
inline std::string first_lines(const Diagnostics& d) {
  std::string out;
  for (const Diagnostic& x : d.kept()) {
    const std::string s = d.render(x);
    out += s.substr(0, s.find('\n') + 1);
  }
  return out;
}

inline PitchSpec pitch_of(double p, int starts = 1) {
  PitchSpec s;
  s.set = true;
  s.pitch = p;
  s.starts = starts;
  s.loc = {1, 1};
  return s;
}

}  // namespace clpost::testing

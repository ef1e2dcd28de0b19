// THREAD/ON parameters and pitch couplets: what is accepted, what it converts to, and the exact
// text of every error.
#include "planner/thread_words.h"

#include <gtest/gtest.h>

#include <cmath>
#include <limits>
#include <string>

#include "planner/planner_test_util.h"

namespace clpost {
namespace {

using testing::TestStatement;

// The "file:line:col: severity: message" lines of all diagnostics.
std::string messages(const Diagnostics& d) {
  std::string out;
  for (const Diagnostic& x : d.kept()) {
    const std::string r = d.render(x);
    out += r.substr(0, r.find('\n') + 1);
  }
  return out;
}

// Parses THREAD/ON words of `line` (line 1, words from arg 1) and returns the messages.
std::string thread_errors(const std::string& line, LengthUnit u = LengthUnit::kMm) {
  TestStatement st(line);
  Diagnostics d("t.cl");
  ThreadWords w;
  const bool ok = parse_thread_words(st.st, 1, u, w, d);
  EXPECT_EQ(ok, !d.has_errors()) << line;
  return messages(d);
}

std::string pitch_errors(const std::string& line, LengthUnit u = LengthUnit::kMm) {
  TestStatement st(line);
  Diagnostics d("t.cl");
  PitchSpec p;
  const size_t first = st.st.major == "PITCH" ? 0 : 1;
  const bool ok = parse_pitch_words(st.st, first, u, p, d);
  EXPECT_EQ(ok, !d.has_errors()) << line;
  return messages(d);
}

TEST(ThreadWords, ParsesEveryWordWithItsColumn) {
  TestStatement st(
      "THREAD/ON,DEPTH,2.2,CUTS,4,STEP,0.5,FINCUT,2,0.2,OPTION,3,CUTANG,150,TLANGL,55,"
      "ATANGL,10,1.2,RETURN,3,TPI,8,MULTRD,2,INCR,0.01",
      7);
  Diagnostics d("t.cl");
  ThreadWords w;
  ASSERT_TRUE(parse_thread_words(st.st, 1, LengthUnit::kMm, w, d)) << d.render_all();
  EXPECT_TRUE(w.depth.set);
  EXPECT_EQ(w.depth.value, 2.2);
  EXPECT_EQ(w.depth.loc.line, 7u);
  EXPECT_EQ(w.depth.loc.col, 11u);
  EXPECT_TRUE(w.cuts.set);
  EXPECT_EQ(w.cuts.count, 4);
  EXPECT_TRUE(w.cuts.steps.empty());
  EXPECT_EQ(w.cuts.loc.col, 21u);
  EXPECT_EQ(w.step.value, 0.5);
  EXPECT_EQ(w.step.loc.col, 28u);
  EXPECT_EQ(w.fincut.count, 2);
  EXPECT_EQ(w.fincut.dist, 0.2);
  EXPECT_EQ(w.fincut.loc.col, 37u);
  EXPECT_EQ(w.option.value, 3);
  EXPECT_EQ(w.option.loc.col, 50u);
  EXPECT_EQ(w.cutang.value, 150);
  EXPECT_EQ(w.cutang.loc.col, 59u);
  EXPECT_EQ(w.tlangl.value, 55);
  EXPECT_EQ(w.tlangl.loc.col, 70u);
  EXPECT_TRUE(w.atangl.set);
  EXPECT_EQ(w.atangl.angle, 10);
  EXPECT_EQ(w.atangl.height, 1.2);
  EXPECT_TRUE(w.ret.set);
  EXPECT_TRUE(w.ret.height_given);
  EXPECT_EQ(w.ret.height, 3);
  // TPI 8 in a mm file: 25.4 / 8 = 3.175 mm.
  EXPECT_TRUE(w.pitch.value_given);
  EXPECT_DOUBLE_EQ(w.pitch.pitch, 3.175);
  EXPECT_TRUE(w.pitch.from_tpi);
  EXPECT_EQ(w.pitch.tpi, 8);
  EXPECT_EQ(w.pitch.starts, 2);
  EXPECT_TRUE(w.pitch.starts_given);
  EXPECT_EQ(w.pitch.lead_change, 0.01);
  EXPECT_FALSE(w.chamfr.set);
}

// CHAIN (threading.md section 11) takes no value, once.
TEST(ThreadWords, Chain) {
  TestStatement st("THREAD/ON,DEPTH,1,CHAIN");
  Diagnostics d("t.cl");
  ThreadWords w;
  ASSERT_TRUE(parse_thread_words(st.st, 1, LengthUnit::kMm, w, d)) << d.render_all();
  EXPECT_TRUE(w.chain.set);
  EXPECT_EQ(w.chain.loc.col, 19u);
  EXPECT_EQ(thread_errors("THREAD/ON,CHAIN,DEPTH,1,CHAIN"),
            "t.cl:1:25: error: CHAIN is given twice (first at column 11)\n");
  EXPECT_EQ(thread_errors("THREAD/ON,CHAIN,3"),
            "t.cl:1:17: error: unexpected number 3 after CHAIN: CHAIN takes no value\n");
}

// The word list of the "unknown word" error and the words the parser knows are the same: each
// listed word alone is parsed as itself (a missing value at most), never reported as unknown.
TEST(ThreadWords, EveryListedWordIsKnown) {
  std::string_view list = kThreadWordList;
  int words = 0;
  while (!list.empty()) {
    const size_t comma = list.find(", ");
    const std::string word(list.substr(0, comma));
    list = comma == std::string_view::npos ? std::string_view() : list.substr(comma + 2);
    ++words;
    const std::string errors = thread_errors("THREAD/ON," + word);
    EXPECT_EQ(errors.find("unknown"), std::string::npos) << errors;
    if (word == "RETURN" || word == "CHAIN") {
      EXPECT_EQ(errors, "");
    } else {
      EXPECT_NE(errors.find("after " + word + ", found the end of the statement"),
                std::string::npos)
          << errors;
    }
  }
  EXPECT_EQ(words, 18);
  EXPECT_EQ(thread_errors("THREAD/ON,DEPT,1"),
            "t.cl:1:11: error: unknown thread parameter 'DEPT'; valid words: " +
                std::string(kThreadWordList) + "\n");
}

TEST(ThreadWords, CutsForms) {
  Diagnostics d("t.cl");
  {
    TestStatement st("THREAD/ON,CUTS,4,0.5");
    ThreadWords w;
    ASSERT_TRUE(parse_thread_words(st.st, 1, LengthUnit::kMm, w, d));
    EXPECT_EQ(w.cuts.count, 4);
    ASSERT_EQ(w.cuts.steps.size(), 1u);
    EXPECT_EQ(w.cuts.steps[0].count, 4);
    EXPECT_EQ(w.cuts.steps[0].step, 0.5);
  }
  {
    TestStatement st("THREAD/ON,CUTS,2,0.5,3,0.2,1,0.1");
    ThreadWords w;
    ASSERT_TRUE(parse_thread_words(st.st, 1, LengthUnit::kMm, w, d));
    // 2 + 3 + 1 = 6 passes in three couplets.
    EXPECT_EQ(w.cuts.count, 6);
    ASSERT_EQ(w.cuts.steps.size(), 3u);
    EXPECT_EQ(w.cuts.steps[1].count, 3);
    EXPECT_EQ(w.cuts.steps[1].step, 0.2);
    EXPECT_EQ(w.cuts.steps[1].loc.col, 22u);
    EXPECT_EQ(w.cuts.steps[2].step, 0.1);
  }
  EXPECT_FALSE(d.has_errors());
}

TEST(ThreadWords, OptionalValues) {
  Diagnostics d("t.cl");
  TestStatement st("THREAD/ON,CHAMFR,-2,RETURN,FINCUT,3,ATANGL,0");
  ThreadWords w;
  ASSERT_TRUE(parse_thread_words(st.st, 1, LengthUnit::kMm, w, d));
  EXPECT_EQ(w.chamfr.length, -2);
  EXPECT_FALSE(w.chamfr.angle_given);
  EXPECT_EQ(w.chamfr.angle, 45);  // default
  EXPECT_TRUE(w.ret.set);
  EXPECT_FALSE(w.ret.height_given);
  EXPECT_EQ(w.fincut.count, 3);
  EXPECT_EQ(w.fincut.dist, 0);  // default allowance
  EXPECT_TRUE(w.atangl.set);
  EXPECT_EQ(w.atangl.height, 0);  // 0: the default height, decided by the planner
}

TEST(ThreadWords, ChamfrZeroTurnsOffWhateverTheAngle) {
  Diagnostics d("t.cl");
  TestStatement st("THREAD/ON,CHAMFR,0,0");
  ThreadWords w;
  ASSERT_TRUE(parse_thread_words(st.st, 1, LengthUnit::kMm, w, d)) << d.render_all();
  EXPECT_TRUE(w.chamfr.set);
  EXPECT_EQ(w.chamfr.length, 0);
}

TEST(ThreadWords, ProEFormAfterThreadTurn) {
  // OP/THREAD,TURN,...: the words start at argument 2.
  Diagnostics d("t.cl");
  TestStatement st("OP/THREAD,TURN,DEPTH,0.061343,TPI,10,CUTS,3,FINCUT,3,CUTANG,180");
  ThreadWords w;
  ASSERT_TRUE(parse_thread_words(st.st, 2, LengthUnit::kInch, w, d)) << d.render_all();
  EXPECT_EQ(w.depth.value, 0.061343);
  EXPECT_DOUBLE_EQ(w.pitch.pitch, 0.1);  // 1 / 10 inch
  EXPECT_EQ(w.cuts.count, 3);
  EXPECT_EQ(w.fincut.count, 3);
  EXPECT_EQ(w.cutang.value, 180);
}

struct PitchCase {
  const char* line;
  LengthUnit units;
  double pitch;
  bool from_tpi;
};

TEST(PitchWords, UnitsConvertToClUnits) {
  const PitchCase cases[] = {
      // THREAD/ON couplets (keyword, value).
      {"THREAD/ON,TPI,10", LengthUnit::kInch, 0.1, true},      // 1/10 in
      {"THREAD/ON,TPI,10", LengthUnit::kMm, 2.54, true},       // 25.4/10 mm
      {"THREAD/ON,IPR,0.1", LengthUnit::kInch, 0.1, false},    // 0.1 in
      {"THREAD/ON,IPR,0.1", LengthUnit::kMm, 2.54, false},     // 0.1 x 25.4 mm
      {"THREAD/ON,MMPR,2.54", LengthUnit::kInch, 0.1, false},  // 2.54 / 25.4 in
      {"THREAD/ON,MMPR,1.5", LengthUnit::kMm, 1.5, false},
      {"THREAD/ON,PERREV,0.1", LengthUnit::kInch, 0.1, false},
      {"THREAD/ON,PERREV,1.5", LengthUnit::kMm, 1.5, false},
  };
  for (const PitchCase& c : cases) {
    TestStatement st(c.line);
    Diagnostics d("t.cl");
    ThreadWords w;
    ASSERT_TRUE(parse_thread_words(st.st, 1, c.units, w, d)) << c.line;
    EXPECT_NEAR(w.pitch.pitch, c.pitch, 1e-12) << c.line;
    EXPECT_EQ(w.pitch.from_tpi, c.from_tpi) << c.line;
  }
}

TEST(PitchWords, PitchStatementForms) {
  const PitchCase cases[] = {
      {"PITCH/10", LengthUnit::kMm, 0.1, false},        // 10 threads per mm
      {"PITCH/10", LengthUnit::kInch, 0.1, true},       // 10 threads per inch
      {"PITCH/10,TPI", LengthUnit::kMm, 2.54, true},    // 25.4 / 10
      {"PITCH/0.1,IPR", LengthUnit::kMm, 2.54, false},  // 0.1 x 25.4
      {"PITCH/1.5,MMPR", LengthUnit::kMm, 1.5, false},
      {"PITCH/1.5,PERREV", LengthUnit::kMm, 1.5, false},
      {"COUPLE/ON,TPI,4", LengthUnit::kInch, 0.25, true},
      {"COUPLE/ON,0.125,IPR", LengthUnit::kInch, 0.125, false},
  };
  for (const PitchCase& c : cases) {
    TestStatement st(c.line);
    Diagnostics d("t.cl");
    PitchSpec p;
    const size_t first = st.st.major == "PITCH" ? 0 : 1;
    ASSERT_TRUE(parse_pitch_words(st.st, first, c.units, p, d)) << c.line << d.render_all();
    EXPECT_TRUE(p.set);
    EXPECT_NEAR(p.pitch, c.pitch, 1e-12) << c.line;
    EXPECT_EQ(p.from_tpi, c.from_tpi) << c.line;
    EXPECT_EQ(p.starts, 1);
    EXPECT_EQ(p.loc.line, 1u);
  }
}

TEST(PitchWords, MultiStartAndVariableLead) {
  Diagnostics d("t.cl");
  {
    TestStatement st("PITCH/1.5,MMPR,MULTRD,3,DECR,0.025");
    PitchSpec p;
    ASSERT_TRUE(parse_pitch_words(st.st, 0, LengthUnit::kMm, p, d));
    EXPECT_EQ(p.pitch, 1.5);
    EXPECT_EQ(p.starts, 3);
    EXPECT_EQ(p.starts_loc.col, 16u);
    EXPECT_EQ(p.lead_change, -0.025);
    EXPECT_EQ(p.lead_change_loc.col, 25u);
  }
  {
    TestStatement st("PITCH/0.1,IPR,INCR,0.01");
    PitchSpec p;
    ASSERT_TRUE(parse_pitch_words(st.st, 0, LengthUnit::kInch, p, d));
    EXPECT_EQ(p.lead_change, 0.01);
  }
  EXPECT_FALSE(d.has_errors());
}

TEST(PitchWords, CoupletsOverrideOnlyWhatTheyGive) {
  Diagnostics d("t.cl");
  PitchSpec modal = testing::pitch_of(1.5, 2);
  {
    TestStatement st("COUPLE/ON,MMPR,2", 9);
    PitchSpec p = modal;
    ASSERT_TRUE(parse_pitch_words(st.st, 1, LengthUnit::kMm, p, d));
    EXPECT_EQ(p.pitch, 2);
    EXPECT_EQ(p.starts, 2);  // kept from the modal PITCH/
    EXPECT_EQ(p.loc.line, 9u);
  }
  {
    TestStatement st("COUPLE/ON,MULTRD,3");
    PitchSpec p = modal;
    ASSERT_TRUE(parse_pitch_words(st.st, 1, LengthUnit::kMm, p, d));
    EXPECT_EQ(p.pitch, 1.5);  // kept
    EXPECT_EQ(p.starts, 3);
  }
  {
    TestStatement st("COUPLE/ON");
    PitchSpec p = modal;
    ASSERT_TRUE(parse_pitch_words(st.st, 1, LengthUnit::kMm, p, d));
    EXPECT_EQ(p.pitch, 1.5);
    EXPECT_EQ(p.starts, 2);
  }
  EXPECT_FALSE(d.has_errors());
}

TEST(PitchWords, ErrorLeavesThePitchUnchanged) {
  TestStatement st("COUPLE/ON,MMPR,2,MULTRD,0");
  Diagnostics d("t.cl");
  PitchSpec p = testing::pitch_of(1.5);
  EXPECT_FALSE(parse_pitch_words(st.st, 1, LengthUnit::kMm, p, d));
  EXPECT_EQ(p.pitch, 1.5);
}

// Each bad THREAD/ON word with its exact message (a table, so that a new word is one row).
struct ErrorCase {
  const char* line;
  const char* expected;
};
const ErrorCase kErrorCases[] = {
    {"THREAD/ON,3",
     "t.cl:1:11: error: expected a thread parameter word, found number 3; valid words: DEPTH, "
     "CUTS, STEP, FINCUT, OPTION, CUTANG, TLANGL, ATANGL, CHAMFR, RETURN, CHAIN, TPI, IPR, MMPR, "
     "PERREV, MULTRD, INCR, DECR\n"},
    {"THREAD/ON,DEPTH,1,PITCH,2",
     "t.cl:1:19: error: unknown thread parameter 'PITCH'; valid words: DEPTH, CUTS, STEP, "
     "FINCUT, OPTION, CUTANG, TLANGL, ATANGL, CHAMFR, RETURN, CHAIN, TPI, IPR, MMPR, PERREV, "
     "MULTRD, "
     "INCR, DECR\n"},
    {"THREAD/ON,DEPTH,CUTS,3",
     "t.cl:1:11: error: expected the thread depth after DEPTH, found 'CUTS'\n"},
    {"THREAD/ON,DEPTH",
     "t.cl:1:11: error: expected the thread depth after DEPTH, found the end of the "
     "statement\n"},
    {"THREAD/ON,DEPTH,1,2",
     "t.cl:1:19: error: unexpected number 2 after DEPTH: DEPTH takes one value (DEPTH,d)\n"},
    {"THREAD/ON,DEPTH,0", "t.cl:1:11: error: DEPTH must be positive; got 0\n"},
    {"THREAD/ON,DEPTH,-1.5", "t.cl:1:11: error: DEPTH must be positive; got -1.5\n"},
    {"THREAD/ON,DEPTH,1,DEPTH,2", "t.cl:1:19: error: DEPTH is given twice (first at column 11)\n"},
    {"THREAD/ON,CUTS",
     "t.cl:1:11: error: expected the number of passes after CUTS, found the end of the "
     "statement\n"},
    {"THREAD/ON,CUTS,2,0.5,3",
     "t.cl:1:11: error: CUTS takes a count, a count and a step, or count,step pairs; got 3 "
     "numbers (an odd count of more than 2)\n"},
    {"THREAD/ON,CUTS,2.5",
     "t.cl:1:16: error: CUTS count must be a positive whole number; got 2.5\n"},
    {"THREAD/ON,CUTS,0", "t.cl:1:16: error: CUTS count must be a positive whole number; got 0\n"},
    {"THREAD/ON,CUTS,201",
     "t.cl:1:16: error: CUTS count 201 is more than the 200 passes a thread may have\n"},
    {"THREAD/ON,CUTS,4,0", "t.cl:1:18: error: CUTS step must be positive; got 0\n"},
    {"THREAD/ON,CUTS,2,0.5,3,-0.1", "t.cl:1:24: error: CUTS step must be positive; got -0.1\n"},
    {"THREAD/ON,STEP,0", "t.cl:1:11: error: STEP must be positive; got 0\n"},
    {"THREAD/ON,STEP,OPTION,1",
     "t.cl:1:11: error: expected the first infeed step after STEP, found 'OPTION'\n"},
    {"THREAD/ON,FINCUT",
     "t.cl:1:11: error: expected the number of finish passes after FINCUT, found the end of "
     "the statement\n"},
    {"THREAD/ON,FINCUT,-1",
     "t.cl:1:11: error: FINCUT count must be a whole number, 0 or more; got -1\n"},
    {"THREAD/ON,FINCUT,1.5",
     "t.cl:1:11: error: FINCUT count must be a whole number, 0 or more; got 1.5\n"},
    {"THREAD/ON,FINCUT,201",
     "t.cl:1:11: error: FINCUT count 201 is more than the 200 passes a thread may have\n"},
    {"THREAD/ON,FINCUT,1,-0.1", "t.cl:1:11: error: FINCUT allowance must be 0 or more; got -0.1\n"},
    {"THREAD/ON,FINCUT,1,0.1,2",
     "t.cl:1:24: error: unexpected number 2 after FINCUT: FINCUT takes "
     "FINCUT,count[,allowance]\n"},
    {"THREAD/ON,OPTION,5", "t.cl:1:11: error: OPTION must be 0, 1, 2, 3 or 4; got 5\n"},
    {"THREAD/ON,OPTION,1.5", "t.cl:1:11: error: OPTION must be 0, 1, 2, 3 or 4; got 1.5\n"},
    {"THREAD/ON,CUTANG,400",
     "t.cl:1:11: error: CUTANG must be between -360 and 360 degrees; got 400\n"},
    {"THREAD/ON,CUTANG,-360.5",
     "t.cl:1:11: error: CUTANG must be between -360 and 360 degrees; got -360.5\n"},
    {"THREAD/ON,TLANGL,0",
     "t.cl:1:11: error: TLANGL must be more than 0 and less than 180 degrees; got 0\n"},
    {"THREAD/ON,TLANGL,180",
     "t.cl:1:11: error: TLANGL must be more than 0 and less than 180 degrees; got 180\n"},
    {"THREAD/ON,ATANGL,85",
     "t.cl:1:11: error: ATANGL must be between -80 and 80 degrees; got 85\n"},
    {"THREAD/ON,ATANGL,-81",
     "t.cl:1:11: error: ATANGL must be between -80 and 80 degrees; got -81\n"},
    {"THREAD/ON,ATANGL,10,-1",
     "t.cl:1:11: error: ATANGL height must be 0 or more (0: the default pitch/(2 tan 30)); got "
     "-1\n"},
    {"THREAD/ON,CHAMFR,2,5",
     "t.cl:1:11: error: CHAMFR angle must be between 10 and 80 degrees; got 5\n"},
    {"THREAD/ON,CHAMFR,-2,81",
     "t.cl:1:11: error: CHAMFR angle must be between 10 and 80 degrees; got 81\n"},
    {"THREAD/ON,CHAMFR",
     "t.cl:1:11: error: expected the chamfer length after CHAMFR, found the end of the "
     "statement\n"},
    {"THREAD/ON,RETURN,0", "t.cl:1:11: error: RETURN height must be positive; got 0\n"},
    {"THREAD/ON,RETURN,2,3",
     "t.cl:1:20: error: unexpected number 3 after RETURN: RETURN takes RETURN[,height]\n"},
    {"THREAD/ON,TPI,0", "t.cl:1:11: error: TPI must be positive; got 0\n"},
    {"THREAD/ON,MMPR,-1", "t.cl:1:11: error: MMPR must be positive; got -1\n"},
    {"THREAD/ON,IPR",
     "t.cl:1:11: error: expected the pitch in inches after IPR, found the end of the "
     "statement\n"},
    {"THREAD/ON,PERREV,DEPTH,1",
     "t.cl:1:11: error: expected the pitch in CL units after PERREV, found 'DEPTH'\n"},
    {"THREAD/ON,TPI,10,MMPR,1.5",
     "t.cl:1:18: error: MMPR: the pitch is already given by TPI at column 11\n"},
    {"THREAD/ON,MULTRD,0",
     "t.cl:1:11: error: MULTRD must be a positive whole number of starts; got 0\n"},
    {"THREAD/ON,MULTRD,2.5",
     "t.cl:1:11: error: MULTRD must be a positive whole number of starts; got 2.5\n"},
    {"THREAD/ON,MULTRD,101",
     "t.cl:1:11: error: MULTRD 101 is more than the 100 starts a thread may have\n"},
    {"THREAD/ON,MULTRD,2,MULTRD,3",
     "t.cl:1:20: error: MULTRD is given twice (first at column 11)\n"},
    {"THREAD/ON,INCR,-0.1",
     "t.cl:1:11: error: INCR takes the size of the lead change (0 or more); got -0.1 (use DECR "
     "for a shrinking lead)\n"},
    {"THREAD/ON,DECR,-0.1",
     "t.cl:1:11: error: DECR takes the size of the lead change (0 or more); got -0.1 (use INCR "
     "for a growing lead)\n"},
    {"THREAD/ON,INCR,0.1,DECR,0.1",
     "t.cl:1:20: error: DECR: the lead change is already given at column 11\n"},
    {"THREAD/ON,TPI,8,2",
     "t.cl:1:17: error: unexpected number 2 after TPI: TPI takes one value (TPI,v)\n"},
};

TEST(ThreadWordsErrors, ExactMessages) {
  for (const ErrorCase& c : kErrorCases) EXPECT_EQ(thread_errors(c.line), c.expected) << c.line;
}

TEST(ThreadWordsErrors, EveryErrorIsReported) {
  // Two independent mistakes: both are reported, each at its own word.
  EXPECT_EQ(
      thread_errors("THREAD/ON,DEPTH,0,FOO,OPTION,9"),
      "t.cl:1:11: error: DEPTH must be positive; got 0\n"
      "t.cl:1:19: error: unknown thread parameter 'FOO'; valid words: DEPTH, CUTS, STEP, "
      "FINCUT, OPTION, CUTANG, TLANGL, ATANGL, CHAMFR, RETURN, CHAIN, TPI, IPR, MMPR, PERREV, "
      "MULTRD, INCR, DECR\n"
      "t.cl:1:23: error: OPTION must be 0, 1, 2, 3 or 4; got 9\n");
}

TEST(ThreadWordsErrors, NonFiniteNumber) {
  TestStatement st("THREAD/ON,DEPTH,1");
  st.st.args[2].number = std::numeric_limits<double>::infinity();
  Diagnostics d("t.cl");
  ThreadWords w;
  EXPECT_FALSE(parse_thread_words(st.st, 1, LengthUnit::kMm, w, d));
  EXPECT_EQ(messages(d), "t.cl:1:11: error: DEPTH must be positive; got inf\n");
  TestStatement ch("THREAD/ON,CHAMFR,1");
  ch.st.args[2].number = -std::numeric_limits<double>::infinity();
  Diagnostics d2("t.cl");
  EXPECT_FALSE(parse_thread_words(ch.st, 1, LengthUnit::kMm, w, d2));
  EXPECT_EQ(messages(d2), "t.cl:1:11: error: CHAMFR length must be a finite number; got -inf\n");
}

TEST(ThreadWordsErrors, RepeatOnAContinuationLineNamesTheLine) {
  // A word repeated on another physical line of the same statement says which line.
  TestStatement st("THREAD/ON,DEPTH,1,DEPTH,2", 4);
  st.st.args[3].loc = {5, 2};  // as if the second DEPTH were on the continuation line
  Diagnostics d("t.cl");
  ThreadWords w;
  EXPECT_FALSE(parse_thread_words(st.st, 1, LengthUnit::kMm, w, d));
  EXPECT_EQ(messages(d), "t.cl:5:2: error: DEPTH is given twice (first at line 4, column 11)\n");
}

TEST(ThreadWordsErrors, TheCaretPointsAtTheWord) {
  TestStatement st("THREAD/ON, DEPTH, 2, OPTION, 7");
  Diagnostics d("t.cl");
  ThreadWords w;
  EXPECT_FALSE(parse_thread_words(st.st, 1, LengthUnit::kMm, w, d));
  EXPECT_EQ(d.render_all(),
            "t.cl:1:22: error: OPTION must be 0, 1, 2, 3 or 4; got 7\n"
            "  THREAD/ON, DEPTH, 2, OPTION, 7\n"
            "                       ^\n");
}

TEST(PitchWordsErrors, ExactMessages) {
  struct Case {
    const char* line;
    const char* expected;
  };
  const Case cases[] = {
      {"PITCH/",
       "t.cl:1:1: error: PITCH needs a value: "
       "PITCH/v[,TPI|IPR|MMPR|PERREV][,MULTRD,n][,INCR|DECR,dv]\n"},
      {"PITCH/MULTRD,2",
       "t.cl:1:1: error: PITCH needs a value: "
       "PITCH/v[,TPI|IPR|MMPR|PERREV][,MULTRD,n][,INCR|DECR,dv]\n"},
      {"PITCH/0", "t.cl:1:7: error: the pitch value must be positive; got 0\n"},
      {"PITCH/1.5,FOO",
       "t.cl:1:11: error: unknown pitch word 'FOO'; valid words: TPI, IPR, MMPR, PERREV, MULTRD, "
       "INCR, DECR\n"},
      {"PITCH/1.5,2",
       "t.cl:1:11: error: unexpected number 2: the pitch is already given by the value 1.5 at "
       "column 7\n"},
      {"PITCH/10,TPI,12",
       "t.cl:1:10: error: TPI: the pitch is already given by the value 10 at column 7\n"},
      {"COUPLE/ON,TPI",
       "t.cl:1:11: error: expected the threads per inch after TPI, found the end of the "
       "statement\n"},
      {"COUPLE/ON,MULTRD,3,TPI,10,IPR,0.1",
       "t.cl:1:27: error: IPR: the pitch is already given by TPI at column 20\n"},
      {"COUPLE/ON,DECR,-1",
       "t.cl:1:11: error: DECR takes the size of the lead change (0 or more); got -1 (use INCR "
       "for a growing lead)\n"},
  };
  for (const Case& c : cases) EXPECT_EQ(pitch_errors(c.line), c.expected) << c.line;
}

}  // namespace
}  // namespace clpost

#include "reader/cl_reader.h"

#include <gtest/gtest.h>

#include <cstdio>
#include <string>
#include <vector>

#include "reader/cl_reader_test_util.h"

namespace clpost {
namespace {

using namespace reader_test;

// ---- statements -------------------------------------------------------------------------------

TEST(ClReader, RecordWithNumbers) {
  Result r = read("GOTO/1.0,2.5,-3\n");
  ASSERT_EQ(r.st.size(), 1u);
  const Owned& s = r.st[0];
  EXPECT_EQ(s.form, Form::kRecord);
  EXPECT_EQ(s.major, "GOTO");
  EXPECT_EQ(s.loc.line, 1u);
  EXPECT_EQ(s.loc.col, 1u);
  ASSERT_EQ(s.args.size(), 3u);
  EXPECT_EQ(s.args[0].kind, Kind::kNumber);
  EXPECT_EQ(s.args[0].text, "1.0");
  EXPECT_EQ(s.args[0].number, 1.0);
  EXPECT_EQ(s.args[0].loc.col, 6u);
  EXPECT_EQ(s.args[1].number, 2.5);
  EXPECT_EQ(s.args[1].loc.col, 10u);
  EXPECT_EQ(s.args[2].text, "-3");
  EXPECT_EQ(s.args[2].number, -3.0);
  EXPECT_EQ(s.args[2].loc.line, 1u);
  EXPECT_EQ(s.args[2].loc.col, 14u);
  EXPECT_EQ(s.first_line, 1u);
  EXPECT_EQ(s.lines, std::vector<std::string>{"GOTO/1.0,2.5,-3"});
  EXPECT_EQ(r.diags, "");
}

TEST(ClReader, RecordWithoutArguments) {
  Result r = read("RAPID/\nRAPID /  \n");
  EXPECT_EQ(dump(r), "1:1 R RAPID/ [1+1]\n2:1 R RAPID/ [2+1]\n");
  EXPECT_EQ(r.diags, "");
}

TEST(ClReader, BareWords) {
  Result r = read("RAPID\nEND\nFINI\nSTOP\nOPSTOP\nGOHOME\nEND-OF-PATH\nRAPID \n  fini\t\n");
  EXPECT_EQ(dump(r),
            "1:1 B RAPID [1+1]\n"
            "2:1 B END [2+1]\n"
            "3:1 B FINI [3+1]\n"
            "4:1 B STOP [4+1]\n"
            "5:1 B OPSTOP [5+1]\n"
            "6:1 B GOHOME [6+1]\n"
            "7:1 B END-OF-PATH [7+1]\n"
            "8:1 B RAPID [8+1]\n"
            "9:3 B FINI [9+1]\n");
  EXPECT_EQ(r.diags, "");
}

TEST(ClReader, TextStatements) {
  Result r = read(
      "PARTNO / THREAD-TURN\n"
      "PPRINT Hello, World $$ not a comment $$\n"
      "insert/[HOLDER=C40-M06EM2] 6mm CRB  \n"
      "PPRINT\n"
      "  PartNo/  Part 7 /a\t\n"
      "GOTO/1\n");
  EXPECT_EQ(dump(r),
            "1:1 T PARTNO 'THREAD-TURN' [1+1]\n"
            "2:1 T PPRINT 'Hello, World $$ not a comment $$' [2+1]\n"
            "3:1 T INSERT '[HOLDER=C40-M06EM2] 6mm CRB' [3+1]\n"
            "4:1 T PPRINT '' [4+1]\n"
            "5:3 T PARTNO 'Part 7 /a' [5+1]\n"
            "6:1 R GOTO/N:1=1@6:6 [6+1]\n");
  ASSERT_EQ(r.st.size(), 6u);
  EXPECT_TRUE(r.st[1].args.empty());
  EXPECT_EQ(r.diags, "");
}

TEST(ClReader, TextWordNeedsWordEnd) {
  // PPRINTX is not PPRINT.
  Result r = read("PPRINTX/1\nINSERT_TOOL\n");
  EXPECT_EQ(dump(r), "1:1 R PPRINTX/N:1=1@1:9 [1+1]\n2:1 B INSERT_TOOL [2+1]\n");
}

TEST(ClReader, MajorWords) {
  Result r = read(
      "TOOL PATH/DRILLING,TOOL,COUNTERSINKING_TOOL\n"
      "OP  / THREAD , TURN\n"
      "tool   path/x\n"
      "TOOL\tPATH/y\n"
      "GoTo/1\n");
  EXPECT_EQ(dump(r),
            "1:1 R TOOL PATH/W:DRILLING@1:11,W:TOOL@1:20,W:COUNTERSINKING_TOOL@1:25 [1+1]\n"
            "2:1 R OP/W:THREAD@2:7,W:TURN@2:16 [2+1]\n"
            "3:1 R TOOL PATH/W:X@3:13 [3+1]\n"
            "4:1 R TOOL PATH/W:Y@4:11 [4+1]\n"
            "5:1 R GOTO/N:1=1@5:6 [5+1]\n");
  EXPECT_EQ(r.diags, "");
}

TEST(ClReader, BlanksAndTabsAroundSeparators) {
  Result r = read("GOTO  / 1.0, 0.0, 2.0\nGOTO\t/\t1,\t2 ,3\t\n");
  EXPECT_EQ(dump(r),
            "1:1 R GOTO/N:1.0=1@1:9,N:0.0=0@1:14,N:2.0=2@1:19 [1+1]\n"
            "2:1 R GOTO/N:1=1@2:8,N:2=2@2:11,N:3=3@2:14 [2+1]\n");
}

TEST(ClReader, Words) {
  Result r = read(
      "SPINDL/RPM, 400, clw\n"
      "TOOL PATH/10_SVERL_63_N2,TOOL,Mill_0.120Rad\n"
      "TOOL PATH/VARIABLE_CONTOUR,TOOL,BPR-SNR-323S32\n"
      "X/nan,inf,Inf\n");
  EXPECT_EQ(dump(r),
            "1:1 R SPINDL/W:RPM@1:8,N:400=400@1:13,W:CLW@1:18 [1+1]\n"
            "2:1 R TOOL PATH/W:10_SVERL_63_N2@2:11,W:TOOL@2:26,W:MILL_0.120RAD@2:31 [2+1]\n"
            "3:1 R TOOL PATH/W:VARIABLE_CONTOUR@3:11,W:TOOL@3:28,W:BPR-SNR-323S32@3:33 [3+1]\n"
            "4:1 R X/W:NAN@4:3,W:INF@4:7,W:INF@4:11 [4+1]\n");
  EXPECT_EQ(r.diags, "");
}

TEST(ClReader, Numbers) {
  Result r = read("N/1.,.5,-0.5,+2,1E3,1.5e-3,-.5\n");
  ASSERT_EQ(r.st.size(), 1u);
  const std::vector<OwnedArg>& a = r.st[0].args;
  ASSERT_EQ(a.size(), 7u);
  const std::vector<std::string> texts = {"1.", ".5", "-0.5", "+2", "1E3", "1.5e-3", "-.5"};
  const std::vector<double> values = {1.0, 0.5, -0.5, 2.0, 1000.0, 0.0015, -0.5};
  const std::vector<uint32_t> cols = {3, 6, 9, 14, 17, 21, 28};
  for (size_t i = 0; i < a.size(); ++i) {
    EXPECT_EQ(a[i].kind, Kind::kNumber) << i;
    EXPECT_EQ(a[i].text, texts[i]) << i;
    EXPECT_EQ(a[i].number, values[i]) << i;
    EXPECT_EQ(a[i].loc.col, cols[i]) << i;
  }
  EXPECT_EQ(r.diags, "");
}

TEST(ClReader, AnyLetterCase) {
  Result r = read("goto/1,clw\nrapid\npprint Mixed Case\nend-of-path\n");
  EXPECT_EQ(dump(r),
            "1:1 R GOTO/N:1=1@1:6,W:CLW@1:8 [1+1]\n"
            "2:1 B RAPID [2+1]\n"
            "3:1 T PPRINT 'Mixed Case' [3+1]\n"
            "4:1 B END-OF-PATH [4+1]\n");
}

// ---- problems: delivered with the statement, not reported by the reader ---------------------

// The problem of one bad line, which is still delivered (with its raw source and text and no
// arguments), followed by a good one: "line:col: message".
std::string problem_for(const std::string& line) {
  Result r = read(line + "\nFINI\n");
  EXPECT_EQ(r.diags, "") << line;
  EXPECT_EQ(r.st.size(), 2u) << line;
  if (r.st.size() != 2) return {};
  const Owned& s = r.st[0];
  EXPECT_TRUE(s.args.empty()) << line;
  EXPECT_EQ(s.source, line.substr(line.find_first_not_of(' '))) << line;
  Result next;
  next.st.push_back(r.st[1]);
  EXPECT_EQ(dump(next), "2:1 B FINI [2+1]\n") << line;
  return std::to_string(s.problem_loc.line) + ":" + std::to_string(s.problem_loc.col) + ": " +
         s.problem;
}

TEST(ClReader, BadNumbers) {
  EXPECT_EQ(problem_for("GOTO/1.2.3,0"), "1:6: invalid number '1.2.3'");
  EXPECT_EQ(problem_for("GOTO/0, --1"), "1:9: invalid number '--1'");
  EXPECT_EQ(problem_for("GOTO/1e"), "1:6: invalid number '1e'");
  EXPECT_EQ(problem_for("GOTO/1,1e400"), "1:8: number '1e400' is out of range");
  EXPECT_EQ(problem_for("GOTO/-inf"), "1:6: invalid number '-inf'");
}

TEST(ClReader, SeparatorProblems) {
  EXPECT_EQ(problem_for("GOTO/1 2"), "1:8: missing ',' before '2'");
  EXPECT_EQ(problem_for("GOTO/1/2"), "1:7: unexpected '/' in arguments");
  EXPECT_EQ(problem_for("GOTO//1"), "1:6: unexpected '/' in arguments");
  EXPECT_EQ(problem_for("GOTO/1),2"), "1:7: unexpected ')' without a '('");
}

TEST(ClReader, MajorWordProblems) {
  EXPECT_EQ(problem_for("GO#TO/1"), "1:3: invalid character '#' in major word");
  EXPECT_EQ(problem_for("GOTO 1,2"), "1:6: expected '/' after GOTO, found '1'");
  EXPECT_EQ(problem_for("d1=21.5"),
            "1:3: 'D1=' defines an APT part-program symbol: not CL data (post the CL file the "
            "APT processor wrote)");
}

TEST(ClReader, NoMajorWordIsAReaderError) {
  auto errors_for = [](const std::string& line) {
    Result r = read(line + "\nFINI\n");
    EXPECT_EQ(r.errors, 1u) << line;
    EXPECT_EQ(dump(r), "2:1 B FINI [2+1]\n") << line;
    return r.diags;
  };
  EXPECT_EQ(errors_for("  1.0, 2.0"),
            "t.cl:1:3: error: expected a major word, found '1.0'\n"
            "    1.0, 2.0\n"
            "    ^\n");
  EXPECT_EQ(errors_for("/1"),
            "t.cl:1:1: error: expected a major word, found '/'\n"
            "  /1\n"
            "  ^\n");
}

TEST(ClReader, WordProblems) {
  EXPECT_EQ(problem_for("LOAD/TO#OL,1"), "1:8: invalid character '#' in word 'TO#OL'");
  EXPECT_EQ(problem_for("GOTO/1,$2"), "1:8: unexpected character '$'");
  EXPECT_EQ(problem_for("GOTO/1,\xC3\xA9"), "1:8: unexpected character '\\xC3'");
  EXPECT_EQ(problem_for("NOTE/'open"), "1:6: missing the closing ' of this text");
}

// Free text where a post-processor word's arguments should be: delivered whole, with the first
// problem (the interpreter writes an unknown word as a comment, and refuses a known one).
TEST(ClReader, FreeTextArgumentsAreDeliveredRaw) {
  Result r = read(
      "PART_OPE/Phase d'usinage.1\n"
      "OP_NAME/FIN RAYON - G2\n"
      "OPDATA/ACCURACY,    0.001000,TYPE,Finition de profil en tournage,$\n"
      "MMPR,FEED_MACH,    0.400000\n"
      "MACHINE/Tsugami BW128\n");
  EXPECT_EQ(dump(r),
            "1:1 R PART_OPE/ !1:16 missing ',' before 'd'usinage.1' [1+1]\n"
            "2:1 R OP_NAME/ !2:13 missing ',' before 'RAYON' [2+1]\n"
            "3:1 R OPDATA/ !3:44 missing ',' before 'de' [3+2]\n"
            "5:1 R MACHINE/ !5:17 missing ',' before 'BW128' [5+1]\n");
  ASSERT_EQ(r.st.size(), 4u);
  EXPECT_EQ(r.st[0].text, "Phase d'usinage.1");
  EXPECT_EQ(r.st[1].text, "FIN RAYON - G2");
  EXPECT_EQ(
      r.st[2].text,
      "ACCURACY,    0.001000,TYPE,Finition de profil en tournage,MMPR,FEED_MACH,    0.400000");
  EXPECT_EQ(r.st[2].source,
            "OPDATA/ACCURACY,    0.001000,TYPE,Finition de profil en tournage,MMPR,FEED_MACH,    "
            "0.400000");
  EXPECT_EQ(r.st[3].source, "MACHINE/Tsugami BW128");
  EXPECT_EQ(r.diags, "");
}

// ---- continuations and comments ---------------------------------------------------------------

TEST(ClReader, Continuation) {
  Result r = read("GOTO / 1.0, $\n  2.0,$\n3.0\nFINI\n");
  EXPECT_EQ(dump(r),
            "1:1 R GOTO/N:1.0=1@1:8,N:2.0=2@2:3,N:3.0=3@3:1 [1+3]\n"
            "4:1 B FINI [4+1]\n");
  ASSERT_EQ(r.st.size(), 2u);
  EXPECT_EQ(r.st[0].lines, (std::vector<std::string>{"GOTO / 1.0, $", "  2.0,$", "3.0"}));
  EXPECT_EQ(r.diags, "");
}

TEST(ClReader, ContinuationProE) {
  Result r = read(
      "OP  / THREAD , TURN, DEPTH, 0.061343, TPI, 10.000000, CUTS, 3, FINCUT, 3,$\n"
      " CUTANG, 180.000000\n");
  ASSERT_EQ(r.st.size(), 1u);
  const Owned& s = r.st[0];
  EXPECT_EQ(s.major, "OP");
  ASSERT_EQ(s.args.size(), 12u);
  EXPECT_EQ(s.args[9].text, "3");
  EXPECT_EQ(s.args[9].loc.line, 1u);
  EXPECT_EQ(s.args[9].loc.col, 72u);
  EXPECT_EQ(s.args[10].text, "CUTANG");
  EXPECT_EQ(s.args[10].loc.line, 2u);
  EXPECT_EQ(s.args[10].loc.col, 2u);
  EXPECT_EQ(s.args[11].number, 180.0);
  EXPECT_EQ(s.args[11].loc.col, 10u);
}

TEST(ClReader, ContinuationWithTrailingComment) {
  Result r = read("GOTO/1,$ $$ more to come\n  2 $$ done $\nFINI\n");
  EXPECT_EQ(dump(r), "1:1 R GOTO/N:1=1@1:6,N:2=2@2:3 [1+2]\n3:1 B FINI [3+1]\n");
}

TEST(ClReader, ProblemOnContinuationLineIsAtThatLine) {
  Result r = read("GOTO/1,$\n  2..5\nFINI\n");
  EXPECT_EQ(dump(r), "1:1 R GOTO/ !2:3 invalid number '2..5' [1+2]\n3:1 B FINI [3+1]\n");
  EXPECT_EQ(r.diags, "");
}

TEST(ClReader, ContinuationLineOnlyDollar) {
  Result r = read("$\n\nGOTO/1,$\n$\n2\n");
  EXPECT_EQ(dump(r), "3:1 R GOTO/N:1=1@3:6,N:2=2@5:1 [3+3]\n");
  EXPECT_EQ(r.diags, "");
}

TEST(ClReader, Comments) {
  Result r = read(
      "$$ header comment\n"
      "GOTO/1 $$ trailing\n"
      "  $$ indented comment\n"
      "$$-> CSYS / 1.0, 0.0, $\n"
      "            0.0, 1.0, $\n"
      "            0.0, 0.0\n"
      "$$$$$$$$$$$$\n"
      "$$-> END / \n"
      "LOADTL / 4,  OSETNO,  4 $$-> THREAD TOOL\n"
      "FINI\n");
  EXPECT_EQ(dump(r),
            "2:1 R GOTO/N:1=1@2:6 [2+1]\n"
            "9:1 R LOADTL/N:4=4@9:10,W:OSETNO@9:14,N:4=4@9:23 [9+1]\n"
            "10:1 B FINI [10+1]\n");
  EXPECT_EQ(r.diags, "");
}

TEST(ClReader, CommentEndingInDoubleDollarDoesNotContinue) {
  Result r = read("$$ a $$\nGOTO/1\n");
  EXPECT_EQ(dump(r), "2:1 R GOTO/N:1=1@2:6 [2+1]\n");
}

// ---- line ends, BOM, blank lines --------------------------------------------------------------

TEST(ClReader, LineEnds) {
  Result r = read("GOTO/1\r\nGOTO/2\rGOTO/3\nGOTO/4,$\r\n5\rGOTO/6");
  EXPECT_EQ(dump(r),
            "1:1 R GOTO/N:1=1@1:6 [1+1]\n"
            "2:1 R GOTO/N:2=2@2:6 [2+1]\n"
            "3:1 R GOTO/N:3=3@3:6 [3+1]\n"
            "4:1 R GOTO/N:4=4@4:6,N:5=5@5:1 [4+2]\n"
            "6:1 R GOTO/N:6=6@6:6 [6+1]\n");
  EXPECT_EQ(r.diags, "");
  EXPECT_EQ(r.line, 6u);
}

TEST(ClReader, BlankLinesAndBom) {
  Result r = read("\xEF\xBB\xBF\n\n  \t\ngoto/1\n\n\nFINI\n\n");
  EXPECT_EQ(dump(r), "4:1 R GOTO/N:1=1@4:6 [4+1]\n7:1 B FINI [7+1]\n");
  Result bom = read("\xEF\xBB\xBFGOTO/1,x");
  EXPECT_EQ(dump(bom), "1:1 R GOTO/N:1=1@1:6,W:X@1:8 [1+1]\n");
  EXPECT_EQ(bom.bytes, 11u);
}

TEST(ClReader, EmptyInput) {
  Result r = read("");
  EXPECT_TRUE(r.st.empty());
  EXPECT_EQ(r.diags, "");
  EXPECT_EQ(r.line, 0u);
}

TEST(ClReader, BytesReadAndLine) {
  Diagnostics diags("t.cl");
  ClReader reader(std::string_view("GOTO/1\n$$ c\nGOTO/2,$\n3\n"), diags);
  Statement s;
  EXPECT_EQ(reader.bytes_read(), 0u);
  ASSERT_TRUE(reader.next(s));
  EXPECT_EQ(reader.line(), 1u);
  EXPECT_EQ(reader.bytes_read(), 7u);
  ASSERT_TRUE(reader.next(s));
  EXPECT_EQ(reader.line(), 4u);
  EXPECT_EQ(reader.bytes_read(), 23u);
  EXPECT_EQ(s.line_text(3), "GOTO/2,$");
  EXPECT_EQ(s.line_text(4), "3");
  EXPECT_EQ(s.line_text(2), "");
  EXPECT_EQ(s.line_text(5), "");
  EXPECT_FALSE(reader.next(s));
}

// ---- NX information listing -------------------------------------------------------------------

TEST(ClReader, NxListingHeaderAndTrailer) {
  Result r = read(
      "\n"
      "Information listing created by\tphill\n"
      "Date\t18-Dec-2021 21:07:42\n"
      "Node name\tlaptop\n"
      "\n"
      "TOOL PATH/CAVITY_MILL,TOOL,MILL_0.120RAD\n"
      "END-OF-PATH\n"
      "Tool Path Listing has 2 lines.");
  EXPECT_EQ(dump(r),
            "6:1 R TOOL PATH/W:CAVITY_MILL@6:11,W:TOOL@6:23,W:MILL_0.120RAD@6:28 [6+1]\n"
            "7:1 B END-OF-PATH [7+1]\n");
  EXPECT_EQ(r.diags, "t.cl:2: note: skipped NX information listing header (5 lines)\n");
  EXPECT_EQ(r.errors, 0u);
}

TEST(ClReader, NxListingHeaderEndsAtFirstLineWithoutTab) {
  Result r = read("Information listing created by\tme\r\nDate\tx\r\nGOTO/1\r\n");
  EXPECT_EQ(dump(r), "3:1 R GOTO/N:1=1@3:6 [3+1]\n");
  EXPECT_EQ(r.diags, "t.cl:1: note: skipped NX information listing header (2 lines)\n");
}

// ---- binary input and limits ------------------------------------------------------------------

TEST(ClReader, BinaryInput) {
  Result r =
      read(std::string("GOTO/1\n\x7f"
                       "ELF\0\0\0",
                       14));
  EXPECT_TRUE(r.st.empty());
  EXPECT_EQ(r.diags, "t.cl: error: not a CL text file (binary data at byte 11)\n");
  Result controls = read("\x01\x02\x03\x04\x05 GOTO/1\n");
  EXPECT_EQ(controls.diags, "t.cl: error: not a CL text file (binary data at byte 0)\n");
}

// Binary or not is decided on the first 64 KiB; a NUL further on is a stray byte in a text
// file: an error at its line and column, and the file is read on.
TEST(ClReader, NulAfterFirstChunkIsAnErrorAtItsLine) {
  std::string text;
  size_t lines = 0;
  while (text.size() < 100 * 1024) text += "GOTO/1,2,3\n", ++lines;
  text += std::string("ABC\0DEF\n", 8);
  text += "FINI\n";
  Result r = read(text);
  EXPECT_EQ(r.diags, "t.cl:" + std::to_string(lines + 1) +
                         ":4: error: NUL byte in a text file; the statement is skipped\n"
                         "  ABC DEF\n     ^\n");
  EXPECT_EQ(r.st.size(), lines + 1);
  EXPECT_NE(dump(r).find("FINI"), std::string::npos);
}

TEST(ClReader, StrayNulInTextIsAnErrorAtItsLine) {
  Result r = read(std::string("GOTO/1,2,3\nGOTO/4,\0,6\nGOTO/7,$\n8\0,9\nFINI\n", 41));
  EXPECT_EQ(r.diags,
            "t.cl:2:8: error: NUL byte in a text file; the statement is skipped\n"
            "  GOTO/4, ,6\n         ^\n"
            "t.cl:4:2: error: NUL byte in a text file; the statement is skipped\n"
            "  8 ,9\n   ^\n");
  EXPECT_EQ(r.st.size(), 2u);
}

TEST(ClReader, GaveUpOnlyWhenStoppedBeforeTheEnd) {
  auto gave_up = [](std::string_view text) {
    Diagnostics diags("t.cl");
    ClReader reader(text, diags);
    Statement s;
    while (reader.next(s)) {
    }
    return reader.gave_up();
  };
  EXPECT_FALSE(gave_up(""));
  EXPECT_FALSE(gave_up("GOTO/1\n,2\nFINI\n"));  // an error, but read to the end
  EXPECT_TRUE(gave_up(std::string("GOTO/1\n\0\0\0", 10)));
  std::string many;
  for (int i = 0; i < 150; ++i) many += ",2\n";
  EXPECT_TRUE(gave_up(many));
}

const std::string kTooLong = "error: statement too long (more than 1048576 bytes)\n";

TEST(ClReader, StatementTooLongOneLine) {
  Result r = read("PPRINT " + std::string(2 << 20, 'x') + "\nGOTO/1\n");
  EXPECT_EQ(r.diags, "t.cl:1:1: " + kTooLong + "  PPRINT " + std::string(193, 'x') + "...\n  ^\n");
  EXPECT_EQ(dump(r), "2:1 R GOTO/N:1=1@2:6 [2+1]\n");
}

TEST(ClReader, StatementTooLongWithContinuations) {
  std::string text = "  GOTO/";
  for (int i = 0; i < (1 << 20); ++i) text += "1,";
  text += "$\n3,$\n4\nFINI\n";
  Result r = read(text);
  EXPECT_EQ(r.errors, 1u);
  EXPECT_EQ(r.diags.substr(0, 10 + kTooLong.size()), "t.cl:1:3: " + kTooLong);
  EXPECT_EQ(dump(r), "4:1 B FINI [4+1]\n");
}

TEST(ClReader, EndlessContinuation) {
  std::string text = "GOTO/1,$\n";
  for (int i = 0; i < 400000; ++i) text += "1,$\n";  // 3 bytes a line: 1.2 MB
  text += "2\nFINI\n";
  Result r = read(text);
  EXPECT_EQ(r.diags, "t.cl:1:1: " + kTooLong + "  GOTO/1,$\n  ^\n");
  EXPECT_EQ(dump(r), "400003:1 B FINI [400003+1]\n");
}

TEST(ClReader, HundredsOfThousandsOfContinuationLines) {
  // Just under the statement limit: 260 000 lines of `1,$`, each argument located on its line.
  std::string text = "GOTO/$\n";
  for (int i = 0; i < 260000; ++i) text += "1,$\n";
  text += "2\nFINI\n";
  Result r = read(text);
  EXPECT_EQ(r.diags, "");
  ASSERT_EQ(r.st.size(), 2u);
  ASSERT_EQ(r.st[0].args.size(), 260001u);
  EXPECT_EQ(at(r.st[0].args[0].loc), "@2:1");
  EXPECT_EQ(at(r.st[0].args[259999].loc), "@260001:1");
  EXPECT_EQ(at(r.st[0].args[260000].loc), "@260002:1");
  EXPECT_EQ(r.st[1].major, "FINI");
}

TEST(ClReader, TenMegabyteLine) {
  std::string text = "GOTO/1\nGOTO/" + std::string(10 << 20, '5') + "\nFINI";
  Result r = read(text);
  EXPECT_EQ(r.errors, 1u);
  EXPECT_EQ(r.diags.substr(0, 10 + kTooLong.size()), "t.cl:2:1: " + kTooLong);
  EXPECT_EQ(dump(r), "1:1 R GOTO/N:1=1@1:6 [1+1]\n3:1 B FINI [3+1]\n");
  EXPECT_EQ(r.bytes, text.size());
}

TEST(ClReader, LongCommentsAreNotErrors) {
  Result r = read("$$" + std::string(2 << 20, 'c') + "\n$$ " + std::string(2 << 20, 'c') +
                  " $\n  still comment\nFINI\n");
  EXPECT_EQ(r.diags, "");
  EXPECT_EQ(dump(r), "4:1 B FINI [4+1]\n");
}

TEST(ClReader, TooManyErrors) {
  std::string text;
  for (int i = 0; i < 150; ++i) text += "1,2\nFINI\n";
  Result r = read(text);
  EXPECT_EQ(r.errors, ClReader::kMaxErrors);
  EXPECT_EQ(r.st.size(), ClReader::kMaxErrors - 1);  // the FINIs between the errors
  EXPECT_EQ(r.line, 2 * ClReader::kMaxErrors - 1);
  const std::string last = "t.cl: note: too many errors, stopping\n";
  ASSERT_GT(r.diags.size(), last.size());
  EXPECT_EQ(r.diags.substr(r.diags.size() - last.size()), last);
  EXPECT_EQ(r.diags.substr(0, 50), "t.cl:1:1: error: expected a major word, found '1'\n");
}

// ---- streaming --------------------------------------------------------------------------------

TEST(ClReader, TwoHundredThousandGotosFromFile) {
  std::FILE* f = std::tmpfile();
  ASSERT_NE(f, nullptr);
  char line[64];
  for (int i = 0; i < 200000; ++i) {
    int n = std::snprintf(line, sizeof line, "GOTO/%d.5,-%d.25,%d\n", i, i, i % 7);
    ASSERT_EQ(std::fwrite(line, 1, static_cast<size_t>(n), f), static_cast<size_t>(n));
  }
  const long size = std::ftell(f);
  std::rewind(f);
  Diagnostics diags("big.cl");
  ClReader reader(f, diags);
  Statement s;
  size_t count = 0;
  double last_x = 0;
  while (reader.next(s)) {
    ASSERT_EQ(s.args.size(), 3u);
    ASSERT_EQ(s.args[2].loc.line, count + 1);
    last_x = s.args[0].number;
    ++count;
  }
  EXPECT_EQ(count, 200000u);
  EXPECT_EQ(last_x, 199999.5);
  EXPECT_EQ(s.args[1].number, -199999.25);
  EXPECT_EQ(reader.line(), 200000u);
  EXPECT_EQ(reader.bytes_read(), static_cast<size_t>(size));
  EXPECT_EQ(diags.render_all(), "");
  std::fclose(f);
}

// The first line of a file always takes the general path (it may start an NX listing); later
// plain lines take the one-pass fast path (plain_line.h). Both must give the same statements and
// the same diagnostics: each line is read first in a file and then after a FINI, one line down.
TEST(ClReader, FastPathReadsLikeTheGeneralPath) {
  const char* lines[] = {
      "GOTO/40.0000,0.0000,5.0000",
      "GOTO/1.,.5,-0.5,+2,-.5,-0",
      "LOADTL/1,ADJUST,1",
      "RAPID",
      "GOTO/1,2,",
      "GOTO/1,2,$",
      "GOTO/1,2 $$ note",
      "GOTO/1,2,$$ note",
      "$$ comment",
      "GOTO / 1 , 2",
      "goto/1,clw",
      "GOTO/1e400",
      "GOTO/--1",
      "GOTO/1.2.3",
      "GOTO/1e",
      "GOTO/1,,2",
      "GOTO//1",
      "GOTO/",
      "GOTO/1234567890123456789",
      "GOTO/10_SVERL_63",
      "GOTO/A+B",
      "GOTO/1;",
      "PPRINT/HELLO",
      "PARTNO",
      "1GOTO/1",
      "GOTO/-inf",
  };
  for (const char* line : lines) {
    for (const char* end : {"\n", "\r\n", "\r", ""}) {
      const Result first = read(std::string(line) + end);
      const Result later = read(std::string("FINI\n") + line + end);
      ASSERT_FALSE(later.st.empty()) << line;
      EXPECT_EQ(later.st[0].major, "FINI");
      Result general = first;
      for (Owned& s : general.st) {
        ++s.loc.line;
        ++s.first_line;
        for (OwnedArg& a : s.args) ++a.loc.line;
        if (s.problem_loc.line != 0) ++s.problem_loc.line;
      }
      Result fast = later;
      fast.st.erase(fast.st.begin());
      EXPECT_EQ(dump(fast), dump(general)) << line;
      std::string diags = first.diags;
      for (size_t at = 0; (at = diags.find("t.cl:1:", at)) != std::string::npos; at += 7)
        diags[at + 5] = '2';
      EXPECT_EQ(later.diags, diags) << line;
      EXPECT_EQ(later.errors, first.errors) << line;
      EXPECT_EQ(later.line, first.line + 1) << line;
    }
  }
}

// Statements, line ends and continuations cut at every place by the 64 KiB chunks: reading
// through a FILE* must give what reading from memory gives (read() compares them).
TEST(ClReader, ChunkBoundariesInsideStatements) {
  std::string text;
  const char* ends[] = {"\n", "\r\n", "\r"};
  for (int i = 0; text.size() < 300 * 1024; ++i) {
    text += "CIRCLE / " + std::to_string(i) + ".125, -0.5,  $";
    text += ends[i % 3];
    text += "   1.0, WORD_" + std::to_string(i) + " $$ note $";
    text += ends[(i + 1) % 3];
    if (i % 5 == 0) text += "$$-> CSYS / 1, $\n  2, 3\r";
  }
  Result r = read(text);
  EXPECT_EQ(r.errors, 0u);
  ASSERT_GT(r.st.size(), 1000u);
  for (size_t i = 0; i < r.st.size(); ++i) {
    ASSERT_EQ(r.st[i].args.size(), 4u) << i;
    EXPECT_EQ(r.st[i].args[0].number, static_cast<double>(i) + 0.125) << i;
    EXPECT_EQ(r.st[i].args[3].text, "WORD_" + std::to_string(i)) << i;
    EXPECT_EQ(r.st[i].args[2].loc.line, r.st[i].first_line + 1) << i;
  }
}

// Random text from APT's characters: never a crash, and FILE* and memory input agree (read()
// compares them), also across the 64 KiB chunk boundaries.
TEST(ClReader, RandomInputFileAndMemoryAgree) {
  const std::string alphabet = "GOTO/1.5e-,,  $$\t\n\r\nPPRINT\n$\nX_9.-+";
  uint32_t seed = 12345;
  auto next_random = [&seed] {
    seed = seed * 1664525u + 1013904223u;
    return seed >> 8;
  };
  for (int doc = 0; doc < 40; ++doc) {
    std::string text;
    const size_t size = doc == 0 ? 300 * 1024 : 200 + next_random() % 3000;
    while (text.size() < size) text += alphabet[next_random() % alphabet.size()];
    Result r = read(text);
    EXPECT_LE(r.errors, ClReader::kMaxErrors);
  }
}

}  // namespace
}  // namespace clpost

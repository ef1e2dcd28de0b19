// APT source as CAM systems write it (issue 15): continuation joining card images, empty
// arguments, quoted text, arithmetic, nested definitions, modifier words and the comma form,
// text statements, text bytes, line ends. Each rule with the exact statements delivered.
#include <gtest/gtest.h>

#include <string>

#include "reader/cl_reader_test_util.h"

namespace clpost {
namespace {

using namespace reader_test;

// ---- `$` continuation joins card images ------------------------------------------------------

TEST(AptSource, ContinuationSplitsANumber) {
  // CATIA (fixed-width output) cuts a line in the middle of a number.
  Result r = read(
      "CATMAT/    0.000000,    0.000000,    0$\n"
      ".000000,    1.000000,TURNING_PATH1_TRANSV\n");
  EXPECT_EQ(dump(r),
            "1:1 R CATMAT/N:0.000000=0@1:12,N:0.000000=0@1:25,N:0.000000=0@1:38,"
            "N:1.000000=1@2:13,W:TURNING_PATH1_TRANSV@2:22 [1+2]\n");
  EXPECT_EQ(r.diags, "");
}

TEST(AptSource, ContinuationSplitsAWord) {
  Result r = read("HELICAL/RADIUS,    0.75000,ROUN$\nD,    0.50000\n");
  EXPECT_EQ(
      dump(r),
      "1:1 R HELICAL/W:RADIUS@1:9,N:0.75000=0.75@1:20,W:ROUND@1:28,N:0.50000=0.5@2:7 [1+2]\n");
}

TEST(AptSource, ContinuationLineStartingWithATab) {
  // ICAM's CATIA table indents the continuation of THREAD/ON with a tab.
  Result r = read("THREAD/ON,DEPTH,1.534,CUTS,5,$\n\tATANGL,30,1.5\n");
  EXPECT_EQ(dump(r),
            "1:1 R THREAD/W:ON@1:8,W:DEPTH@1:11,N:1.534=1.534@1:17,W:CUTS@1:23,N:5=5@1:28,"
            "W:ATANGL@2:2,N:30=30@2:9,N:1.5=1.5@2:12 [1+2]\n");
}

TEST(AptSource, ContinuationOfText) {
  // A text statement continues like any other; `Turning Tool$` + ` Assembly.1` is one text.
  Result r = read(
      "TPRINT/T1,Turning Tool$\n"
      " Assembly.1\n"
      "PPRINT/(USING LCPMC73010=AGB#18 GLASS BEADS CONTROLLED BY .250\" DIAM. O$\r\n"
      "RIFICE ) \r\n"
      "PPRINT cost $$ is text, and the line ends in $$\n");
  EXPECT_EQ(dump(r),
            "1:1 T TPRINT 'T1,Turning Tool Assembly.1' [1+2]\n"
            "3:1 T PPRINT '(USING LCPMC73010=AGB#18 GLASS BEADS CONTROLLED BY .250\" DIAM. "
            "ORIFICE )' [3+2]\n"
            "5:1 T PPRINT 'cost $$ is text, and the line ends in $$' [5+1]\n");
}

// ---- empty arguments -------------------------------------------------------------------------

TEST(AptSource, EmptyArgumentsKeepTheirPlace) {
  Result r = read(
      "TDATA/ANGLE,,PITCH,,CORE,    0.000000\n"
      "SPINDL_NAME/NAME,,NUMB,\n"
      "DEC_XY/,,,DEC_POL\n"
      "GOTO/1,2, $$ note\n"
      "RAPID/\n");
  EXPECT_EQ(dump(r),
            "1:1 R TDATA/W:ANGLE@1:7,E@1:13,W:PITCH@1:14,E@1:20,W:CORE@1:21,"
            "N:0.000000=0@1:30 [1+1]\n"
            "2:1 R SPINDL_NAME/W:NAME@2:13,E@2:18,W:NUMB@2:19,E@2:24 [2+1]\n"
            "3:1 R DEC_XY/E@3:8,E@3:9,E@3:10,W:DEC_POL@3:11 [3+1]\n"
            "4:1 R GOTO/N:1=1@4:6,N:2=2@4:8,E@4:10 [4+1]\n"
            "5:1 R RAPID/ [5+1]\n");
  EXPECT_EQ(r.diags, "");
}

// An empty last argument is located just after its ',' on the comma's own line, even when a
// `$` continues the statement onto an empty line (a caret on an empty line shows nothing).
TEST(AptSource, AnEmptyLastArgumentIsJustAfterItsComma) {
  Result r = read("CYCLE/DRILL,$\n\nGOTO/1,  $\n   \nFINI\n");
  EXPECT_EQ(dump(r),
            "1:1 R CYCLE/W:DRILL@1:7,E@1:13 [1+2]\n"
            "3:1 R GOTO/N:1=1@3:6,E@3:8 [3+2]\n"
            "5:1 B FINI [5+1]\n");
  EXPECT_EQ(r.diags, "");
}

// REMARK, APT's comment statement (NCL's APT source begins with one), is a text statement: the
// file name with its '.' and the date are text, not arguments.
TEST(AptSource, RemarkIsAText) {
  Result r = read("REMARK upside_down.as     27-APR-2021  10:45:22  NCLCAM     2020.00\nFINI\n");
  EXPECT_EQ(dump(r),
            "1:1 T REMARK 'upside_down.as     27-APR-2021  10:45:22  NCLCAM     2020.00' [1+1]\n"
            "2:1 B FINI [2+1]\n");
  EXPECT_EQ(r.diags, "");
}

// ---- quoted text -----------------------------------------------------------------------------

TEST(AptSource, QuotedText) {
  // `$$` inside quotes is text, not a comment; a quote inside a word is an ordinary character.
  Result r = read(
      "SYN/'TLAXIS','$$*TLAXIS'\n"
      "NOTE/\"say \"\"hi\", 'it''s' $$ a comment\n"
      "SYN/'A', 'B' ,\"C D\"\n");
  EXPECT_EQ(dump(r),
            "1:1 R SYN/T:'TLAXIS'@1:5,T:'$$*TLAXIS'@1:14 [1+1]\n"
            "2:1 R NOTE/ !2:12 missing ',' before '\"hi\"' [2+1]\n"
            "3:1 R SYN/T:'A'@3:5,T:'B'@3:10,T:'C D'@3:15 [3+1]\n");
}

// ---- arithmetic ------------------------------------------------------------------------------

TEST(AptSource, Arithmetic) {
  Result r = read("PITCH/(1/2.5),MULTRD,1\nX/(2*3+1), -(1 + 2) ,( (4) ), (2**3**2), (-2**2)\n");
  EXPECT_EQ(dump(r),
            "1:1 R PITCH/N:(1/2.5)=0.40000000000000002@1:7,W:MULTRD@1:15,N:1=1@1:22 [1+1]\n"
            "2:1 R X/N:(2*3+1)=7@2:3,N:-(1 + 2)=-3@2:12,N:( (4) )=4@2:22,N:(2**3**2)=512@2:31,"
            "N:(-2**2)=-4@2:42 [2+1]\n");
}

TEST(AptSource, ArithmeticProblemsAreAtTheirColumn) {
  Result r = read(
      "PITCH/(1/0)\n"
      "PITCH/(1/(2-2))\n"
      "PITCH/(1/2.5\n"
      "STOP/(INSTALL TEST STRIP)\n"
      "X/(1e300*1e300)\n"
      "X/((-8)**0.5)\n"
      "X/(2 3)\n"
      "X/(1e308 + 1e308)\n");
  EXPECT_EQ(dump(r),
            "1:1 R PITCH/ !1:9 division by zero [1+1]\n"
            "2:1 R PITCH/ !2:9 division by zero [2+1]\n"
            "3:1 R PITCH/ !3:7 missing ')' to close this '(' [3+1]\n"
            "4:1 R STOP/ !4:7 expected a number in the expression, found 'INSTALL' [4+1]\n"
            "5:1 R X/ !5:9 the result is out of range [5+1]\n"
            "6:1 R X/ !6:8 the result is not a number [6+1]\n"
            "7:1 R X/ !7:6 expected an operator or ')' in the expression, found '3' [7+1]\n"
            "8:1 R X/ !8:10 the result is out of range [8+1]\n");
  EXPECT_EQ(r.diags, "");
}

TEST(AptSource, DeepParenthesesAreRefusedNotOverflowed) {
  Result r = read("X/" + std::string(100000, '(') + "1" + std::string(100000, ')') + "\n");
  EXPECT_EQ(dump(r), "1:1 R X/ !1:67 parentheses nested too deeply [1+1]\n");
  Result d = read("X/" + std::string(100000, '(') + "\n");
  EXPECT_EQ(dump(d), "1:1 R X/ !1:67 parentheses nested too deeply [1+1]\n");
}

// ---- nested definitions ----------------------------------------------------------------------

TEST(AptSource, NestedDefinitions) {
  // CATIA's turning arc, as DEMO5.txt writes it.
  Result r = read(
      "TLON,GOFWD/      (CIRCLE/     25.00000,      0.00000,    -30.00000,$\r\n"
      "       4.60000),ON,(LINE/     25.00000,      0.00000,    -30.00000,$\r\n"
      "                              25.00000,      0.00000,    -25.40000)\r\n");
  EXPECT_EQ(dump(r),
            "1:6 R TLON,GOFWD/D:CIRCLE(N:25.00000=25@1:31,N:0.00000=0@1:46,N:-30.00000=-30@1:58,"
            "N:4.60000=4.5999999999999996@2:8)@1:18,W:ON@2:17,D:LINE(N:25.00000=25@2:31,"
            "N:0.00000=0@2:46,N:-30.00000=-30@2:58,N:25.00000=25@3:31,N:0.00000=0@3:46,"
            "N:-25.40000=-25.399999999999999@3:58)@2:20 [1+3]\n");
  EXPECT_EQ(r.diags, "");
}

TEST(AptSource, DefinitionsNestInDefinitions) {
  Result r = read(
      "PSIS/(PLANE/(POINT/ 2, 0, 2),PERPTO,$\n"
      "            (VECTOR/ 0, 1, 0))\n"
      "X/(LINE/),(POINT/1,,3)\n");
  EXPECT_EQ(dump(r),
            "1:1 R PSIS/D:PLANE(D:POINT(N:2=2@1:21,N:0=0@1:24,N:2=2@1:27)@1:13,W:PERPTO@1:30,"
            "D:VECTOR(N:0=0@2:22,N:1=1@2:25,N:0=0@2:28)@2:13)@1:6 [1+2]\n"
            "3:1 R X/D:LINE()@3:3,D:POINT(N:1=1@3:18,E@3:20,N:3=3@3:21)@3:11 [3+1]\n");
}

TEST(AptSource, NestedDefinitionProblems) {
  Result r = read("X/(LINE/1,2\nX/(LINE/1 2)\nX/(CIRCLE/(POINT/1),1))\n");
  EXPECT_EQ(dump(r),
            "1:1 R X/ !1:3 missing ')' to close (LINE/ [1+1]\n"
            "2:1 R X/ !2:11 missing ',' before '2' [2+1]\n"
            "3:1 R X/ !3:23 unexpected ')' without a '(' [3+1]\n");
}

// ---- words -----------------------------------------------------------------------------------

TEST(AptSource, WordsStartingWithADigit) {
  Result r = read("CYCLE/DEEP,1STPECK,2.5,5PT,900CCLW\n");
  EXPECT_EQ(dump(r),
            "1:1 R CYCLE/W:DEEP@1:7,W:1STPECK@1:12,N:2.5=2.5@1:20,W:5PT@1:24,W:900CCLW@1:28 "
            "[1+1]\n");
}

// ---- the words before the '/': modifiers, and the comma form ---------------------------------

TEST(AptSource, ModifierWordsBeforeTheMajorWord) {
  // APT's motion statements: the word before the '/' is the major word, the words before it
  // modify it (TLON tool on the drive surface; RAPID the next motion).
  Result r = read(
      "TLON,GOFWD/(CIRCLE/1,2,3,4),ON,(LINE/1,2,3,4,5,6)\n"
      "rapid, clrsrf/now\n"
      "TLLFT , GOLFT / C2,TANTO,C4\n"
      "A,B,C/1\n");
  EXPECT_EQ(dump(r),
            "1:6 R TLON,GOFWD/D:CIRCLE(N:1=1@1:20,N:2=2@1:22,N:3=3@1:24,N:4=4@1:26)@1:12,"
            "W:ON@1:29,D:LINE(N:1=1@1:38,N:2=2@1:40,N:3=3@1:42,N:4=4@1:44,N:5=5@1:46,"
            "N:6=6@1:48)@1:32 [1+1]\n"
            "2:8 R RAPID,CLRSRF/W:NOW@2:15 [2+1]\n"
            "3:9 R TLLFT,GOLFT/W:C2@3:17,W:TANTO@3:20,W:C4@3:26 [3+1]\n"
            "4:5 R A,B,C/N:1=1@4:7 [4+1]\n");
  ASSERT_EQ(r.st.size(), 4u);
  EXPECT_EQ(r.st[0].text, "(CIRCLE/1,2,3,4),ON,(LINE/1,2,3,4,5,6)");
  EXPECT_EQ(r.st[1].source, "rapid, clrsrf/now");
}

TEST(AptSource, CommaFormWithoutSlash) {
  // `CHANNEL,1` (ICAM's CATIA tables): no '/', the first ',' stands for it.
  Result r = read("CHANNEL,\nCHANNEL,1\nCHANNEL , 1 , ,\nSYNC,1,A\n");
  EXPECT_EQ(dump(r),
            "1:1 R CHANNEL/ [1+1]\n"
            "2:1 R CHANNEL/N:1=1@2:9 [2+1]\n"
            "3:1 R CHANNEL/N:1=1@3:11,E@3:15,E@3:16 [3+1]\n"
            "4:1 R SYNC/N:1=1@4:6,W:A@4:8 [4+1]\n");
}

// ---- text statements -------------------------------------------------------------------------

TEST(AptSource, TextStatementsWithoutSlash) {
  Result r = read(
      "PPRINT TOOL: Thread Tool.1\n"
      "PPRINT -prva strana\n"
      "PPRINT (SDFSDFSDFSD)\n"
      "TPRINT/SDJCL 1210 D07,SDJCL 1210 D07\n"
      "PARTNO Part Operation.1\n");
  EXPECT_EQ(dump(r),
            "1:1 T PPRINT 'TOOL: Thread Tool.1' [1+1]\n"
            "2:1 T PPRINT '-prva strana' [2+1]\n"
            "3:1 T PPRINT '(SDFSDFSDFSD)' [3+1]\n"
            "4:1 T TPRINT 'SDJCL 1210 D07,SDJCL 1210 D07' [4+1]\n"
            "5:1 T PARTNO 'Part Operation.1' [5+1]\n");
}

// ---- text bytes, line ends -------------------------------------------------------------------

TEST(AptSource, Latin1AndUtf8Text) {
  Result r = read(
      "$$  D\xE9"
      "but de g\xE9n\xE9ration de: FIN RAYON - G2\n"
      "TPRINT/Porte-plaquette ext\xE9rieur.1\n"
      "PPRINT ext\xC3\xA9rieur\n"
      "NOTE/'\xE9t\xE9'\n"
      "OP_NAME/Contournage p\xE9riph\n");
  EXPECT_EQ(dump(r),
            "2:1 T TPRINT 'Porte-plaquette ext\xE9rieur.1' [2+1]\n"
            "3:1 T PPRINT 'ext\xC3\xA9rieur' [3+1]\n"
            "4:1 R NOTE/T:'\xE9t\xE9'@4:6 [4+1]\n"
            "5:1 R OP_NAME/ !5:21 missing ',' before 'p\\xE9riph' [5+1]\n");
  EXPECT_EQ(r.diags, "");
}

TEST(AptSource, CrlfAndNoFinalNewline) {
  Result r = read("GOTO/1,$\r\n2\r\nTHREAD/OFF");
  EXPECT_EQ(dump(r), "1:1 R GOTO/N:1=1@1:6,N:2=2@2:1 [1+2]\n3:1 R THREAD/W:OFF@3:8 [3+1]\n");
}

// ---- APT part programs: read, never a crash ----------------------------------------------------

TEST(AptSource, PartProgramDefinitionsAreDeliveredWithAProblem) {
  Result r = read("p1=point/22,-3.0,0 $$location\nc3=circle/xlarge,in,c1\n");
  EXPECT_EQ(dump(r),
            "1:1 B P1 !1:3 'P1=' defines an APT part-program symbol: not CL data (post the CL "
            "file the APT processor wrote) [1+1]\n"
            "2:1 B C3 !2:3 'C3=' defines an APT part-program symbol: not CL data (post the CL "
            "file the APT processor wrote) [2+1]\n");
  ASSERT_EQ(r.st.size(), 2u);
  EXPECT_EQ(r.st[0].source, "p1=point/22,-3.0,0");
}

// ---- the CATIA+ICAM thread of issue 15, as the ICAM table writes it -------------------------

TEST(AptSource, CatiaIcamThread) {
  Result r = read(
      "PPFUN/15,1318046,OFF\n"
      "SYN/'TLAXIS','$$*TLAXIS'\n"
      "PPRINT TOOL: Thread Tool.1\n"
      "TURRET/7,OSETNO,7,SETOOL,0.0,0.0,0.0\n"
      "PITCH/(1/2.5),MULTRD,1\n"
      "DNTCUT\n"
      "GODLTA/1,0,0\n"
      "THREAD/ON,DEPTH,1.534,CUTS,5,CUTANG,180,FINCUT,1,$\n"
      "\tATANGL,30,1.5,TLANGL,60,OPTION,1\n"
      "THREAD/OFF\n");
  EXPECT_EQ(dump(r),
            "1:1 R PPFUN/N:15=15@1:7,N:1318046=1318046@1:10,W:OFF@1:18 [1+1]\n"
            "2:1 R SYN/T:'TLAXIS'@2:5,T:'$$*TLAXIS'@2:14 [2+1]\n"
            "3:1 T PPRINT 'TOOL: Thread Tool.1' [3+1]\n"
            "4:1 R TURRET/N:7=7@4:8,W:OSETNO@4:10,N:7=7@4:17,W:SETOOL@4:19,N:0.0=0@4:26,"
            "N:0.0=0@4:30,N:0.0=0@4:34 [4+1]\n"
            "5:1 R PITCH/N:(1/2.5)=0.40000000000000002@5:7,W:MULTRD@5:15,N:1=1@5:22 [5+1]\n"
            "6:1 B DNTCUT [6+1]\n"
            "7:1 R GODLTA/N:1=1@7:8,N:0=0@7:10,N:0=0@7:12 [7+1]\n"
            "8:1 R THREAD/W:ON@8:8,W:DEPTH@8:11,N:1.534=1.534@8:17,W:CUTS@8:23,N:5=5@8:28,"
            "W:CUTANG@8:30,N:180=180@8:37,W:FINCUT@8:41,N:1=1@8:48,W:ATANGL@9:2,N:30=30@9:9,"
            "N:1.5=1.5@9:12,W:TLANGL@9:16,N:60=60@9:23,W:OPTION@9:26,N:1=1@9:33 [8+2]\n"
            "10:1 R THREAD/W:OFF@10:8 [10+1]\n");
  EXPECT_EQ(r.diags, "");
}

}  // namespace
}  // namespace clpost

// Pass-through words and the machine's positions: AUXFUN, PREFUN, SELCTL, CLAMP, OPSKIP, GOHOME
// and the tool-change position.
#include <gtest/gtest.h>

#include "interpreter/post_test_util.h"

namespace clpost {
namespace {

using test::load;
using test::post;
using test::Posted;

constexpr const char* kGenericStart = "%\nO0001\nG18 G21 G40 G90\n";

TEST(MachineWords, AuxfunAndPrefunAreTheMachinesCodes) {
  Posted p = post("AUXFUN/8\nPREFUN/40\nAUXFUN/19,NEXT\nFINI\n", load("generic-lathe"));
  EXPECT_EQ(p.nc, std::string(kGenericStart) + "M8\nG40\nM19\nM30\n%\n");
  EXPECT_EQ(p.diags,
            "t.cl:3:11: warning: AUXFUN/: the words after the number are not written ('NEXT')\n"
            "  AUXFUN/19,NEXT\n"
            "            ^\n");
}

TEST(MachineWords, WithoutATemplateTheWordIsAWarningAndAComment) {
  Machine m = load("generic-lathe");
  m.templates.erase("auxfun");
  Posted p = post("AUXFUN/8\nSELCTL/2\nCLAMP/ON\nFINI\n", m);
  EXPECT_EQ(p.nc, std::string(kGenericStart) + "(AUXFUN/8)\n(SELCTL/2)\n(CLAMP/ON)\nM30\n%\n");
  EXPECT_NE(p.diags.find("t.cl:1:1: warning: AUXFUN/: machine 'generic-lathe' has no template "
                         "'auxfun': written as a comment"),
            std::string::npos)
      << p.diags;
  EXPECT_NE(p.diags.find("t.cl:3:1: warning: CLAMP/: machine 'generic-lathe' has no code "
                         "'clamp_on': written as a comment"),
            std::string::npos)
      << p.diags;
  EXPECT_EQ(post("AUXFUN/1.5\nFINI\n", m).errors, 1u);
}

TEST(MachineWords, ClampWithTheMachinesCodes) {
  Posted p = post("CLAMP/ON\nCLAMP/OFF\nCLAMP/TIGHT\nFINI\n",
                  load("generic-lathe", {"codes.clamp_on=M10", "codes.clamp_off=M11"}));
  EXPECT_EQ(p.errors, 1u);
  EXPECT_NE(p.nc.find("M10\nM11\n"), std::string::npos) << p.nc;
  EXPECT_NE(p.diags.find("t.cl:3:7: error: expected CLAMP/ON or CLAMP/OFF"), std::string::npos)
      << p.diags;
}

TEST(MachineWords, OpskipMarksTheBlocksInBetween) {
  Posted p = post(
      "FEDRAT/0.2,MMPR\nGOTO/10,0,0\nOPSKIP/ON\nGOTO/10,0,-5\nAUXFUN/8\nOPSKIP/OFF\n"
      "GOTO/12,0,-5\nFINI\n",
      load("generic-lathe"));
  EXPECT_EQ(p.diags, "");
  // After the range the move states its motion, X, Z and F again: with block delete on the
  // control skipped Z-5 (docs/cl-meaning.md).
  EXPECT_EQ(p.nc, std::string(kGenericStart) +
                      "G1 X20. Z0. G95 F0.2\n/Z-5.\n/M8\nG1 X24. Z-5. G95 F0.2\nM30\n%\n");
  // Fanuc numbers its blocks: the mark comes first.
  Machine f = load("fanuc-0i-t", {"block_numbers.enabled=true"});
  Posted q = post("FEDRAT/0.2,MMPR\nOPSKIP/ON\nGOTO/10,0,0\nOPSKIP/OFF\nFINI\n", f);
  EXPECT_NE(q.nc.find("\n/N20 G1 X20. Z0. G99 F0.2\nN30 M30\n"), std::string::npos) << q.nc;
}

TEST(MachineWords, GohomeIsTheMachinesHomeAxisByAxis) {
  Posted p = post("RAPID\nGOTO/20,0,5\nGOHOME\nRAPID\nGOTO/20,0,5\nFINI\n", load("fanuc-0i-t"));
  EXPECT_EQ(p.diags, "");
  // After the home return both axes and the motion code are written again.
  EXPECT_NE(p.nc.find("G0 X40. Z5.\nG28 U0.\nG28 W0.\nG0 X40. Z5.\nM30\n"), std::string::npos)
      << p.nc;
}

TEST(MachineWords, GohomeWithoutATemplate) {
  // A home point in the CL: a rapid move there.
  Posted p = post("GOHOME/50,0,100\nFINI\n", load("generic-lathe"));
  EXPECT_EQ(p.diags, "");
  EXPECT_EQ(p.nc, std::string(kGenericStart) + "G0 X100. Z100.\nM30\n%\n");
  Posted q = post("GOHOME\nFINI\n", load("generic-lathe"));
  EXPECT_EQ(q.nc, std::string(kGenericStart) + "(GOHOME)\nM30\n%\n");
  EXPECT_NE(q.diags.find("t.cl:1:1: warning: GOHOME: machine 'generic-lathe' has no template "
                         "'home' and the CL gives no home point: written as a comment"),
            std::string::npos)
      << q.diags;
}

TEST(MachineWords, ToolChangePositionBeforeEveryToolChange) {
  Posted p = post("RAPID\nGOTO/20,0,5\nLOADTL/2\nRAPID\nGOTO/20,0,5\nLOADTL/3\nFINI\n",
                  load("generic-lathe", {"templates.tool_change_position=[\"G53 X200. Z300.\"]"}));
  EXPECT_EQ(p.diags, "");
  EXPECT_EQ(p.nc, std::string(kGenericStart) +
                      "G0 X40. Z5.\nG53 X200. Z300.\nT0202\nG0 X40. Z5.\nG53 X200. Z300.\n"
                      "T0303\nM30\n%\n");
}

TEST(MachineWords, CoolantWordsAfterTheCoolantAreNotDroppedSilently) {
  Posted p = post("COOLNT/FLOOD,HIGH,2\nCOOLNT/OFF\nFINI\n", load("generic-lathe"));
  EXPECT_EQ(p.nc, std::string(kGenericStart) + "M8\nM9\nM30\n%\n");
  EXPECT_EQ(p.diags,
            "t.cl:1:14: warning: COOLNT/FLOOD: the words after it are not written ('HIGH,2')\n"
            "  COOLNT/FLOOD,HIGH,2\n"
            "               ^\n");
}

// CATIA's tool change writes COOLNT/ with nothing after it for a tool without coolant (ICAM's
// interface kit swallows it): the coolant in force stays, with one note.
TEST(MachineWords, AnEmptyCoolantWordChangesNothing) {
  Posted p = post("COOLNT/ON\nLOADTL/2\nCOOLNT/\nLOADTL/3\nCOOLNT/\nCOOLNT/OFF\nFINI\n",
                  load("generic-lathe"));
  EXPECT_EQ(p.nc, std::string(kGenericStart) + "M8\nT0202\nT0303\nM9\nM30\n%\n");
  EXPECT_EQ(p.diags,
            "t.cl:3:1: note: COOLNT/ without a coolant (CATIA's tool change for a tool with none "
            "set): the coolant does not change\n"
            "  COOLNT/\n"
            "  ^\n");
  // Bare, or with an empty argument, it is not CATIA's form: still an error.
  Posted q = post("COOLNT\nCOOLNT/,\nFINI\n", load("generic-lathe"));
  EXPECT_EQ(q.errors, 2u);
  EXPECT_EQ(q.diags,
            "t.cl:1:1: error: expected COOLNT/ON, FLOOD, MIST, THRU, AIR or OFF\n"
            "  COOLNT\n"
            "  ^\n"
            "t.cl:2:8: error: expected COOLNT/ON, FLOOD, MIST, THRU, AIR or OFF\n"
            "  COOLNT/,\n"
            "         ^\n");
}

// REMARK (APT's comment statement, NCL's header line) leaves nothing in the program.
TEST(MachineWords, RemarkIsSkipped) {
  Posted p = post("REMARK part.as  5-JAN-2021\nREMARK again\nFINI\n", load("generic-lathe"));
  EXPECT_EQ(p.nc, std::string(kGenericStart) + "M30\n%\n");
  EXPECT_EQ(p.diags,
            "t.cl:1:1: note: REMARK records skipped (nothing a lathe program needs)\n"
            "  REMARK part.as  5-JAN-2021\n"
            "  ^\n");
}

// Sequence numbers only where a tool change begins; long comments wrapped; long blocks refused.
constexpr const char* kTwoTools =
    "LOADTL/1\nRAPID\nGOTO/10,0,5\nPPRINT a comment that is rather long\nLOADTL/2\nFINI\n";

TEST(MachineWords, SequenceNumbersAtToolChanges) {
  Posted p = post(kTwoTools, load("generic-lathe", {"block_numbers.enabled=true",
                                                    "block_numbers.at_tool_changes=true"}));
  EXPECT_EQ(p.nc, std::string(kGenericStart) +
                      "N10 T0101\nG0 X20. Z5.\n(a comment that is rather long)\nN20 T0202\nM30\n"
                      "%\n");
}

TEST(MachineWords, LongCommentsAreWrappedAtABlank) {
  Posted p = post(kTwoTools, load("generic-lathe", {"comments.max_length=12"}));
  EXPECT_EQ(p.nc, std::string(kGenericStart) +
                      "T0101\nG0 X20. Z5.\n(a comment)\n(that is)\n(rather long)\nT0202\nM30\n"
                      "%\n");
  EXPECT_EQ(p.diags,
            "t.cl: warning: 1 comments longer than comments.max_length 12 of machine "
            "'generic-lathe' were wrapped onto more comment blocks\n");
  // A word longer than the limit is cut.
  Posted q = post("PPRINT ABCDEFGHIJ\nFINI\n", load("generic-lathe", {"comments.max_length=4"}));
  EXPECT_EQ(q.nc, std::string(kGenericStart) + "(ABCD)\n(EFGH)\n(IJ)\nM30\n%\n");
}

TEST(MachineWords, ABlockLongerThanTheMachineTakesIsAnError) {
  // "G18 G21 G40 G90" (line 3) is the first block longer than 14 characters.
  Posted p = post(kTwoTools, load("generic-lathe", {"output.max_line_length=14"}));
  EXPECT_EQ(p.errors, 1u);
  EXPECT_NE(p.diags.find("t.cl: error: 2 blocks are longer than output.max_line_length 14 of "
                         "machine 'generic-lathe', the first at NC line 3"),
            std::string::npos)
      << p.diags;
}

}  // namespace
}  // namespace clpost

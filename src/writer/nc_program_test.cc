#include "writer/nc_program.h"

#include <fmt/format.h>
#include <gtest/gtest.h>

namespace clpost {
namespace {

Machine test_machine() {
  Machine m;
  m.codes = {{"rapid", "G0"},         {"linear", "G1"},  {"arc_cw", "G2"},
             {"arc_ccw", "G3"},       {"thread", "G33"}, {"feed_per_rev", "G95"},
             {"feed_per_min", "G94"}, {"metric", "G21"}, {"coolant_flood", "M8"},
             {"coolant_off", "M9"}};
  m.templates["program_start"] = {"%", "O{program_number:04}", "G18 {units_code}"};
  m.templates["spindle_rpm"] = {"G97 S{rpm} {direction}"};
  m.codes["spindle_cw"] = "M3";
  m.formats["S"] = NumberFormat{0, false, true, true, 1};
  return m;
}

TEST(NcProgram, ModalWordsAndDiameterOutput) {
  Machine m = test_machine();
  StringSink out;
  NcProgram p(m, out);
  EXPECT_TRUE(p.start("", false, "x.cl"));
  EXPECT_TRUE(p.spindle_rpm(1200, SpindleDir::kCw));
  p.rapid({22, 2});  // radius 22 -> X44.
  p.rapid({22, 0});  // only Z changes
  p.set_feed(0.2, FeedMode::kPerRev);
  p.linear({-0.4, 0});  // G1, X-0.8, G95 F0.2 on the first feed move
  p.linear({-0.4, 1});  // only Z
  p.set_feed(0.15, FeedMode::kPerRev);
  p.linear({15, 1});  // new F only
  EXPECT_EQ(out.out,
            "%\nO0001\nG18 G21\nG97 S1200 M3\nG0 X44. Z2.\nZ0.\nG1 X-0.8 G95 F0.2\nZ1.\n"
            "X30. F0.15\n");
}

// A move to where the tool was just written to be writes no block: "G0" alone (the motion code
// changed, no axis) would be a block that moves nothing. A position written differently (X to
// the X format's 3 decimals) is a move.
TEST(NcProgram, AMoveToTheWrittenPositionWritesNothing) {
  Machine m = test_machine();
  StringSink out;
  NcProgram p(m, out);
  p.set_feed(0.2, FeedMode::kPerRev);
  p.linear({12, -10});
  p.rapid({12, -10});
  p.linear({12.0000001, -10});
  p.rapid({16, 2});
  p.rapid({16.001, 2});
  EXPECT_EQ(out.out, "G1 X24. Z-10. G95 F0.2\nG0 X32. Z2.\nX32.002\n");
}

// "T{tool:02}{offset:02}": the offset is told from the tool by its two digits only. Tool 700
// with offset 7 is T70007 (tool 700, offset 07); offset 700 would write T07700, read as tool 77
// offset 0 (or T700700 as tool 7007): the template cannot say it, an error, nothing written.
TEST(NcProgram, AFieldWiderThanItsWidthAfterAnotherIsAnError) {
  Machine m = test_machine();
  m.templates["tool_change"] = {"T{tool:02}{offset:02}"};
  StringSink out;
  NcProgram p(m, out);
  EXPECT_TRUE(p.tool_change(700, 7, ""));
  const TemplateWrite w = p.tool_change(7, 700, "");
  EXPECT_EQ(w.status, TemplateWrite::Status::kBadLine);
  EXPECT_EQ(w.detail,
            "{offset} 700 is 3 digits where 'T{tool:02}{offset:02}' gives it 2: the word would "
            "read as other numbers");
  EXPECT_EQ(out.out, "T70007\n");
}

TEST(NcProgram, ModalSuppressionComparesTheWrittenText) {
  // 0.0055 · 1000 is 5.5 in double arithmetic, but the exact binary value of 0.0055 lies below
  // the half: it is written Z0.005, as printf rounds. The move to Z0.006 after it is a new text
  // and must be written (comparing values rounded half away from zero took both for 0.006).
  // Z0.0059 then writes Z0.006 again: left out, and the block is empty.
  Machine m = test_machine();
  StringSink out;
  NcProgram p(m, out);
  p.rapid({10, 0.0055});
  p.rapid({10, 0.006});
  p.rapid({10, 0.0059});
  p.rapid({11, 0.006});
  // 0.0625 is an exact tie at 3 decimals: fmt writes it (half to even, Z0.062). The same value
  // again is left out; 0.062 writes the same text but is another value: written again, as
  // leaving out a word needs the digits to be known for sure.
  p.rapid({11, 0.0625});
  p.rapid({12, 0.0625});
  p.rapid({12, 0.062});
  EXPECT_EQ(out.out, "G0 X20. Z0.005\nZ0.006\nX22.\nZ0.062\nX24.\nZ0.062\n");
}

TEST(NcProgram, BlockNumbersWrap) {
  Machine m = test_machine();
  m.block_numbers = true;
  m.block_start = 10;
  m.block_step = 10;
  m.block_max = 30;
  StringSink out;
  NcProgram p(m, out);
  p.rapid({1, 1});
  p.rapid({2, 1});
  p.rapid({3, 1});
  p.rapid({4, 1});
  p.comment("(done)");
  EXPECT_EQ(out.out, "N10 G0 X2. Z1.\nN20 X4.\nN30 X6.\nN10 X8.\nN20 (done)\n");
}

TEST(NcProgram, ArcCentreIsIncrementalRadius) {
  Machine m = test_machine();
  StringSink out;
  NcProgram p(m, out);
  p.set_feed(0.15, FeedMode::kPerRev);
  p.linear({15, -20});
  // Fillet R2 from (r15, z-20) to (r17, z-22) about (r17, z-20): I = 17-15 = 2, K = -20-(-20) = 0.
  p.arc({17, -22}, {17, -20}, false);
  EXPECT_EQ(out.out, "G1 X30. Z-20. G95 F0.15\nG2 X34. Z-22. I2. K0.\n");
}

TEST(NcProgram, ThreadLeadInFRestatesTheFeedAfterwards) {
  Machine m = test_machine();
  m.thread_lead_address = "F";
  StringSink out;
  NcProgram p(m, out);
  p.set_feed(0.2, FeedMode::kPerRev);
  p.linear({10, 0});
  p.thread({10, -20}, 1.5);
  p.linear({12, -20});  // F0.2 again: F1.5 replaced it on the control
  EXPECT_EQ(out.out, "G1 X20. Z0. G95 F0.2\nG33 Z-20. F1.5\nG1 X24. F0.2\n");
}

}  // namespace
}  // namespace clpost

namespace clpost {
namespace {

// The lead words of thread blocks: K along Z, I when the X travel dominates (a face thread),
// E threads per inch, SF= start angle, G34/G35 with the lead change in F.
TEST(NcProgram, ThreadLeadWords) {
  Machine m = test_machine();
  m.thread_lead_address = "K";
  m.thread_lead_address_x = "I";
  m.start_angle_word = true;
  m.start_angle_address = "SF=";
  m.codes["thread_increasing"] = "G34";
  m.codes["thread_decreasing"] = "G35";
  m.formats["K"] = NumberFormat{6, false, true, true, 1};
  m.formats["I"] = NumberFormat{6, false, true, true, 1};
  StringSink out;
  NcProgram p(m, out);
  p.rapid({10, 2});
  ThreadLead l;
  l.lead = 1.5;
  l.start_angle = 180;
  p.thread({10, -20}, l);  // 22 along Z: K
  p.rapid({40, 0});
  l.start_angle.reset();
  p.thread({20, 0}, l);  // 20 radius = 40 on the diameter along X, 0 along Z: I
  p.rapid({10, 2});
  ThreadLead v;
  v.lead = 2;
  v.lead_change = 0.05;
  p.thread({10, -20}, v);
  p.rapid({10, 2});
  v.lead_change = -0.05;
  p.thread({10, -20}, v);
  EXPECT_EQ(out.out,
            "G0 X20. Z2.\nG33 Z-20. K1.5 SF=180.\nG0 X80. Z0.\nG33 X40. I1.5\nG0 X20. Z2.\n"
            "G34 Z-20. K2. F0.05\nG0 Z2.\nG35 Z-20. K2. F0.05\n");
}

TEST(NcProgram, ThreadsPerInchWord) {
  Machine m = test_machine();
  m.thread_lead_address = "F";
  m.tpi_address = "E";
  m.formats["E"] = NumberFormat{4, false, true, true, 1};
  StringSink out;
  NcProgram p(m, out);
  p.rapid({5, 2});
  ThreadLead l;
  l.lead = 25.4 / 13;
  l.tpi = 13;
  p.thread({5, -20}, l);
  l.tpi = 0;  // a machine without the word, or a metric lead: F
  p.rapid({5, 2});
  p.thread({5, -20}, l);
  EXPECT_EQ(out.out, "G0 X10. Z2.\nG33 Z-20. E13.\nG0 Z2.\nG33 Z-20. F1.954\n");
}

}  // namespace
}  // namespace clpost

namespace clpost {
namespace {

// Issue 14: a template that cannot be written is never silence. Each template writer says why,
// and the message names the machine and the template.
TEST(NcProgramTemplates, EveryWriterReportsAMissingTemplate) {
  Machine m;  // no templates at all
  m.name = "bare";
  StringSink out;
  NcProgram p(m, out);
  const TemplateWrite results[] = {p.start("P", false, "x.cl"),
                                   p.end("P"),
                                   p.tool_change(1, 1, ""),
                                   p.spindle_rpm(100, SpindleDir::kCw),
                                   p.spindle_css(200, 3000, SpindleDir::kCw),
                                   p.spindle_stop(),
                                   p.dwell(1.0, std::nullopt)};
  const char* names[] = {"program_start", "program_end",  "tool_change", "spindle_rpm",
                         "spindle_css",   "spindle_stop", "dwell"};
  for (size_t i = 0; i < std::size(results); ++i) {
    EXPECT_EQ(results[i].status, TemplateWrite::Status::kMissing) << names[i];
    EXPECT_EQ(template_error(m, results[i]),
              fmt::format("machine 'bare' has no template '{0}' (templates.{0} in its machine or "
                          "post file)",
                          names[i]));
  }
  EXPECT_EQ(out.out, "");
}

TEST(NcProgramTemplates, AValueTheCallerCannotKnowAndABadLine) {
  Machine m;
  m.name = "bare";
  m.templates["dwell"] = {"G4 P{revolutions}"};
  m.templates["spindle_rpm"] = {"S{rpm:d}"};  // the loader refuses this: 'd' is not for text
  StringSink out;
  NcProgram p(m, out);
  TemplateWrite r = p.dwell(2.0, std::nullopt);
  EXPECT_EQ(r.status, TemplateWrite::Status::kNoValue);
  EXPECT_EQ(template_error(m, r),
            "machine 'bare': template 'dwell' needs {revolutions}, which is not known here");
  r = p.spindle_rpm(100, SpindleDir::kCw);
  EXPECT_EQ(r.status, TemplateWrite::Status::kBadLine);
  EXPECT_EQ(template_error(m, r),
            "machine 'bare': template 'spindle_rpm' cannot be written: invalid type specifier");
  EXPECT_EQ(out.out, "");
}

// `dwell: []` is the integrator's choice to write nothing: written, no block.
TEST(NcProgramTemplates, AnEmptyTemplateWritesNothing) {
  Machine m;
  m.templates["dwell"] = {};
  StringSink out;
  NcProgram p(m, out);
  EXPECT_EQ(p.dwell(1.0, 10.0).status, TemplateWrite::Status::kWritten);
  EXPECT_EQ(out.out, "");
}

}  // namespace
}  // namespace clpost

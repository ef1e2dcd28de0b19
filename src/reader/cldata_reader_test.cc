// Binary CLDATA: the code tables, layout detection, the reader against the text reader on the
// same program, and damaged input (every error names its record and byte).
#include "reader/cldata_reader.h"

#include <gtest/gtest.h>

#include <array>
#include <cmath>
#include <cstdio>
#include <fstream>
#include <sstream>
#include <string>
#include <vector>

#include "reader/cl_reader.h"
#include "reader/cldata_ncl.h"
#include "reader/cldata_words.h"
#include "reader/cldata_writer.h"

namespace clpost {
namespace {

using cldata::Writer;

// What a reader delivered, as text: one line per statement (form, major, args with kind).
struct Read {
  std::vector<std::string> st;
  std::string diags;
  bool gave_up = false;
};

std::string describe(const Statement& s) {
  std::string d = std::to_string(static_cast<int>(s.form)) + " " + std::string(s.major);
  for (const Arg& a : s.args)
    d += a.is_number() ? " #" + std::string(a.text) + "=" + std::to_string(a.number)
                       : " w" + std::string(a.text);
  if (s.form == Statement::Form::kText) d += " '" + std::string(s.text) + "'";
  return d;
}

Read read_all(std::string_view input) {
  Diagnostics diags("t.cl");
  ClReader r(input, diags);
  Read out;
  Statement st;
  while (r.next(st)) out.st.push_back(describe(st));
  out.diags = diags.render_all();
  out.gave_up = r.gave_up();
  return out;
}

std::string encode(std::string_view apt, cldata::EncodeOptions opts = {}) {
  Diagnostics diags("t.apt");
  std::string bin;
  EXPECT_TRUE(cldata::encode_apt(apt, diags, bin, opts)) << diags.render_all();
  return bin;
}

std::string read_file(const std::string& path) {
  std::ifstream in(path, std::ios::binary);
  std::stringstream s;
  s << in.rdbuf();
  return s.str();
}

std::string real_file() {
  return read_file(CLPOST_SOURCE_DIR "/../shared/realcam/apt360_binary/cl.tap");
}

// Every kind of record the reader turns into a statement, a lathe thread among them.
constexpr std::string_view kEveryRecord = R"(PARTNO SHAFT 12
PPRINT turned, threaded: M20 X 2.5
UNITS/MM
MACHIN/LATHE1
LOADTL/7,ADJUST,7
CUTTER/0.8
TOLER/0.01
INTOL/0.005
OUTTOL/0.005
SPINDL/600,RPM,CLW
COOLNT/FLOOD
FEDRAT/0.2,MMPR
RAPID
FROM/50,0,50
GOTO/15,0,5
GODLTA/0,0,-1
PITCH/2.5,MMPR
THREAD/ON,DEPTH,1.534,CUTS,4,FINCUT,1,0.1,OPTION,1,MMPR,2.5,CHAMFR,2.5
GOTO/10,0,2
GOTO/10,0,-30
THREAD/OFF
PITCH/1.5,MMPR
THREAD/TURN
GOTO/9.2,0,2
GOTO/9.2,0,-20
RAPID
GOTO/15,0,-20
COUPLE/ON
GOTO/9.1,0,-20
GOTO/10.6,0,-21.5
COUPLE/OFF
MULTAX/ON
GOTO/20,0,0,0,0,1
MULTAX/OFF
DELAY/2
INSERT M00 (CHECK)
OPSTOP
STOP
END
FINI
)";

TEST(CldataWords, Tables) {
  EXPECT_EQ(cldata::major_name(1009), "FEDRAT");
  EXPECT_EQ(cldata::major_name(1036), "THREAD");
  EXPECT_EQ(cldata::major_name(1049), "COUPLE");
  EXPECT_EQ(cldata::major_name(1050), "PITCH");
  EXPECT_EQ(cldata::major_name(5), "RAPID");
  EXPECT_EQ(cldata::major_name(1034), "");
  EXPECT_EQ(cldata::major_code("LOADTL"), 1055);
  EXPECT_EQ(cldata::minor_name(71), "ON");
  EXPECT_EQ(cldata::minor_name(27), "TANTO");
  EXPECT_EQ(cldata::minor_code("DSTAN"), 27);
  EXPECT_EQ(cldata::minor_name(60), "CLW");
  EXPECT_EQ(cldata::minor_name(5000), "");
  EXPECT_EQ(cldata::subtype_name(cldata::kMotion, 3), "FROM");
  EXPECT_EQ(cldata::subtype_name(cldata::kTool, 6), "CUTTER");
  EXPECT_EQ(cldata::surface_name(4), "CIRCLE");
}

TEST(CldataLayout, DetectedFromTheFirstBytes) {
  const std::string real = real_file();
  ASSERT_EQ(real.size(), 4681u);
  const cldata::Layout* l = cldata::detect_layout(real);
  ASSERT_NE(l, nullptr);
  EXPECT_EQ(l->name, "APT360");
  EXPECT_EQ(cldata::detect_layout(real.substr(0, 16)), l);
  EXPECT_EQ(cldata::detect_layout(real.substr(0, 15)), nullptr);
  EXPECT_EQ(cldata::detect_layout("GOTO/1,2,3\nFINI\n"), nullptr);
  std::string second_wrong = real;
  second_wrong[32] = 7;  // record 2 numbered 7
  EXPECT_EQ(cldata::detect_layout(second_wrong), nullptr);
  const cldata::RecordHeader h = cldata::read_header(*l, real.data() + 32);
  EXPECT_EQ(h.number, 2);
  EXPECT_EQ(h.length, 11);
  EXPECT_EQ(h.type, 2000);
  EXPECT_EQ(h.subtype, 1045);
}

TEST(CldataReader, GivesTheStatementsOfTheAptText) {
  const Read text = read_all(kEveryRecord);
  ASSERT_EQ(text.diags, "");
  for (size_t per : {1, 2, 50}) {
    const Read bin = read_all(encode(kEveryRecord, {per == 1, per}));
    EXPECT_EQ(bin.diags, "") << per;
    EXPECT_EQ(bin.st, text.st) << per;
  }
  EXPECT_EQ(text.st[0], "2 PARTNO 'SHAFT 12'");
  EXPECT_EQ(text.st[9], "0 SPINDL #600=600.000000 wRPM wCLW");
}

// A layout is data: the same program in the big-endian layout is detected as such and reads
// to the same statements.
TEST(CldataReader, BigEndianLayout) {
  const cldata::Layout& be = cldata::known_layouts()[1];
  ASSERT_FALSE(be.little_endian);
  Writer w(be);
  w.record(cldata::kPostWord, 1009, std::vector<uint64_t>{Writer::number(0.2), Writer::code(916)});
  w.record(cldata::kMotion, 5,
           std::vector<uint64_t>{0, 0, Writer::number(10), 0, Writer::number(-2.5)});
  w.record(cldata::kPostWord, 1045, std::vector<uint64_t>{w.text("SHAFT")});
  w.record(cldata::kFini, 0, {});
  EXPECT_EQ(w.bytes().substr(0, 8), std::string("\0\0\0\1\0\0\0\2", 8));
  EXPECT_EQ(cldata::detect_layout(w.bytes()), &be);
  const Read r = read_all(w.bytes());
  EXPECT_EQ(r.diags, "");
  EXPECT_EQ(r.st, (std::vector<std::string>{"0 FEDRAT #0.2=0.200000 wMMPR",
                                            "0 GOTO #10=10.000000 #0=0.000000 #-2.5=-2.500000",
                                            "2 PARTNO 'SHAFT'", "1 FINI"}));
}

TEST(CldataReader, RealApt360File) {
  const Read r = read_all(real_file());
  EXPECT_EQ(r.diags, "t.cl: record 64 (byte 4664): note: 1 bytes after FINI ignored\n");
  ASSERT_GE(r.st.size(), 10u);
  EXPECT_EQ(r.st[0], "2 PARTNO 'A WINDOW'");
  EXPECT_EQ(r.st[1], "0 MACHIN wPMILL");
  EXPECT_EQ(r.st[2],
            "0 CLRSRF wCLPL #0=0.000000 #0=0.000000 #0=0.000000 #1=1.000000 #0.1=0.100000");
  EXPECT_EQ(r.st[3], "0 CUTTER #0.2=0.200000");
  EXPECT_EQ(r.st[4], "0 SPINDL #3000=3000.000000 wCLW");
  EXPECT_EQ(r.st[5], "1 RAPID");
  EXPECT_EQ(r.st[6], "0 FROM #4=4.000000 #0=0.000000 #0=0.000000");
  EXPECT_EQ(r.st[10], "0 CUTCOM wLENGTH #1=1.000000");
  EXPECT_EQ(r.st.back(), "1 FINI");
  size_t gotos = 0;
  for (const std::string& s : r.st) gotos += s.starts_with("0 GOTO ");
  // 1 (GODLTA) + 1 (GO/TO,C2) + 9 + 14 + 43 + 14 (C3) + 1 (GODLTA) + 6 + 2 points.
  EXPECT_EQ(gotos, 91u);
}

TEST(CldataReader, FileInputGivesWhatMemoryInputGives) {
  const std::string real = real_file();
  std::FILE* f = std::tmpfile();
  ASSERT_NE(f, nullptr);
  std::fwrite(real.data(), 1, real.size(), f);
  std::rewind(f);
  Diagnostics diags("t.cl");
  ClReader r(f, diags);
  std::vector<std::string> st;
  Statement s;
  while (r.next(s)) st.push_back(describe(s));
  std::fclose(f);
  EXPECT_EQ(st, read_all(real).st);
  EXPECT_EQ(r.bytes_read(), real.size());
  EXPECT_EQ(r.line(), 64u);
}

// A file of the given records, FINI last.
std::string records(
    const std::vector<std::pair<std::pair<int64_t, int64_t>, std::vector<uint64_t>>>& recs) {
  Writer w;
  for (const auto& [ts, words] : recs) w.record(ts.first, ts.second, words);
  return w.bytes();
}

TEST(CldataReader, UnknownCodesAreKeptAndUnknownRecordsSkipped) {
  const std::string bin = records({{{2000, 1999}, {Writer::code(71)}},
                                   {{2000, 1030}, {Writer::code(777)}},
                                   {{4000, 1}, {Writer::number(1)}},
                                   {{6000, 1}, {}},
                                   {{14000, 0}, {}}});
  const Read r = read_all(bin);
  EXPECT_EQ(r.st, (std::vector<std::string>{"0 CODE1999 wON", "0 COOLNT wCODE777", "1 FINI"}));
  EXPECT_EQ(r.diags,
            "t.cl: record 3 (byte 48): warning: unknown record type 4000 (subtype 1, 1 words); "
            "skipped\n"
            "t.cl: record 4 (byte 72): warning: unknown subtype of record type 6000 (subtype 1, "
            "0 words); skipped\n");
}

// Found by the fuzz target: a text ending in one '$' would continue the line when its APT text
// is read back, so the '$' is read as '?' (like a byte that is not text), with a warning.
TEST(CldataReader, TextEndingInADollarIsNotAContinuation) {
  Writer w;
  w.record(cldata::kPostWord, 1045, std::vector<uint64_t>{w.text("SHAFT$")});
  w.record(cldata::kPostWord, 1045, std::vector<uint64_t>{w.text("A$$")});
  w.record(cldata::kFini, 0, {});
  const Read r = read_all(w.bytes());
  EXPECT_EQ(r.st, (std::vector<std::string>{"2 PARTNO 'SHAFT?'", "2 PARTNO 'A$$'", "1 FINI"}));
  EXPECT_EQ(r.diags,
            "t.cl: record 1 (byte 0): warning: PARTNO text ends in '$', which APT reads as a "
            "continuation: read as '?'\n");
}

TEST(CldataReader, DamagedInputIsReportedAtItsRecordAndByte) {
  const std::string good =
      records({{{2000, 1009}, {Writer::number(0.2)}},
               {{5000, 5}, {0, 0, Writer::number(1), Writer::number(2), Writer::number(3)}}});
  // Truncated in the middle of the GOTO record (it starts at byte 24).
  Read r = read_all(good.substr(0, good.size() - 4));
  EXPECT_EQ(r.st, (std::vector<std::string>{"0 FEDRAT #0.2=0.200000"}));
  EXPECT_EQ(r.diags,
            "t.cl: record 2 (byte 24): error: truncated record: type 5000 of 5 words (40 bytes), "
            "36 bytes left\n");
  EXPECT_TRUE(r.gave_up);
  // A header cut short.
  r = read_all(good + std::string("\x03\0\0\0\x01", 5));
  EXPECT_EQ(r.diags,
            "t.cl: record 3 (byte 80): error: truncated record: 5 bytes where a 16-byte header "
            "should be\n");
  // An impossible length: reading stops there, nothing hangs or is allocated for it.
  std::string huge = good;
  huge[28] = '\xff', huge[29] = '\xff', huge[30] = '\xff', huge[31] = '\x7f';
  r = read_all(huge);
  EXPECT_EQ(r.diags,
            "t.cl: record 2 (byte 24): error: impossible record length 2147483647 words (type "
            "5000); reading stops here\n");
  // A coordinate that is not a number, and a point cut short.
  const std::string bad =
      records({{{5000, 5}, {0, 0, Writer::number(1), Writer::number(NAN), Writer::number(3)}},
               {{5000, 5}, {0, 0, Writer::number(1), Writer::number(2)}},
               {{5000, 5}, {0, 0, Writer::number(1), Writer::code(71), Writer::number(2)}}});
  r = read_all(bad);
  EXPECT_EQ(r.st, std::vector<std::string>{});
  EXPECT_EQ(r.diags,
            "t.cl: record 1 (byte 40): error: GOTO coordinate 2 is not a finite number\n"
            "t.cl: record 2 (byte 88): error: GOTO record ends in the middle of a point: 2 of 3 "
            "coordinates\n"
            "t.cl: record 3 (byte 144): error: GOTO coordinate 2 is not a number\n");
}

// The statements' APT text (what cl2apt writes) read by the text reader gives them again, for
// words that look like names but are not (a blank inside, digits alone) and texts that start
// with '/'.
TEST(CldataReader, AptTextReadsBackToTheSameStatements) {
  Writer w;
  const auto text_word = [&](std::string_view t) { return w.text(t); };
  const std::string bin =
      records({{{2000, 1044}, {text_word("/X  Y "), text_word("Z")}},
               {{2000, 1015}, {text_word("A WIN"), text_word(" 1234"), text_word(" LATHE")}},
               {{2000, 1045}, {}},
               {{14000, 0}, {}}});
  Diagnostics diags("t.cl");
  CldataReader r(cldata::known_layouts().front(), bin, diags);
  std::vector<std::string> st;
  std::string apt;
  Statement s;
  while (r.next(s)) st.push_back(describe(s)), apt += std::string(s.lines.front()) + "\n";
  EXPECT_EQ(diags.render_all(), "");
  EXPECT_EQ(read_all(apt).st, st);
  EXPECT_EQ(apt.substr(0, apt.find('\n')), "PPRINT //X  Y Z");
  ASSERT_EQ(st.size(), 4u);
  EXPECT_EQ(st[0], "2 PPRINT '/X  Y Z'");
  EXPECT_EQ(st[1].substr(0, 10), "0 MACHIN #");  // "A WIN" is no name: a number
  EXPECT_NE(st[1].find(" wLATHE"), std::string::npos);
  EXPECT_EQ(std::count(st[1].begin(), st[1].end(), '#'), 2);
  EXPECT_EQ(st[2], "2 PARTNO ''");
}

// ---- NCL's layout: 16-bit headers, 36-word physical blocks, its own records and codes ----------

const cldata::Layout& ncl_layout() {
  for (const cldata::Layout& l : cldata::known_layouts())
    if (l.flavor == cldata::Flavor::kNcl) return l;
  ADD_FAILURE() << "no NCL layout";
  return cldata::known_layouts().front();
}

// A lathe program as NCL would write it: its header record, post words with NCL's codes (UNITS
// 841, MMPR 316, FLOOD 89, GOHOME 17, REMARK 1091), a cutter of one parameter, points in records
// that run over the end of a 36-word block, MULTAX/ON and OFF (9000, subtype 0 and 1).
std::string ncl_program(double nan_at = 0) {
  Writer w(ncl_layout());
  const auto n = [](double v) { return Writer::number(v); };
  std::vector<uint64_t> head;
  head.push_back(w.text("SHAFT12"));
  for (int i = 1; i < 10; ++i) head.push_back(w.text(""));
  for (const char* f : {" 5-JAN-2", "021", "17:05:20", "NCLCAM", " 2020.00"})
    head.push_back(w.text(f));
  head.push_back(0);
  w.record(cldata::kNclHeader, 0, head);
  w.record(cldata::kPostWord, 1045, std::vector<uint64_t>{w.text("SHAFT 12")});
  w.record(cldata::kPostWord, 841, std::vector<uint64_t>{Writer::code(296)});
  w.record(cldata::kPostWord, 1055, std::vector<uint64_t>{n(7)});
  w.record(cldata::kTool, 6, std::vector<uint64_t>{n(0.8)});
  w.record(cldata::kPostWord, 1031,
           std::vector<uint64_t>{n(600), Writer::code(78), Writer::code(60)});
  w.record(cldata::kPostWord, 1009, std::vector<uint64_t>{n(0.2), Writer::code(316)});
  w.record(cldata::kPostWord, 1030, std::vector<uint64_t>{Writer::code(89)});
  w.record(cldata::kPostWord, 5, {});
  w.record(cldata::kMotion, 3, std::vector<uint64_t>{n(50), n(0), n(50)});
  std::vector<uint64_t> pts;
  for (int i = 0; i < 6; ++i) pts.insert(pts.end(), {n(20 - i), n(0), n(5 - i)});
  w.record(cldata::kMotion, 5, pts);
  pts.clear();
  for (int i = 0; i < 5; ++i) pts.insert(pts.end(), {n(14), n(0), n(-1 - i)});
  if (nan_at != 0) pts[static_cast<size_t>(nan_at)] = n(NAN);
  w.record(cldata::kMotion, 5, pts);
  w.record(cldata::kMultiAxis, 0, {});
  w.record(cldata::kMotion, 5, std::vector<uint64_t>{n(20), n(0), n(0), n(0), n(0), n(1)});
  w.record(cldata::kMultiAxis, 1, {});
  w.record(cldata::kPostWord, 17, {});
  w.record(cldata::kPostWord, 1091, std::vector<uint64_t>{w.text("END OF"), w.text(" SHAFT")});
  w.record(cldata::kFini, 0, {});
  return w.bytes();
}

TEST(CldataLayout, NclDetectedFromItsHeaderRecord) {
  const std::string bin = ncl_program();
  EXPECT_EQ(bin.size(), 3 * 288u);  // the last block filled up after FINI
  EXPECT_EQ(cldata::detect_layout(bin), &ncl_layout());
  EXPECT_EQ(cldata::detect_layout(bin.substr(0, 8)), &ncl_layout());
  EXPECT_EQ(cldata::detect_layout(real_file()), &cldata::known_layouts().front());
  // Not NCL's header (type 7300), or too short a one to hold name, date, time and version.
  std::string other = bin;
  other[2] = static_cast<char>(7300 & 0xff), other[3] = static_cast<char>(7300 >> 8);
  EXPECT_EQ(cldata::detect_layout(other), nullptr);
  other = bin;
  other[0] = 10;
  EXPECT_EQ(cldata::detect_layout(other), nullptr);
  const cldata::RecordHeader h = cldata::read_header(ncl_layout(), bin.data() + 136);
  EXPECT_EQ(h.length, 1);  // PARTNO: a word count of 2, the header counted
  EXPECT_EQ(h.type, 2000);
  EXPECT_EQ(h.subtype, 1045);
  EXPECT_EQ(h.isn, 2);
}

TEST(CldataReader, NclRecordsAndCodes) {
  const Read r = read_all(ncl_program());
  EXPECT_EQ(r.diags, "");
  EXPECT_EQ(
      r.st,
      (std::vector<std::string>{
          "2 REMARK 'SHAFT12      5-JAN-2021  17:05:20  NCLCAM     2020.00'",
          "2 PARTNO 'SHAFT 12'",
          "0 UNITS wMM",
          "0 LOADTL #7=7.000000",
          "0 CUTTER #0.8=0.800000 #0=0.000000 #0=0.000000 #0=0.000000 #0=0.000000 #0=0.000000 "
          "#0=0.000000",
          "0 SPINDL #600=600.000000 wRPM wCLW",
          "0 FEDRAT #0.2=0.200000 wMMPR",
          "0 COOLNT wFLOOD",
          "1 RAPID",
          "0 FROM #50=50.000000 #0=0.000000 #50=50.000000",
          "0 GOTO #20=20.000000 #0=0.000000 #5=5.000000",
          "0 GOTO #19=19.000000 #0=0.000000 #4=4.000000",
          "0 GOTO #18=18.000000 #0=0.000000 #3=3.000000",
          "0 GOTO #17=17.000000 #0=0.000000 #2=2.000000",
          "0 GOTO #16=16.000000 #0=0.000000 #1=1.000000",
          "0 GOTO #15=15.000000 #0=0.000000 #0=0.000000",
          "0 GOTO #14=14.000000 #0=0.000000 #-1=-1.000000",
          "0 GOTO #14=14.000000 #0=0.000000 #-2=-2.000000",
          "0 GOTO #14=14.000000 #0=0.000000 #-3=-3.000000",
          "0 GOTO #14=14.000000 #0=0.000000 #-4=-4.000000",
          "0 GOTO #14=14.000000 #0=0.000000 #-5=-5.000000",
          "0 MULTAX wON",
          "0 GOTO #20=20.000000 #0=0.000000 #0=0.000000 #0=0.000000 #0=0.000000 #1=1.000000",
          "0 MULTAX wOFF",
          "1 GOHOME",
          "2 REMARK 'END OF   SHAFT'",
          "1 FINI",
      }));
  // From a FILE*, in chunks, as `clpost part.cl` reads it: the same, every byte counted.
  const std::string bin = ncl_program();
  std::FILE* f = std::tmpfile();
  ASSERT_NE(f, nullptr);
  std::fwrite(bin.data(), 1, bin.size(), f);
  std::rewind(f);
  Diagnostics diags("t.cl");
  ClReader file_reader(f, diags);
  std::vector<std::string> st;
  Statement s;
  while (file_reader.next(s)) st.push_back(describe(s));
  std::fclose(f);
  EXPECT_EQ(st, r.st);
  EXPECT_EQ(file_reader.bytes_read(), bin.size());
  EXPECT_EQ(diags.render_all(), "");
}

// The records' APT text (cl2apt) reads back to the same statements: REMARK is a text statement
// for the text reader too.
TEST(CldataReader, NclAptTextReadsBack) {
  Diagnostics diags("t.cl");
  const std::string bin = ncl_program();
  CldataReader r(ncl_layout(), bin, diags);
  std::vector<std::string> st;
  std::string apt;
  Statement s;
  while (r.next(s)) st.push_back(describe(s)), apt += std::string(s.lines.front()) + "\n";
  EXPECT_EQ(read_all(apt).st, st);
  EXPECT_EQ(apt.substr(0, apt.find('\n')),
            "REMARK SHAFT12      5-JAN-2021  17:05:20  NCLCAM     2020.00");
  EXPECT_NE(apt.find("\nCUTTER/0.8,0,0,0,0,0,0\n"), std::string::npos) << apt;
}

// Locations are the file's bytes: the unused word that ends each 288-byte block is counted.
TEST(CldataReader, NclDiagnosticsNameTheFileByte) {
  // The second GOTO record's header is file word 59 (byte 472); its words follow, word 71 (the
  // last of the second block) left out: point 5's Y, its word 13, is file word 74, byte 592.
  Read r = read_all(ncl_program(13));
  EXPECT_EQ(r.diags,
            "t.cl: record 12 (byte 592): error: GOTO coordinate 2 is not a finite number\n");
  // Cut inside that record: truncated, at the record's own byte.
  const std::string bin = ncl_program();
  r = read_all(bin.substr(0, 560));
  EXPECT_EQ(r.diags,
            "t.cl: record 12 (byte 472): error: truncated record: type 5000 of 15 words (120 "
            "bytes), 80 bytes left\n");
  // A MULTAX record of another subtype: the points after it cannot be read.
  std::string multax = bin;
  const size_t at = multax.find(std::string("\x01\x00\x28\x23", 4));
  ASSERT_NE(at, std::string::npos);
  multax[at + 4] = 5;
  r = read_all(multax);
  EXPECT_EQ(r.diags,
            "t.cl: record 13 (byte " + std::to_string(at) +
                "): error: MULTAX record of subtype 5: NCL writes 0 (ON) or 1 (OFF); the points "
                "after it could not be read\n");
}

TEST(CldataNcl, CutterAsAptWritesIt) {
  using A = std::array<double, 7>;
  // upside_down.cl's cutter: diameter, corner radius, height.
  EXPECT_EQ(cldata::ncl_apt_cutter(std::vector<double>{0.75, 0.125, 2.25}),
            (A{0.75, 0.125, 0.25, 0.125, 0, 0, 2.25}));
  EXPECT_EQ(cldata::ncl_apt_cutter(std::vector<double>{10}), (A{10, 0, 0, 0, 0, 0, 0}));
  // A cone cutter of side angle 90 - 2·45: the diameter where APT measures it.
  const A cone = cldata::ncl_apt_cutter(std::vector<double>{10, 1, 20, 0.0 + 0});
  EXPECT_EQ(cone, (A{10, 1, 4, 1, 0, 0, 20}));
  const A c45 = cldata::ncl_apt_cutter(std::vector<double>{10, 1, 20, 45});
  EXPECT_NEAR(c45[0], 10 - 2 + 2 * std::tan(22.5 * M_PI / 180), 1e-12);
  EXPECT_EQ(c45[2], 4);
  EXPECT_EQ(c45[5], 45);
  // Five parameters and more: APT's order.
  EXPECT_EQ(cldata::ncl_apt_cutter(std::vector<double>{10, 1, 20, 2, 3, 4}),
            (A{10, 2, 3, 3, 1, 4, 20}));
}

// The fuzz target's seeds (fuzz/seeds/cldata/) are the files these tests write and read: the
// test fails when one is stale; CLPOST_WRITE_SEEDS=1 rewrites them.
TEST(CldataReader, FuzzSeedsAreTheFilesTheTestsWrite) {
  const std::string dir = CLPOST_SOURCE_DIR "/fuzz/seeds/cldata/";
  const std::vector<std::pair<std::string, std::string>> seeds = {
      {"every_record.bin", encode(kEveryRecord)},
      {"every_record_merged.bin", encode(kEveryRecord, {false, 50})},
      {"thread_m20.bin", encode(read_file(CLPOST_SOURCE_DIR "/samples/thread-m20.apt"))},
      {"ncl_program.bin", ncl_program()}};
  for (const auto& [name, bytes] : seeds) {
    if (std::getenv("CLPOST_WRITE_SEEDS") != nullptr)
      std::ofstream(dir + name, std::ios::binary) << bytes;
    EXPECT_TRUE(read_file(dir + name) == bytes)
        << name << " is stale: run reader_tests with CLPOST_WRITE_SEEDS=1";
    EXPECT_EQ(read_all(bytes).diags, "") << name;
  }
}

}  // namespace
}  // namespace clpost

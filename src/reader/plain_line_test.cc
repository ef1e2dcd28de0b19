// The fast path must give exactly what the general lexer gives, or decline.
#include "reader/plain_line.h"

#include <gtest/gtest.h>

#include <cstdint>
#include <cstring>
#include <string>
#include <vector>

#include "reader/continuation.h"
#include "reader/lexer.h"

namespace clpost::reader {
namespace {

bool operator==(SourceLoc a, SourceLoc b) {
  return a.line == b.line && a.col == b.col;
}

uint64_t bits(double d) {
  uint64_t b;
  std::memcpy(&b, &d, sizeof b);
  return b;
}

// Lexes `line` both ways. False when the fast path declined; otherwise checks that the general
// path reads the same statement, field by field (numbers bit for bit).
bool fast_agrees(std::string_view line) {
  constexpr uint32_t kLine = 7;
  Statement fast;
  fast.args.push_back(Arg{});  // leftovers from an earlier statement must go
  fast.modifiers.push_back(Arg{});
  fast.nested.push_back(Arg{});
  fast.problem.message = "old";
  const std::string input = std::string(line) + "\nNEXT/1\n";
  PlainLine plain;
  if (!lex_plain_line(input, kLine, fast, plain)) return false;
  EXPECT_EQ(plain.size, line.size()) << line;
  EXPECT_EQ(plain.terminator, 1u) << line;

  // What ClReader checks before the general lexer: none of it may apply to a plain line.
  EXPECT_FALSE(is_blank_line(line)) << line;
  EXPECT_FALSE(is_comment_line(line)) << line;
  EXPECT_FALSE(StatementLexer::is_text_statement(line)) << line;
  bool continues = true;
  EXPECT_EQ(code_part(line, &continues), line) << line;
  EXPECT_FALSE(continues) << line;

  Statement general;
  general.first_line = kLine;
  general.lines.assign(1, line);
  StatementLexer lexer;
  StatementLexer::Error err;
  EXPECT_EQ(lexer.lex_code(general, err), StatementLexer::Result::kOk)
      << line << ": " << err.message;
  EXPECT_EQ(fast.form, general.form) << line;
  EXPECT_EQ(fast.major, general.major) << line;
  EXPECT_TRUE(fast.loc == general.loc) << line;
  EXPECT_EQ(fast.text, general.text) << line;
  EXPECT_EQ(fast.source, general.source) << line;
  EXPECT_TRUE(fast.modifiers.empty()) << line;
  EXPECT_TRUE(general.modifiers.empty()) << line;
  EXPECT_TRUE(fast.nested.empty()) << line;
  EXPECT_TRUE(general.nested.empty()) << line;
  EXPECT_FALSE(fast.has_problem()) << line;
  EXPECT_FALSE(general.has_problem()) << line << ": " << general.problem.message;
  EXPECT_EQ(fast.first_line, general.first_line) << line;
  EXPECT_EQ(fast.lines, general.lines) << line;
  EXPECT_EQ(fast.args.size(), general.args.size()) << line;
  for (size_t i = 0; i < fast.args.size() && i < general.args.size(); ++i) {
    const Arg& a = fast.args[i];
    const Arg& b = general.args[i];
    EXPECT_EQ(a.kind, b.kind) << line << " arg " << i;
    EXPECT_EQ(a.text, b.text) << line << " arg " << i;
    EXPECT_EQ(bits(a.number), bits(b.number)) << line << " arg " << i;
    EXPECT_TRUE(a.loc == b.loc) << line << " arg " << i;
  }
  return true;
}

TEST(PlainLine, TakesPlainRecordsAndBareWords) {
  for (const char* line :
       {"GOTO/40.0000,0.0000,5.0000", "GOTO/1.,.5,-0.5,+2,-.5,-0", "LOADTL/1,ADJUST,1",
        "SPINDL/1200,RPM,CLW", "TOOL_PATH/OP_10,TOOL,MILL_0.120RAD", "RAPID", "END-OF-PATH", "FINI",
        "GOTO/123456789012345,0.12345678901234", "THREAD/ON,DEPTH,1.534,CUTS,4", "PARTNOX/1",
        "INSERTS", "A/B-C.D_E"}) {
    EXPECT_TRUE(fast_agrees(line)) << line;
  }
}

TEST(PlainLine, DeclinesEverythingElse) {
  // Each of these is either an error (reported by the general path, at its line and column) or
  // needs what only the general path does (continuations, comments, blanks, case, exponents).
  for (const char* line : {"",
                           " ",
                           "\t",
                           "GOTO/1,2,",
                           "GOTO/1,2,$",
                           "GOTO/1 $",
                           "GOTO/1$$ note",
                           "$$ comment",
                           "GOTO / 1, 2",
                           " GOTO/1",
                           "GOTO/1 ",
                           "GOTO/1\t",
                           "goto/1",
                           "GOTO/clw",
                           "Goto/1",
                           "GOTO/1e400",
                           "GOTO/1e3",
                           "GOTO/--1",
                           "GOTO/1.2.3",
                           "GOTO/+",
                           "GOTO/.",
                           "GOTO/-",
                           "GOTO/1,,2",
                           "GOTO/,1",
                           "GOTO//1",
                           "GOTO/1/2",
                           "GOTO/",
                           "GOTO/1234567890123456",
                           "GOTO/0.1234567890123456",
                           "GOTO/10_SVERL",
                           "GOTO/1a",
                           "GOTO/A+B",
                           "GOTO/A(B)",
                           "GOTO/1,\"S\"",
                           "PARTNO",
                           "PARTNO/X",
                           "PPRINT/HELLO",
                           "INSERT/G4",
                           "TPRINT/T1",
                           "CHANNEL,1",
                           "TLON,GOFWD/1",
                           "PITCH/(1/2.5)",
                           "GOTO/-(1)",
                           "SYN/'A'",
                           "P1=POINT/1",
                           "1GOTO/1",
                           "_A/1",
                           "GOTO/1\f",
                           "GOTO/1,2\v",
                           "G\xC3\x96TO/1",
                           "GOTO/1;",
                           "GOTO/-inf",
                           "GOTO/nan"}) {
    EXPECT_FALSE(fast_agrees(line)) << line;
  }
}

TEST(PlainLine, LineEnds) {
  Statement st;
  PlainLine plain;
  ASSERT_TRUE(lex_plain_line("GOTO/1,2\r\nX\n", 3, st, plain));
  EXPECT_EQ(plain.size, 8u);
  EXPECT_EQ(plain.terminator, 2u);
  EXPECT_EQ(st.lines[0], "GOTO/1,2");
  ASSERT_TRUE(lex_plain_line("RAPID\rGOTO/1\n", 3, st, plain));  // a lone CR
  EXPECT_EQ(plain.size, 5u);
  EXPECT_EQ(plain.terminator, 1u);
  EXPECT_EQ(st.major, "RAPID");
  ASSERT_TRUE(lex_plain_line("RAPID\n", 3, st, plain));
  EXPECT_EQ(plain.terminator, 1u);
  // No line end in the input yet (the end of a chunk, or the last line of the file), or a CR
  // that may be the start of a CRLF: the general path reads it.
  EXPECT_FALSE(lex_plain_line("", 3, st, plain));
  EXPECT_FALSE(lex_plain_line("GOTO/1,2", 3, st, plain));
  EXPECT_FALSE(lex_plain_line("GOTO/1,2\r", 3, st, plain));
  EXPECT_FALSE(lex_plain_line("GOTO/1,2\rX", 3, st, plain));  // a '\n' is needed too
}

// Random lines near plain ones: whatever the fast path takes, the general path reads the same.
TEST(PlainLine, RandomLinesAgreeWithTheGeneralLexer) {
  const std::vector<std::string> seeds = {
      "GOTO/40.0000,0.0000,5.0000", "LOADTL/1,ADJUST,1", "RAPID",           "END-OF-PATH",
      "CIRCLE/1.,.5,-0.5,+2",       "PPRINT/X",          "FEDRAT/0.25,MMPR"};
  static constexpr char kAlphabet[] = " \t$,./-+eE0123456789aAZz_\"'()*=";
  uint64_t x = 0x9E3779B97F4A7C15ull;  // xorshift64: deterministic
  auto next = [&x](uint64_t n) {
    x ^= x << 13, x ^= x >> 7, x ^= x << 17;
    return x % n;
  };
  size_t taken = 0;
  for (int i = 0; i < 200000; ++i) {
    std::string line = seeds[next(seeds.size())];
    for (int m = static_cast<int>(next(4)); m >= 0; --m) {
      const size_t at = next(line.size() + 1);
      const char c = kAlphabet[next(sizeof kAlphabet - 1)];
      switch (next(3)) {
        case 0:
          line.insert(at, 1, c);
          break;
        case 1:
          if (at < line.size()) line.erase(at, 1);
          break;
        default:
          if (at < line.size()) line[at] = c;
          break;
      }
    }
    if (fast_agrees(line)) ++taken;
    if (HasFailure()) break;
  }
  EXPECT_GT(taken, 10000u);  // the mutations leave many lines plain
}

}  // namespace
}  // namespace clpost::reader

#pragma once
// One APT/CL statement as the reader delivers it. Views point into the reader's buffers and stay
// valid until the next call to ClReader::next().
#include <cstdint>
#include <span>
#include <string>
#include <string_view>
#include <vector>

#include "support/source_loc.h"

namespace clpost {

struct Arg {
  enum class Kind : uint8_t {
    kWord,        // ON, MMPR, 1STPECK
    kNumber,      // 2.5, and an arithmetic expression: (1/2.5)
    kEmpty,       // nothing between two commas (`ANGLE,,PITCH`) or after a last comma
    kText,        // a quoted text: 'TLAXIS', "N"
    kDefinition,  // a nested definition: (CIRCLE/25,0,-30,4.6)
  };
  Kind kind = Kind::kWord;
  // words: upper-cased; numbers: as written (an expression with its parentheses: "(1/2.5)");
  // text: between the quotes, as written; definitions: their major word, upper-cased; empty: "".
  std::string_view text;
  // Definitions: their arguments are Statement::nested[first, first + count) (see
  // Statement::args_of), themselves possibly definitions. Sharing the number's room keeps an
  // argument at 40 bytes, which the plain GOTO path copies three times a line.
  struct Span {
    uint32_t first;
    uint32_t count;
  };
  union {
    double number = 0;  // numbers only (an expression: its value)
    Span def;           // definitions only
  };
  SourceLoc loc;  // where the argument starts (a definition: its '(')

  bool is_word() const { return kind == Kind::kWord; }
  bool is_number() const { return kind == Kind::kNumber; }
  bool is_empty() const { return kind == Kind::kEmpty; }
  bool is_text() const { return kind == Kind::kText; }
  bool is_definition() const { return kind == Kind::kDefinition; }
  bool is(std::string_view word) const { return kind == Kind::kWord && text == word; }
};

// A lexical problem in a statement that still has a major word: the statement is delivered, with
// no arguments, and the interpreter decides (an unknown word becomes a warning and a comment
// holding `source`; a known one an error here).
struct LexProblem {
  SourceLoc loc;
  std::string message;
};

static_assert(sizeof(Arg) <= 40);

struct Statement {
  enum class Form : uint8_t {
    kRecord,  // MAJOR/arg,arg,...   (args filled; `RAPID/` is a record with no args); also the
              // comma form `CHANNEL,1` (no '/': the first ',' stands for it)
    kBare,    // MAJOR alone on its line: RAPID, END, FINI, STOP, END-OF-PATH ...
    kText,    // PARTNO, PPRINT, INSERT, TPRINT, REMARK: `text` holds the rest of the line verbatim
  };
  Form form = Form::kBare;
  std::string_view major;  // upper-cased; inner runs of blanks collapsed to one ("TOOL PATH")
  SourceLoc loc;           // of the major word
  std::vector<Arg> args;
  // kText: everything after the major word (and its optional '/'), continuation lines joined,
  // leading and trailing blanks trimmed, case kept. kRecord: the arguments as written (after
  // the '/' or the first ','), trimmed. kBare: empty.
  std::string_view text;
  // The whole statement as written: the code of its lines joined (comments and continuation
  // `$` removed), trimmed; a text statement: its first line.
  std::string_view source;
  // Words written before the major word, in order: `TLON,GOFWD/…` is GOFWD with modifier TLON
  // (APT's motion statements), `RAPID,GOTO/…` GOTO with modifier RAPID.
  std::vector<Arg> modifiers;
  std::vector<Arg> nested;  // the arguments of nested definitions (Arg::first, Arg::count)
  LexProblem problem;       // message empty: none

  bool has_problem() const { return !problem.message.empty(); }
  std::span<const Arg> args_of(const Arg& definition) const {
    return std::span<const Arg>(nested).subspan(definition.def.first, definition.def.count);
  }

  // The physical lines this statement was read from (continuations included), for diagnostics.
  uint32_t first_line = 0;
  std::vector<std::string_view> lines;
  std::string_view line_text(uint32_t line) const {
    if (line < first_line || line - first_line >= lines.size()) return {};
    return lines[line - first_line];
  }
};

}  // namespace clpost

namespace clpost {

// An owned copy of a statement's physical lines, for diagnostics issued after the reader has
// moved on (e.g. a THREAD/ON error found at THREAD/OFF).
struct SavedLines {
  uint32_t first_line = 0;
  std::vector<std::string> lines;

  static SavedLines of(const Statement& st) {
    SavedLines s;
    s.first_line = st.first_line;
    s.lines.assign(st.lines.begin(), st.lines.end());
    return s;
  }
  std::string_view text(uint32_t line) const {
    if (line < first_line || line - first_line >= lines.size()) return {};
    return lines[line - first_line];
  }
};

// Text for a message: control and non-ASCII bytes as \xNN, long text cut; quoted: between '…'.
std::string shown(std::string_view s);
std::string quoted(std::string_view s);

// What argument `i` of `args` is, for "found …" in messages: 'WORD', number 2.5, the text 'A B',
// (CIRCLE/…), an empty argument, the end of the statement after ',' (an empty last argument),
// the end of the statement (no argument `i`). Never an empty ''. `whole`: what `args` are the
// arguments of ("the definition" for a nested one's).
std::string describe_arg(std::span<const Arg> args, size_t i,
                         std::string_view whole = "the statement");
// The same for `a`, one of `st.args`.
std::string describe_arg(const Statement& st, const Arg& a);

}  // namespace clpost

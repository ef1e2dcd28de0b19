#pragma once
// Turns the physical lines of one statement into a Statement: major word, form, arguments with
// their line and column. Knows nothing of files or buffers; ClReader finds the lines.
//
// The code of continued lines is joined as APT card images are: `0$` + `.000000` is the number
// 0.000000, `Turning Tool$` + ` Assembly.1` one text. Locations still name the physical line
// and column of each character.
#include <cstdint>
#include <string>
#include <string_view>
#include <vector>

#include "reader/statement.h"
#include "support/source_loc.h"

namespace clpost::reader {

class StatementLexer {
 public:
  struct Error {
    SourceLoc loc;
    std::string message;
  };
  enum class Result { kOk, kEmpty, kError };

  // PARTNO, PPRINT, INSERT, TPRINT, REMARK (any case) as the first word of `line`, followed by a
  // blank, a '/' or nothing: the rest of the statement is text, not arguments.
  static bool is_text_statement(std::string_view line);

  // `st.first_line` and `st.lines` (a statement's physical lines, continuations included) are
  // set; fills in the rest. kEmpty: the lines hold no code at all. kError: no major word (`err`
  // says what is there). A statement with a major word is always kOk; a problem in the rest of
  // it is delivered in `st.problem` (reader/statement.h), with no arguments.
  Result lex_code(Statement& st, Error& err);
  // The same for a text statement: its lines (a line ending in a single `$` continues).
  void lex_text(Statement& st);

 private:
  // A piece of the joined code: src_[offset, next piece) comes from line `line` (an index in
  // st.lines), column 1 on.
  struct Piece {
    size_t offset;
    uint32_t line;
  };

  void join(const Statement& st, bool text);
  SourceLoc loc_at(size_t pos) const;
  SourceLoc loc() const { return loc_at(pos_); }
  bool at_end();  // after skipping blanks
  char cur() const { return src_[pos_]; }
  std::string_view token() const;  // from the cursor to the next blank , / ( )
  std::string_view add_upper(std::string_view text);
  std::string_view major_word();
  bool head(Statement& st);
  bool modifiers(Statement& st, size_t after_comma);
  bool lex_args(Statement& st, std::vector<Arg>& out, int depth);
  bool lex_arg(Statement& st, std::vector<Arg>& out, int depth);
  bool lex_paren(Statement& st, std::vector<Arg>& out, int depth);
  bool lex_definition(Statement& st, std::vector<Arg>& out, int depth);
  bool lex_expression(Statement& st, std::vector<Arg>& out);
  static bool problem(Statement& st, SourceLoc at, std::string message);

  std::string words_;   // upper-cased words; reserved up front so that views into it stay valid
  std::string joined_;  // the joined code of a statement of several lines
  std::string_view src_;
  std::vector<Piece> pieces_;
  std::vector<Arg> scratch_;  // arguments of the nested definitions being read
  uint32_t first_line_ = 0;
  size_t pos_ = 0;
};

}  // namespace clpost::reader

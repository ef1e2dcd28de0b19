#pragma once
// Turns the physical lines of one statement into a Statement: major word, form, arguments with
// their line and column. Knows nothing of files or buffers; ClReader finds the lines.
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

  // PARTNO, PPRINT, INSERT (any case) as the first word of `line`, followed by a blank, a '/' or
  // nothing: the rest of the line is text, not arguments.
  static bool is_text_statement(std::string_view line);

  // `st.first_line` and `st.lines` (a statement's physical lines, continuations included) are
  // set; fills in the rest. kEmpty: the lines hold no code at all. kError: `err` says what is
  // wrong (the first problem only).
  Result lex_code(Statement& st, Error& err);
  // The same for a text statement (one line).
  void lex_text(Statement& st);

 private:
  bool at_end();  // after skipping blanks and line ends
  char cur() const { return code_[li_][pos_]; }
  SourceLoc loc() const { return SourceLoc{first_line_ + li_, static_cast<uint32_t>(pos_ + 1)}; }
  std::string_view token() const;  // from the cursor to the next blank, ',' or '/'
  bool lex_arg(Statement& st, Error& err);
  bool fail(Error& err, SourceLoc loc, std::string message);
  std::string_view add_upper(std::string_view text);
  void start(const Statement& st);

  std::string words_;  // upper-cased words; reserved up front so that views into it stay valid
  std::vector<std::string_view> code_;  // the code part of each line
  uint32_t first_line_ = 0;
  uint32_t li_ = 0;  // cursor: line index in code_
  size_t pos_ = 0;   // cursor: byte in that line
};

}  // namespace clpost::reader

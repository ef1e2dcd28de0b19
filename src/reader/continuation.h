#pragma once
// Where the APT code on a physical line ends (`$$` comments) and whether the statement goes on
// to the next line (`$` continuation). Two forms of the same rules: on a whole line in memory,
// and streaming (LineTail) for lines too long to keep.
//
// A quoted argument (`'…'` or `"…"` opened where an argument starts: after `/`, `,` or `(`, or
// at the start of a line) may hold `$$` (`SYN/'TLAXIS','$$*TLAXIS'`): it does not start a
// comment there. A quote elsewhere (`PART_OPE/Phase d'usinage.1`) is an ordinary character.
// A quote is closed at the end of its line (a quoted text continued with `$` whose next line
// holds `$$` is not supported).
#include <string_view>

namespace clpost::reader {

inline bool is_blank_char(char c) {
  return c == ' ' || c == '\t';
}

// Only blanks and tabs (or nothing).
bool is_blank_line(std::string_view line);

// The first non-blank characters are `$$`.
bool is_comment_line(std::string_view line);

// The code of a statement line: what comes before the first `$$` outside quotes, trailing
// blanks removed, and a last `$` (continuation) removed; `*continues` says whether there was
// one. Blanks before that `$` are kept: `Turning Tool $` + `Assembly.1` is `Turning Tool
// Assembly.1`.
std::string_view code_part(std::string_view line, bool* continues);

// A whole-line `$$` comment (or a line continuing one), and a text statement (PPRINT, PARTNO,
// INSERT, TPRINT: `$$` is text there), continue on the next line when the last non-blank
// character is a single `$` (`$$-> CSYS / 1.0, $`), not `$$`.
bool comment_continues(std::string_view line);

// The same answers as code_part() and comment_continues(), fed a line piece by piece.
class LineTail {
 public:
  void feed(std::string_view bytes);
  bool code_continues() const { return code_last_ == '$'; }
  bool comment_continues() const { return last_ == '$' && before_last_ != '$'; }

 private:
  bool in_comment_ = false;
  bool arg_start_ = true;  // a quote here opens a quoted argument
  char quote_ = 0;         // the open quote, or 0
  bool dollar_ = false;    // the byte before is a `$` outside quotes
  char prev_ = 0;          // the byte before the current one
  char code_last_ = 0;     // last non-blank byte before the first `$$`
  char code_saved_ = 0;    // code_last_ before the latest `$` (undone when `$$` starts)
  char last_ = 0;          // last non-blank byte
  char before_last_ = 0;   // the byte just before last_
};

}  // namespace clpost::reader

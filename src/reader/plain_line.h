#pragma once
// The reader's fast path. Most lines of a CL file are plain records such as
// `GOTO/40.0000,0.0000,5.0000` or `LOADTL/1,ADJUST,1`, or a bare word (`RAPID`). Such a line is
// lexed here in one pass straight from the input buffer — finding its end, its words and its
// numbers at once — without the general path's line splitting, continuation handling, word
// buffer and error reporting. Anything else (blanks, `$`, lower case, a word that starts with a
// digit, an exponent, an empty or trailing argument, more than 15 digits, any error) is declined
// and left to the general path (LineSource + StatementLexer), so the result is always exactly
// the one the general path would give.
#include <cstddef>
#include <cstdint>
#include <string_view>

#include "reader/statement.h"

namespace clpost::reader {

struct PlainLine {
  size_t size = 0;        // bytes of the line, without its terminator
  size_t terminator = 0;  // 1 (LF or a lone CR) or 2 (CRLF)
};

// `input` starts at the beginning of physical line `line_no`. When that line is plain — `MAJOR`
// or `MAJOR/arg,arg,...`, MAJOR in [A-Z][A-Z0-9_-]* and not a text statement (PARTNO, PPRINT,
// INSERT, TPRINT), each argument a number `[+-]digits[.digits]` (at most 15 digits) or an
// upper-case word `[A-Z][A-Z0-9_.-]*` — and its line end is in `input` (a CR as the last byte of
// `input` is not enough: CRLF or CR cannot be told yet), fills `st` (views into `input`) and
// `line`, and returns true. Otherwise returns false; `st` may then have been changed and must be
// filled by the general path.
bool lex_plain_line(std::string_view input, uint32_t line_no, Statement& st, PlainLine& line);

}  // namespace clpost::reader

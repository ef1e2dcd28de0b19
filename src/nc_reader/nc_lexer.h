#pragma once
// Reads one line of an NC program in a machine's dialect into an NcBlock: the block number
// (block_numbers.address), comments (comments.open / close, ISO `( )` too, `;` to the end of the
// line), words (an address of one or more letters, an optional '=', a number: "X-20.", "IC3",
// "SF=180", "G0X20Z5" unspaced too), bare words ("DIAMON", "MACHINING") and calls
// ("CYCLE99(0, 24, ...)").
#include <string>
#include <string_view>

#include "machine/machine.h"
#include "nc_reader/nc_block.h"

namespace clpost {

// What of a machine's dialect the lexer needs.
struct NcSyntax {
  std::string block_address = "N";  // "N", "N " (block numbers are dropped)
  std::string comment_open = "(";
  std::string comment_close = ")";  // "" = to the end of the line
};

NcSyntax nc_syntax(const Machine& m);

struct NcLexError {
  uint32_t col = 0;  // 1-based
  std::string message;
};

// Reads `line` (without its terminator) into `block` (cleared first). Returns false with `error`
// on text that is not NC: an invalid number, an unterminated comment or call, a stray character.
bool lex_nc_line(std::string_view line, uint32_t line_no, const NcSyntax& syntax, NcBlock& block,
                 NcLexError& error);

}  // namespace clpost

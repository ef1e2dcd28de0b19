#pragma once
// One NC block (line) as read back from a program: its words in order, a subroutine call's
// arguments, its comments. What nc_lexer makes and the control simulation (simulator/) runs.
#include <cstdint>
#include <string>
#include <string_view>
#include <vector>

namespace clpost {

struct NcWord {
  std::string address;  // "X", "G", "IC", "SF=" (with the '=' when the program wrote one)
  std::string text;     // the number as written: "-20.", "010060" ("" for a bare word)
  double value = 0;     // the number's value (as written, no format scale applied)
  uint32_t col = 0;     // 1-based column of the address
  bool has_value() const { return !text.empty(); }
};

struct NcCall {
  std::string name;               // "CYCLE99"
  std::vector<std::string> args;  // each argument's text, trimmed ("" for an empty one)
  std::vector<uint32_t> cols;     // each argument's column
  uint32_t col = 0;               // column of the name
};

struct NcBlock {
  uint32_t line = 0;
  std::vector<NcWord> words;  // block number excluded
  std::vector<NcCall> calls;
  std::vector<std::string> comments;
  bool program_delimiter = false;  // a '%' line
  bool block_delete = false;       // it starts with the block delete mark ('/'): optional
  // The one-letter addresses among the words, a bit each ('A' is bit 0): a look-up for a letter
  // the block has not is answered at once (a block has few words, a simulation asks it for some
  // twenty codes). Set by lex_nc_line with the words.
  uint32_t letters = 0;

  // The bit of `address` in `letters`, or 0 when it is not one letter A-Z.
  static uint32_t letter_bit(std::string_view address) {
    return address.size() == 1 && address[0] >= 'A' && address[0] <= 'Z'
               ? uint32_t{1} << (address[0] - 'A')
               : 0;
  }
  // False when the block has no word of `address` for sure.
  bool may_have(std::string_view address) const {
    const uint32_t bit = letter_bit(address);
    return bit == 0 || (letters & bit) != 0;
  }
  const NcWord* find(std::string_view address) const {
    if (const uint32_t bit = letter_bit(address); bit != 0) {
      if ((letters & bit) == 0) return nullptr;
      for (const NcWord& w : words)
        if (w.address.size() == 1 && w.address[0] == address[0]) return &w;
      return nullptr;
    }
    for (const NcWord& w : words)
      if (w.address == address) return &w;
    return nullptr;
  }
};

}  // namespace clpost

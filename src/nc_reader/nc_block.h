#pragma once
// One NC block (line) as read back from a program: its words in order, a subroutine call's
// arguments, its comments. What nc_lexer makes and the control simulation (simulator/) runs.
#include <cstdint>
#include <string>
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

  const NcWord* find(std::string_view address) const {
    for (const NcWord& w : words)
      if (w.address == address) return &w;
    return nullptr;
  }
};

}  // namespace clpost

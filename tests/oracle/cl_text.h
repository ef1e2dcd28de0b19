#pragma once
// The oracle's own reader of APT/CL text: one statement per line (a line ending in a single `$`
// goes on with the next), `MAJOR/arg,arg,…` or a bare `MAJOR`, `$$` comments. Enough for the
// programs the generator writes and the hand-written tests; nothing of src/reader.
#include <string>
#include <string_view>
#include <vector>

namespace oracle {

struct ClStatement {
  int line = 0;
  std::string text;               // as written, without the comment
  std::string major;              // upper-cased
  std::vector<std::string> args;  // upper-cased, blanks removed

  bool is_number(size_t i) const;
  double number(size_t i) const;  // 0 when not a number
  bool has(std::string_view word) const;
  // The index of `word` among the arguments, or -1.
  int find(std::string_view word) const;
  // The first argument that is a number, or -1.
  int first_number() const;
};

std::vector<ClStatement> read_cl(std::string_view text);

}  // namespace oracle

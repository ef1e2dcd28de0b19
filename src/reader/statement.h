#pragma once
// One APT/CL statement as the reader delivers it. Views point into the reader's buffers and stay
// valid until the next call to ClReader::next().
#include <cstdint>
#include <string_view>
#include <vector>

#include "support/source_loc.h"

namespace clpost {

struct Arg {
  enum class Kind : uint8_t { kWord, kNumber };
  Kind kind = Kind::kWord;
  std::string_view text;  // words: upper-cased; numbers: as written
  double number = 0;      // numbers only
  SourceLoc loc;          // where the argument starts

  bool is_word() const { return kind == Kind::kWord; }
  bool is_number() const { return kind == Kind::kNumber; }
  bool is(std::string_view word) const { return kind == Kind::kWord && text == word; }
};

struct Statement {
  enum class Form : uint8_t {
    kRecord,  // MAJOR/arg,arg,...   (args filled; `RAPID/` is a record with no args)
    kBare,    // MAJOR alone on its line: RAPID, END, FINI, STOP, END-OF-PATH ...
    kText,    // PARTNO, PPRINT, INSERT: `text` holds the rest of the line verbatim
  };
  Form form = Form::kBare;
  std::string_view major;  // upper-cased; inner runs of blanks collapsed to one ("TOOL PATH")
  SourceLoc loc;           // of the major word
  std::vector<Arg> args;
  std::string_view text;  // kText: everything after the major word (and its optional '/'),
                          // leading and trailing blanks trimmed, case kept

  // The physical lines this statement was read from (continuations included), for diagnostics.
  uint32_t first_line = 0;
  std::vector<std::string_view> lines;
  std::string_view line_text(uint32_t line) const {
    if (line < first_line || line - first_line >= lines.size()) return {};
    return lines[line - first_line];
  }
};

}  // namespace clpost

#include <string>

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

}  // namespace clpost

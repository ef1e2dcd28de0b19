#pragma once
// Writes binary CLDATA (the inverse of cldata_reader.h): records from words, and APT text as
// the records APT360 would have written for it. For tests, seeds of the fuzz target and the
// benchmark's binary input; the files read back to the same statements.
#include <cstdint>
#include <span>
#include <string>
#include <string_view>

#include "reader/cldata_layout.h"
#include "support/diagnostics.h"

namespace clpost::cldata {

class Writer {
 public:
  explicit Writer(const Layout& layout = known_layouts().front()) : layout_(layout) {}

  // A record of the given words (as read_word() reads them); in a blocked layout (NCL) through
  // its physical blocks, the last one filled up after FINI.
  void record(int64_t type, int64_t subtype, std::span<const uint64_t> words);
  static uint64_t number(double v);
  static uint64_t code(int64_t minor) { return static_cast<uint64_t>(minor); }
  // Text: the layout's characters of a word, padded with blanks.
  uint64_t text(std::string_view chars) const;

  const std::string& bytes() const { return out_; }
  int64_t records() const { return number_; }

 private:
  void put(uint64_t v, size_t bytes);
  void skip_unused();
  const Layout& layout_;
  std::string out_;
  int64_t number_ = 0;
};

struct EncodeOptions {
  // Record k for line k of the text: a sequence number (1000) record for each line that
  // starts no statement, one point per GOTO record. A statement then has the same number as a
  // record as it had as a line, and so does what the NC program says of it ("thread line 18").
  // Otherwise a sequence record before each statement (as APT360 writes) and
  // `points_per_record` consecutive GOTO points in a record, then continuation records.
  bool line_aligned = true;
  size_t points_per_record = 1;
};

// The binary CLDATA of APT text. False, with the statements that have no record reported
// (CIRCLE, a word with no code that is not a short name), when it cannot be written exactly.
bool encode_apt(std::string_view apt, Diagnostics& diags, std::string& out,
                const EncodeOptions& opts = {});

}  // namespace clpost::cldata

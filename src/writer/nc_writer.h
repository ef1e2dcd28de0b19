#pragma once
// NC blocks: words formatted per the machine's number formats, optional block numbers, the
// machine's comment style and line ending. No modal logic here (see nc_program.h).
#include <algorithm>
#include <string>
#include <string_view>
#include <vector>

#include "machine/machine.h"
#include "support/sink.h"
#include "writer/block_buffer.h"
#include "writer/number_format.h"

namespace clpost {

class NcWriter {
 public:
  NcWriter(const Machine& m, Sink& out);

  // Appends a code word ("G0", "M3"); empty codes are skipped.
  NcWriter& code(std::string_view c);
  // Appends address + number in the address's format.
  NcWriter& word(std::string_view address, double value);
  // The same with the format given (looked up once by the caller: the hot path, inline).
  NcWriter& word(std::string_view address, double value, const NumberFormat& format) {
    return word(address, written(value, format), format);
  }
  // The same with the value already worked out for `format` (written()).
  NcWriter& word(std::string_view address, const WrittenNumber& value, const NumberFormat& format) {
    separate();
    char* p = line_.room(address.size() + max_number_chars(format));
    p = std::copy(address.begin(), address.end(), p);
    line_.commit(put_written(p, value, format));
    return *this;
  }
  // Appends text as it is (a separating blank is added).
  NcWriter& text(std::string_view raw);
  // Writes the block (with a block number when enabled); an empty block writes nothing.
  void end_block();
  // A comment block in the machine's comment style.
  void comment(std::string_view text);
  // A line written verbatim (INSERT), without block number.
  void raw_line(std::string_view text);
  // `text` as machine `m` writes comment text: forbidden characters removed, control characters
  // as blanks, upper case when it asks, trimmed.
  static std::string comment_text(const Machine& m, std::string_view text);
  // comment_text() cut into the machine's comments.max_length (at the last blank that fits, else
  // at the limit): one string per comment block.
  static std::vector<std::string> comment_lines(const Machine& m, std::string_view text);
  // Every block from now on starts with `mark` (block delete, "/"); empty: none.
  void set_block_delete(std::string_view mark);
  // With block_numbers.at_tool_changes: the next block gets a number (a tool change begins).
  void number_next() { number_next_ = true; }
  // Comments wrapped at comments.max_length; blocks longer than output.max_line_length and the
  // first of them (1-based line of the program).
  size_t wrapped_comments() const { return wrapped_comments_; }
  size_t long_lines() const { return long_lines_; }
  // Lines written so far (blocks, comments, raw lines).
  size_t lines() const { return lines_; }
  size_t first_long_line() const { return first_long_line_; }

  const Machine& machine() const { return m_; }

 private:
  // Before each word: a blank after the words before it, or for the first word of a block, the
  // block's opening (its block number, when numbered).
  void separate() {
    if (open_) {
      line_.push_back(' ');
    } else {
      open_block();
    }
  }
  void open_block();
  std::string_view words() const { return line_.view().substr(words_at_); }

  const Machine& m_;
  Sink& out_;
  // The block being built, as it is written (block number, words, line ending): one write per
  // block, no copy. The block number is put first as the block opens; end_block() takes it out
  // again for a block that gets none (block_skip), which is rare.
  BlockBuffer line_;
  size_t words_at_ = 0;       // where the words start in line_
  bool open_ = false;         // a block has words
  std::string block_delete_;  // OPSKIP: the mark every block starts with
  bool number_next_ = false;  // at_tool_changes: this block is numbered
  bool numbered_ = false;     // the open block has a number
  bool plain_blocks_;         // neither block delete nor numbers at tool changes only
  size_t line_limit_;         // output.max_line_length (SIZE_MAX: none)
  size_t lines_ = 0;          // lines written
  size_t wrapped_comments_ = 0, long_lines_ = 0, first_long_line_ = 0;
  int next_number_;
};

}  // namespace clpost

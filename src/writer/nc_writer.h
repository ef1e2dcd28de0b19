#pragma once
// NC blocks: words formatted per the machine's number formats, optional block numbers, the
// machine's comment style and line ending. No modal logic here (see nc_program.h).
#include <string>
#include <string_view>

#include "machine/machine.h"
#include "support/sink.h"

namespace clpost {

class NcWriter {
 public:
  NcWriter(const Machine& m, Sink& out);

  // Appends a code word ("G0", "M3"); empty codes are skipped.
  NcWriter& code(std::string_view c);
  // Appends address + number in the address's format.
  NcWriter& word(std::string_view address, double value);
  // The same with the format given (looked up once by the caller: the hot path).
  NcWriter& word(std::string_view address, double value, const NumberFormat& format);
  // Appends text as it is (a separating blank is added).
  NcWriter& text(std::string_view raw);
  // Writes the block (with a block number when enabled); an empty block writes nothing.
  void end_block();
  // A comment block in the machine's comment style.
  void comment(std::string_view text);
  // A line written verbatim (INSERT), without block number.
  void raw_line(std::string_view text);

  const Machine& machine() const { return m_; }

 private:
  const Machine& m_;
  Sink& out_;
  std::string block_;
  std::string line_;  // block number, block and line ending: one write per block
  int next_number_;
};

}  // namespace clpost

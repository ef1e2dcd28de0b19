#pragma once
// What every control's cycle read-back needs of a block (src/controls/*/*_readback.cc): a word's
// value or its default, the words a cycle cannot do without, and the arguments of a call written
// by a template (CYCLE99(…)), read by field name.
#include <cstdint>
#include <map>
#include <optional>
#include <string>
#include <string_view>
#include <utility>

#include "machine/machine_schema.h"
#include "simulator/sim_state.h"

namespace clpost::sim {

// The column of the block's first word (1 for an empty block): where a cycle's errors point.
uint32_t first_col(const NcBlock& b);
// The value of the block's `address` word read with `format`, or `fallback` when it has none.
double word_or(const State& s, const NcBlock& b, const char* address, std::string_view format,
               double fallback);
// True, with an error "<code> without its <w> word", when one of the one-letter `words` is not
// in the block.
bool missing(State& s, const NcBlock& b, const Code& code, const char* words);

// Where each {field} of a call template sits among its arguments: "spl" -> 0, ...
std::map<std::string, size_t> call_fields(std::string_view t);

// The arguments of a call the machine's template `spec` writes, read by field name; an argument
// that is not a number is reported once and makes ok() false.
// The arguments of a call the machine's template `spec` writes, read by field name; an argument
// that is not a number is reported once and makes ok() false.
class CallArgs {
 public:
  // Null when the block has no such call (or the machine no such template).
  static std::optional<CallArgs> find(State& s, const NcBlock& b, const TemplateSpec& spec);

  // The argument of `field` read with `format`; `fallback` when it is empty or absent.
  double arg(const char* field, std::string_view format, double fallback);
  // `v` as a whole number in [lo, hi] (else an error naming `n`, and lo).
  int whole(double v, const char* n, int lo, int hi);
  bool ok() const { return ok_; }
  uint32_t col() const { return call_->col; }

 private:
  CallArgs(State& s, const NcCall& c, std::string name, std::map<std::string, size_t> fields)
      : s_(&s), call_(&c), name_(std::move(name)), fields_(std::move(fields)) {}
  State* s_;
  const NcCall* call_;
  std::string name_;
  std::map<std::string, size_t> fields_;
  bool ok_ = true;
};

}  // namespace clpost::sim

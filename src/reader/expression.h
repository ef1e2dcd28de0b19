#pragma once
// APT arithmetic in parentheses, as CAM systems write it in arguments: `PITCH/(1/2.5)`,
// `(2*3+1)`, `(-(1+2)*3)`, `(2**3)`. Numbers are APT numbers (reader/number.h); the operators
// are + - * / and ** (power, right-associative, above unary minus as in FORTRAN:
// (-2**2) is -4); blanks are allowed between the parts.
#include <cstddef>
#include <string>
#include <string_view>

namespace clpost::reader {

struct ExprError {
  size_t at = 0;  // offset in the source of what is wrong
  std::string message;
};

// `src[pos]` is '+', '-' or '('. Evaluates the expression that starts there — an optional sign
// and a parenthesized expression — and leaves `pos` after its closing ')'. False on an error
// (division by zero at the '/', a result out of range, a word or an unclosed parenthesis), with
// `err` set.
bool eval_expression(std::string_view src, size_t& pos, double& value, ExprError& err);

// Parentheses nested deeper than this are refused (hostile input must not exhaust the stack).
constexpr int kMaxNesting = 64;

}  // namespace clpost::reader

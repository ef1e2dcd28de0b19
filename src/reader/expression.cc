#include "reader/expression.h"

#include <cmath>
#include <utility>

#include "reader/continuation.h"
#include "reader/number.h"
#include "support/text.h"

namespace clpost::reader {

namespace {

class Evaluator {
 public:
  Evaluator(std::string_view src, size_t pos, ExprError& err) : s_(src), i_(pos), err_(err) {}

  // sum := term (('+'|'-') term)*
  bool sum(double& v, int depth) {
    if (!term(v, depth)) return false;
    for (;;) {
      const char op = peek();
      if (op != '+' && op != '-') return true;
      const size_t at = i_;
      ++i_;
      double r = 0;
      if (!term(r, depth)) return false;
      v = op == '+' ? v + r : v - r;
      if (!finite(v, at)) return false;
    }
  }

  // A parenthesized expression at the cursor.
  bool group(double& v, int depth) {
    const size_t open = i_;
    if (depth >= kMaxNesting) return fail(open, "parentheses nested too deeply");
    ++i_;  // '('
    if (!sum(v, depth + 1)) return false;
    if (peek() != ')') {
      if (i_ >= s_.size()) return fail(open, "missing ')' to close this '('");
      return fail(i_, "expected an operator or ')' in the expression, found '" +
                          std::string(1, s_[i_]) + "'");
    }
    ++i_;
    return true;
  }

  // factor := ('+'|'-') factor | primary ['**' factor]
  bool factor(double& v, int depth) {
    const char c = peek();
    if (c == '+' || c == '-') {
      if (depth >= kMaxNesting) return fail(i_, "expression nested too deeply");
      ++i_;
      if (!factor(v, depth + 1)) return false;
      if (c == '-') v = -v;
      return true;
    }
    if (!primary(v, depth)) return false;
    const size_t after = i_;  // blanks after the last group are not the expression's
    if (peek() == '*' && i_ + 1 < s_.size() && s_[i_ + 1] == '*') {
      const size_t op = i_;
      i_ += 2;
      double e = 0;
      if (depth >= kMaxNesting) return fail(op, "expression nested too deeply");
      if (!factor(e, depth + 1)) return false;
      v = std::pow(v, e);
      return finite(v, op);
    }
    i_ = after;
    return true;
  }

  size_t pos() const { return i_; }

 private:
  // term := factor (('*'|'/') factor)*   ('**' belongs to factor)
  bool term(double& v, int depth) {
    if (!factor(v, depth)) return false;
    for (;;) {
      const char op = peek();
      if (op != '*' && op != '/') return true;
      const size_t at = i_;
      ++i_;
      double r = 0;
      if (!factor(r, depth)) return false;
      if (op == '/' && r == 0) return fail(at, "division by zero");
      v = op == '*' ? v * r : v / r;
      if (!finite(v, at)) return false;
    }
  }

  // primary := number | '(' sum ')'
  bool primary(double& v, int depth) {
    const char c = peek();
    if (c == '(') return group(v, depth);
    if (is_digit(c) || c == '.') return number(v);
    if (i_ >= s_.size()) return fail(i_, "expected a number, found the end of the statement");
    size_t end = i_;
    while (end < s_.size() && !is_blank_char(s_[end]) && s_[end] != ')' && s_[end] != ',') ++end;
    if (end == i_) end = i_ + 1;
    return fail(i_, "expected a number in the expression, found '" +
                        std::string(s_.substr(i_, end - i_)) + "'");
  }

  bool number(double& v) {
    const size_t start = i_;
    while (i_ < s_.size() && (is_digit(s_[i_]) || s_[i_] == '.')) ++i_;
    if (i_ < s_.size() && (s_[i_] == 'e' || s_[i_] == 'E')) {
      size_t k = i_ + 1;
      if (k < s_.size() && (s_[k] == '+' || s_[k] == '-')) ++k;
      if (k < s_.size() && is_digit(s_[k])) {
        i_ = k;
        while (i_ < s_.size() && is_digit(s_[i_])) ++i_;
      }
    }
    const std::string_view tok = s_.substr(start, i_ - start);
    switch (parse_number(tok, v)) {
      case NumberStatus::kOk:
        return true;
      case NumberStatus::kOutOfRange:
        return fail(start, "number '" + std::string(tok) + "' is out of range");
      case NumberStatus::kInvalid:
        break;
    }
    return fail(start, "invalid number '" + std::string(tok) + "'");
  }

  bool finite(double v, size_t at) {
    if (std::isfinite(v)) return true;
    return fail(at, std::isnan(v) ? "the result is not a number" : "the result is out of range");
  }

  char peek() {
    while (i_ < s_.size() && is_blank_char(s_[i_])) ++i_;
    return i_ < s_.size() ? s_[i_] : '\0';
  }

  bool fail(size_t at, std::string message) {
    err_.at = at;
    err_.message = std::move(message);
    return false;
  }

  std::string_view s_;
  size_t i_;
  ExprError& err_;
};

}  // namespace

bool eval_expression(std::string_view src, size_t& pos, double& value, ExprError& err) {
  Evaluator e(src, pos, err);
  if (!e.factor(value, 0)) return false;
  pos = e.pos();
  return true;
}

}  // namespace clpost::reader

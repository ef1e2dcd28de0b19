#include "reader/plain_line.h"

#include <cstring>

namespace clpost::reader {

namespace {

// The scanning loops below need no bounds checks: they run over one line known to end in '\n'
// (found by memchr first), and '\n' belongs to none of the classes they accept.
bool is_upper(char c) {
  return static_cast<unsigned char>(c - 'A') <= 'Z' - 'A';
}
unsigned digit_value(char c) {
  return static_cast<unsigned char>(c - '0');  // > 9: not a digit
}
bool is_major_tail(char c) {
  return is_upper(c) || digit_value(c) <= 9 || c == '_' || c == '-';
}

bool is_text_major(std::string_view major) {
  return major == "PARTNO" || major == "PPRINT" || major == "INSERT" || major == "TPRINT" ||
         major == "REMARK";
}

// Exact powers of ten: with a mantissa below 10^15 one division is correctly rounded, and it is
// the very computation parse_number() does for these numbers, so the values are identical.
constexpr double kPow10[] = {1e0, 1e1, 1e2,  1e3,  1e4,  1e5,  1e6,  1e7,
                             1e8, 1e9, 1e10, 1e11, 1e12, 1e13, 1e14, 1e15};
constexpr int kMaxDigits = 15;

// A number `[+-]? (digits [. digits*] | . digits)` at `p`: advances `p` past it. False when it
// has no digit or too many (parse_number's full grammar is the general path's business).
bool plain_number(const char*& p, double& value) {
  const bool negative = *p == '-';
  if (*p == '+' || *p == '-') ++p;
  uint64_t mantissa = 0;
  const char* const whole = p;
  for (unsigned d; (d = digit_value(*p)) <= 9; ++p) mantissa = mantissa * 10 + d;
  long digits = p - whole;
  long frac_digits = 0;
  if (*p == '.') {
    const char* const frac = ++p;
    for (unsigned d; (d = digit_value(*p)) <= 9; ++p) mantissa = mantissa * 10 + d;
    frac_digits = p - frac;
    digits += frac_digits;
  }
  if (digits == 0 || digits > kMaxDigits) return false;
  const double v = static_cast<double>(mantissa) / kPow10[frac_digits];
  value = negative ? -v : v;
  return true;
}

}  // namespace

bool lex_plain_line(std::string_view input, uint32_t line_no, Statement& st, PlainLine& line) {
  const char* const begin = input.data();
  const char* const input_end = begin + input.size();
  if (input.empty() || std::memchr(begin, '\n', input.size()) == nullptr) return false;

  const char* p = begin;
  if (!is_upper(*p)) return false;
  ++p;
  while (is_major_tail(*p)) ++p;
  const std::string_view major(begin, static_cast<size_t>(p - begin));
  if (is_text_major(major)) return false;

  st.args.clear();
  const bool record = *p == '/';
  const char* const args = p + 1;
  if (record) {
    ++p;
    for (;;) {
      const SourceLoc at{line_no, static_cast<uint32_t>(p - begin + 1)};
      const char* const tok = p;
      if (is_upper(*p)) {
        ++p;
        while (is_major_tail(*p) || *p == '.') ++p;
        st.args.push_back(
            Arg{Arg::Kind::kWord, std::string_view(tok, static_cast<size_t>(p - tok)), {0}, at});
      } else {
        double value = 0;
        if (!plain_number(p, value)) return false;
        st.args.push_back(Arg{
            Arg::Kind::kNumber, std::string_view(tok, static_cast<size_t>(p - tok)), {value}, at});
      }
      if (*p != ',') break;
      ++p;
    }
    // `RAPID/` (a record without arguments) and a trailing ',' come here with no argument read
    // at the end: declined below, as the line does not end there.
  }

  // The line must end right here.
  line.size = static_cast<size_t>(p - begin);
  if (*p == '\n') {
    line.terminator = 1;
  } else if (*p == '\r' && p + 1 < input_end) {
    line.terminator = p[1] == '\n' ? 2 : 1;
  } else {
    return false;
  }
  st.form = record ? Statement::Form::kRecord : Statement::Form::kBare;
  st.major = major;
  st.loc = SourceLoc{line_no, 1};
  st.text = record ? std::string_view(args, static_cast<size_t>(p - args)) : std::string_view();
  st.source = std::string_view(begin, line.size);
  st.modifiers.clear();
  st.nested.clear();
  st.problem.message.clear();
  st.first_line = line_no;
  st.lines.assign(1, std::string_view(begin, line.size));
  return true;
}

}  // namespace clpost::reader

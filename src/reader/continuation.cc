#include "reader/continuation.h"

namespace clpost::reader {

static std::string_view trim_right(std::string_view s) {
  while (!s.empty() && is_blank_char(s.back())) s.remove_suffix(1);
  return s;
}

bool is_blank_line(std::string_view line) {
  for (char c : line) {
    if (!is_blank_char(c)) return false;
  }
  return true;
}

bool is_comment_line(std::string_view line) {
  size_t i = 0;
  while (i < line.size() && is_blank_char(line[i])) ++i;
  return line.substr(i, 2) == "$$";
}

std::string_view code_part(std::string_view line, bool* continues) {
  size_t comment = line.find("$$");
  std::string_view code = trim_right(line.substr(0, comment));
  *continues = !code.empty() && code.back() == '$';
  if (*continues) code.remove_suffix(1);
  return code;
}

bool comment_continues(std::string_view line) {
  line = trim_right(line);
  return !line.empty() && line.back() == '$' && (line.size() < 2 || line[line.size() - 2] != '$');
}

void LineTail::feed(std::string_view bytes) {
  for (char c : bytes) {
    if (!is_blank_char(c)) {
      before_last_ = prev_;
      last_ = c;
      if (!in_comment_) {
        if (c == '$' && prev_ == '$') {
          in_comment_ = true;
          code_last_ = code_saved_;
        } else {
          code_saved_ = code_last_;
          code_last_ = c;
        }
      }
    }
    prev_ = c;
  }
}

}  // namespace clpost::reader

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

// Where the first `$$` outside quotes starts (npos: none). The same states as LineTail::feed.
static size_t comment_start(std::string_view line) {
  size_t at = line.find("$$");
  if (at == std::string_view::npos) return at;
  if (line.find_first_of("'\"") > at) return at;  // the common case: no quote before it
  bool arg_start = true;
  char quote = 0;
  for (size_t i = 0; i < line.size(); ++i) {
    const char c = line[i];
    if (quote != 0) {
      if (c == quote) quote = 0;
      continue;
    }
    if (c == '$' && i + 1 < line.size() && line[i + 1] == '$') return i;
    if ((c == '\'' || c == '"') && arg_start) {
      quote = c;
    } else if (c == '/' || c == ',' || c == '(') {
      arg_start = true;
    } else if (!is_blank_char(c)) {
      arg_start = false;
    }
  }
  return std::string_view::npos;
}

std::string_view code_part(std::string_view line, bool* continues) {
  std::string_view code = trim_right(line.substr(0, comment_start(line)));
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
    }
    prev_ = c;
    if (in_comment_) continue;
    if (quote_ != 0) {
      if (c == quote_) quote_ = 0;
    } else if (c == '$' && dollar_) {
      in_comment_ = true;
      code_last_ = code_saved_;
      continue;
    } else if ((c == '\'' || c == '"') && arg_start_) {
      quote_ = c;
    } else if (c == '/' || c == ',' || c == '(') {
      arg_start_ = true;
    } else if (!is_blank_char(c)) {
      arg_start_ = false;
    }
    dollar_ = quote_ == 0 && c == '$' && !dollar_;
    if (!is_blank_char(c)) {
      code_saved_ = code_last_;
      code_last_ = c;
    }
  }
}

}  // namespace clpost::reader

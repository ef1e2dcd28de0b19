#include "reader/lexer.h"

#include <utility>

#include "reader/continuation.h"
#include "reader/number.h"

namespace clpost::reader {

namespace {

bool is_alpha(char c) {
  return (c >= 'A' && c <= 'Z') || (c >= 'a' && c <= 'z');
}
bool is_digit(char c) {
  return c >= '0' && c <= '9';
}
bool is_major_char(char c) {
  return is_alpha(c) || is_digit(c) || c == '_' || c == '-';
}
bool is_word_char(char c) {
  return is_major_char(c) || c == '.';
}
char to_upper(char c) {
  return (c >= 'a' && c <= 'z') ? static_cast<char>(c - 'a' + 'A') : c;
}

// Text for a message: control and non-ASCII bytes as \xNN, long text cut.
std::string shown(std::string_view s) {
  constexpr size_t kMax = 40;
  std::string out;
  for (size_t i = 0; i < s.size() && i < kMax; ++i) {
    unsigned char c = static_cast<unsigned char>(s[i]);
    if (c >= 0x20 && c < 0x7f) {
      out += static_cast<char>(c);
    } else {
      static constexpr char kHex[] = "0123456789ABCDEF";
      out += "\\x";
      out += kHex[c >> 4];
      out += kHex[c & 15];
    }
  }
  if (s.size() > kMax) out += "...";
  return out;
}

std::string quoted(std::string_view s) {
  // Appended piece by piece: `"'" + shown(s) + "'"` trips GCC 12's -Wrestrict at -O3.
  std::string out = "'";
  out += shown(s);
  out += '\'';
  return out;
}

std::string_view trim(std::string_view s) {
  while (!s.empty() && is_blank_char(s.front())) s.remove_prefix(1);
  while (!s.empty() && is_blank_char(s.back())) s.remove_suffix(1);
  return s;
}

bool equals_upper(std::string_view word, std::string_view upper) {
  if (word.size() != upper.size()) return false;
  for (size_t i = 0; i < word.size(); ++i) {
    if (to_upper(word[i]) != upper[i]) return false;
  }
  return true;
}

// [first non-blank, end of the first word) of a line.
std::pair<size_t, size_t> first_word(std::string_view line) {
  size_t i = 0;
  while (i < line.size() && is_blank_char(line[i])) ++i;
  size_t j = i;
  while (j < line.size() && is_major_char(line[j])) ++j;
  return {i, j};
}

}  // namespace

bool StatementLexer::is_text_statement(std::string_view line) {
  auto [i, j] = first_word(line);
  std::string_view word = line.substr(i, j - i);
  if (!equals_upper(word, "PARTNO") && !equals_upper(word, "PPRINT") &&
      !equals_upper(word, "INSERT")) {
    return false;
  }
  return j == line.size() || is_blank_char(line[j]) || line[j] == '/';
}

void StatementLexer::start(const Statement& st) {
  size_t need = 0;
  for (std::string_view l : st.lines) need += l.size();
  words_.clear();
  if (words_.capacity() < need) words_.reserve(need);
  first_line_ = st.first_line;
  li_ = 0;
  pos_ = 0;
}

std::string_view StatementLexer::add_upper(std::string_view text) {
  // Never reallocates: start() reserved room for every byte of the statement.
  const size_t at = words_.size();
  words_.resize(at + text.size());
  char* dst = words_.data() + at;
  for (size_t i = 0; i < text.size(); ++i) dst[i] = to_upper(text[i]);
  return std::string_view(words_.data() + at, text.size());
}

bool StatementLexer::fail(Error& err, SourceLoc loc, std::string message) {
  err.loc = loc;
  err.message = std::move(message);
  return false;
}

bool StatementLexer::at_end() {
  while (li_ < code_.size()) {
    std::string_view l = code_[li_];
    while (pos_ < l.size() && is_blank_char(l[pos_])) ++pos_;
    if (pos_ < l.size()) return false;
    ++li_;
    pos_ = 0;
  }
  return true;
}

std::string_view StatementLexer::token() const {
  std::string_view l = code_[li_];
  size_t end = pos_;
  while (end < l.size() && !is_blank_char(l[end]) && l[end] != ',' && l[end] != '/') ++end;
  if (end == pos_) end = pos_ + 1;
  return l.substr(pos_, end - pos_);
}

StatementLexer::Result StatementLexer::lex_code(Statement& st, Error& err) {
  start(st);
  code_.clear();
  for (std::string_view l : st.lines) {
    bool continues = false;
    code_.push_back(code_part(l, &continues));
  }
  st.form = Statement::Form::kBare;
  st.major = {};
  st.loc = {};
  st.args.clear();
  st.text = {};

  if (at_end()) return Result::kEmpty;
  if (!is_alpha(cur())) {
    fail(err, loc(), "expected a major word, found " + quoted(token()));
    return Result::kError;
  }

  // The major word: up to '/' or the end; blanks (and line ends) inside collapse to one space.
  st.loc = loc();
  const size_t major_at = words_.size();
  bool blank = false;
  while (li_ < code_.size()) {
    std::string_view l = code_[li_];
    if (pos_ == l.size()) {
      ++li_;
      pos_ = 0;
      blank = true;
      continue;
    }
    const char c = l[pos_];
    if (is_blank_char(c)) {
      blank = true;
      ++pos_;
      continue;
    }
    if (c == '/') break;
    if (!is_major_char(c)) {
      fail(err, loc(), "invalid character " + quoted(std::string_view(&c, 1)) + " in major word");
      return Result::kError;
    }
    if (blank) words_ += ' ';
    blank = false;
    size_t end = pos_ + 1;  // the run of major-word characters, upper-cased in one go
    while (end < l.size() && is_major_char(l[end])) ++end;
    add_upper(l.substr(pos_, end - pos_));
    pos_ = end;
  }
  st.major = std::string_view(words_.data() + major_at, words_.size() - major_at);
  if (li_ == code_.size()) return Result::kOk;  // a bare word

  // Arguments.
  st.form = Statement::Form::kRecord;
  ++pos_;  // the '/'
  SourceLoc comma;
  bool after_comma = false;
  for (;;) {
    if (at_end()) {
      if (after_comma) {
        fail(err, comma, "missing argument after ','");
        return Result::kError;
      }
      return Result::kOk;
    }
    if (cur() == ',') {
      fail(err, loc(), "empty argument before ','");
      return Result::kError;
    }
    if (cur() == '/') {
      fail(err, loc(), "unexpected '/' in arguments");
      return Result::kError;
    }
    if (!lex_arg(st, err)) return Result::kError;
    if (at_end()) return Result::kOk;
    if (cur() == ',') {
      comma = loc();
      after_comma = true;
      ++pos_;
      continue;
    }
    if (cur() == '/') {
      fail(err, loc(), "unexpected '/' in arguments");
    } else {
      fail(err, loc(), "missing ',' before " + quoted(token()));
    }
    return Result::kError;
  }
}

bool StatementLexer::lex_arg(Statement& st, Error& err) {
  const std::string_view tok = token();
  const SourceLoc at = loc();
  pos_ += tok.size();
  const char c0 = tok[0];
  if (is_alpha(c0) || (is_digit(c0) && !looks_numeric(tok))) {
    // A word; it may start with a digit (NX operation names like 10_SVERL_63_N2).
    for (size_t k = 0; k < tok.size(); ++k) {
      if (!is_word_char(tok[k])) {
        return fail(err, SourceLoc{at.line, at.col + static_cast<uint32_t>(k)},
                    "invalid character " + quoted(tok.substr(k, 1)) + " in word " + quoted(tok));
      }
    }
    st.args.push_back(Arg{Arg::Kind::kWord, add_upper(tok), 0, at});
    return true;
  }
  if (is_digit(c0) || c0 == '+' || c0 == '-' || c0 == '.') {
    double value = 0;
    switch (parse_number(tok, value)) {
      case NumberStatus::kOk:
        st.args.push_back(Arg{Arg::Kind::kNumber, tok, value, at});
        return true;
      case NumberStatus::kOutOfRange:
        return fail(err, at, "number " + quoted(tok) + " is out of range");
      case NumberStatus::kInvalid:
        break;
    }
    return fail(err, at, "invalid number " + quoted(tok));
  }
  return fail(err, at, "unexpected character " + quoted(tok.substr(0, 1)));
}

void StatementLexer::lex_text(Statement& st) {
  start(st);
  const std::string_view line = st.lines.empty() ? std::string_view() : st.lines[0];
  auto [i, j] = first_word(line);
  st.form = Statement::Form::kText;
  st.major = add_upper(line.substr(i, j - i));
  st.loc = SourceLoc{st.first_line, static_cast<uint32_t>(i + 1)};
  st.args.clear();
  size_t k = j;
  while (k < line.size() && is_blank_char(line[k])) ++k;
  if (k < line.size() && line[k] == '/') ++k;
  st.text = trim(line.substr(k));
}

}  // namespace clpost::reader

#include "reader/lexer.h"

#include <algorithm>
#include <utility>

#include "reader/continuation.h"
#include "reader/expression.h"
#include "reader/number.h"
#include "support/text.h"

namespace clpost::reader {

namespace {

bool is_alpha(char c) {
  return (c >= 'A' && c <= 'Z') || (c >= 'a' && c <= 'z');
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

// The text of a text statement's line: trailing blanks and a continuation `$` removed.
std::string_view text_part(std::string_view line) {
  const bool continues = comment_continues(line);
  while (!line.empty() && is_blank_char(line.back())) line.remove_suffix(1);
  if (continues) line.remove_suffix(1);
  return line;
}

}  // namespace

bool StatementLexer::is_text_statement(std::string_view line) {
  auto [i, j] = first_word(line);
  std::string_view word = line.substr(i, j - i);
  if (!equals_upper(word, "PARTNO") && !equals_upper(word, "PPRINT") &&
      !equals_upper(word, "INSERT") && !equals_upper(word, "TPRINT") &&
      !equals_upper(word, "REMARK")) {
    return false;
  }
  return j == line.size() || is_blank_char(line[j]) || line[j] == '/';
}

void StatementLexer::join(const Statement& st, bool text) {
  size_t need = 0;
  for (std::string_view l : st.lines) need += l.size();
  words_.clear();
  if (words_.capacity() < need) words_.reserve(need);
  first_line_ = st.first_line;
  pos_ = 0;
  pieces_.clear();
  scratch_.clear();
  if (st.lines.size() == 1) {
    bool continues = false;
    src_ = text ? text_part(st.lines[0]) : code_part(st.lines[0], &continues);
    pieces_.push_back(Piece{0, 0});
    return;
  }
  joined_.clear();
  if (joined_.capacity() < need) joined_.reserve(need);
  for (uint32_t i = 0; i < st.lines.size(); ++i) {
    bool continues = false;
    pieces_.push_back(Piece{joined_.size(), i});
    joined_ += text ? text_part(st.lines[i]) : code_part(st.lines[i], &continues);
  }
  src_ = joined_;
}

SourceLoc StatementLexer::loc_at(size_t pos) const {
  // The last piece that starts at or before `pos` (a binary search: a statement may have
  // hundreds of thousands of continuation lines).
  auto it = std::upper_bound(pieces_.begin() + 1, pieces_.end(), pos,
                             [](size_t p, const Piece& piece) { return p < piece.offset; });
  const Piece& piece = *(it - 1);
  return SourceLoc{first_line_ + piece.line, static_cast<uint32_t>(pos - piece.offset + 1)};
}

std::string_view StatementLexer::add_upper(std::string_view text) {
  // Never reallocates: join() reserved room for every byte of the statement.
  const size_t at = words_.size();
  words_.resize(at + text.size());
  char* dst = words_.data() + at;
  for (size_t i = 0; i < text.size(); ++i) dst[i] = to_upper(text[i]);
  return std::string_view(words_.data() + at, text.size());
}

bool StatementLexer::problem(Statement& st, SourceLoc at, std::string message) {
  st.problem.loc = at;
  st.problem.message = std::move(message);
  return false;
}

bool StatementLexer::at_end() {
  while (pos_ < src_.size() && is_blank_char(src_[pos_])) ++pos_;
  return pos_ >= src_.size();
}

std::string_view StatementLexer::token() const {
  size_t end = pos_;
  while (end < src_.size()) {
    const char c = src_[end];
    if (is_blank_char(c) || c == ',' || c == '/' || c == '(' || c == ')') break;
    ++end;
  }
  if (end == pos_) end = pos_ + 1;
  return src_.substr(pos_, end - pos_);
}

StatementLexer::Result StatementLexer::lex_code(Statement& st, Error& err) {
  join(st, false);
  st.form = Statement::Form::kBare;
  st.major = {};
  st.loc = {};
  st.args.clear();
  st.text = {};
  st.source = trim(src_);
  st.modifiers.clear();
  st.nested.clear();
  st.problem.message.clear();

  if (at_end()) return Result::kEmpty;
  if (!is_alpha(cur())) {
    err.loc = loc();
    err.message = "expected a major word, found " + quoted(token());
    return Result::kError;
  }
  if (!head(st)) {
    st.args.clear();
    st.nested.clear();
  }
  return Result::kOk;
}

// The major word at the cursor: a run of [A-Za-z0-9_-], upper-cased; blanks followed by a
// letter continue it with one space ("TOOL PATH").
std::string_view StatementLexer::major_word() {
  const size_t at = words_.size();
  for (;;) {
    size_t end = pos_;
    while (end < src_.size() && is_major_char(src_[end])) ++end;
    add_upper(src_.substr(pos_, end - pos_));
    pos_ = end;
    size_t k = pos_;
    while (k < src_.size() && is_blank_char(src_[k])) ++k;
    if (k == pos_ || k == src_.size() || !is_alpha(src_[k])) break;
    words_ += ' ';
    pos_ = k;
  }
  return std::string_view(words_.data() + at, words_.size() - at);
}

// MAJOR, MAJOR/args, MAJOR,args (the comma form) or W1,...,MAJOR/args (modifiers).
bool StatementLexer::head(Statement& st) {
  st.loc = loc();
  st.major = major_word();
  const size_t word_end = pos_;
  if (at_end()) return true;  // a bare word
  const char c = cur();
  if (c == '/' || c == ',') {
    ++pos_;
    st.form = Statement::Form::kRecord;
    if (c == ',') modifiers(st, pos_);  // else the comma form: the ',' stands for the '/'
    st.text = trim(src_.substr(pos_));
    return lex_args(st, st.args, 0);
  }
  if (c == '=') {
    return problem(st, loc(),
                   "'" + std::string(st.major) +
                       "=' defines an APT part-program symbol: not CL data (post the CL file "
                       "the APT processor wrote)");
  }
  if (pos_ == word_end) {
    return problem(st, loc(),
                   "invalid character " + quoted(src_.substr(pos_, 1)) + " in major word");
  }
  return problem(st, loc(),
                 "expected '/' after " + std::string(st.major) + ", found " + quoted(token()));
}

// After `W1,`: when the statement goes on with words separated by commas up to a '/'
// (`TLON,GOFWD/…`, `RAPID,GOTO/…`), the last of them is the major word and the others are its
// modifiers; the cursor is left after the '/'. Otherwise nothing changes (the comma form).
bool StatementLexer::modifiers(Statement& st, size_t after_comma) {
  size_t p = after_comma;
  size_t last = 0;  // start of the word before the '/'
  size_t words = 0;
  for (;;) {
    while (p < src_.size() && is_blank_char(src_[p])) ++p;
    if (p == src_.size() || !is_alpha(src_[p])) return false;
    last = p;
    while (p < src_.size() && is_major_char(src_[p])) ++p;
    ++words;
    while (p < src_.size() && is_blank_char(src_[p])) ++p;
    if (p == src_.size()) return false;
    if (src_[p] == '/') break;
    if (src_[p] != ',') return false;
    ++p;
  }
  st.modifiers.push_back(Arg{Arg::Kind::kWord, st.major, {0}, st.loc});
  pos_ = after_comma;
  for (size_t k = 0; k < words; ++k) {
    at_end();
    const SourceLoc at = loc();
    const size_t b = pos_;
    while (pos_ < src_.size() && is_major_char(src_[pos_])) ++pos_;
    const std::string_view w = add_upper(src_.substr(b, pos_ - b));
    if (b == last) {
      st.major = w;
      st.loc = at;
    } else {
      st.modifiers.push_back(Arg{Arg::Kind::kWord, w, {0}, at});
    }
    at_end();
    ++pos_;  // the ',' or, after the last word, the '/'
  }
  return true;
}

// Arguments separated by ',' up to the end (depth 0) or a ')' (in a nested definition). Nothing
// between two commas, or after a last one, is an empty argument.
bool StatementLexer::lex_args(Statement& st, std::vector<Arg>& out, int depth) {
  auto closed = [&] { return at_end() || (depth > 0 && cur() == ')'); };
  if (closed()) return true;
  size_t comma = std::string_view::npos;  // the ',' before the argument
  for (;;) {
    if (closed() || cur() == ',') {
      // An empty last argument is shown just after its ',' on the comma's line, not at the
      // start of a blank continuation line.
      SourceLoc at = loc();
      if (pos_ == src_.size() && comma != std::string_view::npos) {
        at = loc_at(comma);
        ++at.col;
      }
      out.push_back(Arg{Arg::Kind::kEmpty, {}, {0}, at});
    } else if (cur() == '/' || cur() == ')') {
      break;
    } else if (!lex_arg(st, out, depth)) {
      return false;
    }
    if (closed()) return true;
    if (cur() != ',') break;
    comma = pos_++;
  }
  if (cur() == '/') return problem(st, loc(), "unexpected '/' in arguments");
  if (cur() == ')') return problem(st, loc(), "unexpected ')' without a '('");
  return problem(st, loc(), "missing ',' before " + quoted(token()));
}

bool StatementLexer::lex_arg(Statement& st, std::vector<Arg>& out, int depth) {
  const char c0 = cur();
  if (c0 == '\'' || c0 == '"') {
    const SourceLoc at = loc();
    const size_t end = src_.find(c0, pos_ + 1);
    if (end == std::string_view::npos) {
      return problem(st, at, std::string("missing the closing ") + c0 + " of this text");
    }
    out.push_back(Arg{Arg::Kind::kText, src_.substr(pos_ + 1, end - pos_ - 1), {0}, at});
    pos_ = end + 1;
    return true;
  }
  if (c0 == '(') return lex_paren(st, out, depth);
  if (c0 == '+' || c0 == '-') {
    size_t k = pos_ + 1;
    while (k < src_.size() && is_blank_char(src_[k])) ++k;
    if (k < src_.size() && src_[k] == '(') return lex_expression(st, out);
  }
  const std::string_view tok = token();
  const SourceLoc at = loc();
  if (is_alpha(c0) || (is_digit(c0) && !looks_numeric(tok))) {
    // A word; it may start with a digit (1STPECK, NX operation names like 10_SVERL_63_N2).
    for (size_t k = 0; k < tok.size(); ++k) {
      if (!is_word_char(tok[k])) {
        return problem(st, SourceLoc{at.line, at.col + static_cast<uint32_t>(k)},
                       "invalid character " + quoted(tok.substr(k, 1)) + " in word " + quoted(tok));
      }
    }
    pos_ += tok.size();
    out.push_back(Arg{Arg::Kind::kWord, add_upper(tok), {0}, at});
    return true;
  }
  if (is_digit(c0) || c0 == '+' || c0 == '-' || c0 == '.') {
    double value = 0;
    switch (parse_number(tok, value)) {
      case NumberStatus::kOk:
        pos_ += tok.size();
        out.push_back(Arg{Arg::Kind::kNumber, tok, {value}, at});
        return true;
      case NumberStatus::kOutOfRange:
        return problem(st, at, "number " + quoted(tok) + " is out of range");
      case NumberStatus::kInvalid:
        break;
    }
    return problem(st, at, "invalid number " + quoted(tok));
  }
  return problem(st, at, "unexpected character " + quoted(tok.substr(0, 1)));
}

// '(' opens a nested definition when a word and a '/' follow — `(CIRCLE/…)` —, else an
// arithmetic expression.
bool StatementLexer::lex_paren(Statement& st, std::vector<Arg>& out, int depth) {
  size_t k = pos_ + 1;
  while (k < src_.size() && is_blank_char(src_[k])) ++k;
  if (k < src_.size() && is_alpha(src_[k])) {
    while (k < src_.size() && is_major_char(src_[k])) ++k;
    while (k < src_.size() && is_blank_char(src_[k])) ++k;
    if (k < src_.size() && src_[k] == '/') return lex_definition(st, out, depth);
  }
  return lex_expression(st, out);
}

bool StatementLexer::lex_definition(Statement& st, std::vector<Arg>& out, int depth) {
  const SourceLoc open = loc();
  if (depth >= kMaxNesting) return problem(st, open, "nested definitions too deep");
  ++pos_;  // '('
  at_end();
  const size_t b = pos_;
  while (pos_ < src_.size() && is_major_char(src_[pos_])) ++pos_;
  const std::string_view name = add_upper(src_.substr(b, pos_ - b));
  at_end();
  ++pos_;  // '/'
  const size_t base = scratch_.size();
  if (!lex_args(st, scratch_, depth + 1)) return false;
  if (at_end()) {
    return problem(st, open, "missing ')' to close (" + std::string(name) + "/");
  }
  ++pos_;  // ')'
  Arg def{Arg::Kind::kDefinition, name, {0}, open};
  def.def = Arg::Span{static_cast<uint32_t>(st.nested.size()),
                      static_cast<uint32_t>(scratch_.size() - base)};
  st.nested.insert(st.nested.end(), scratch_.begin() + static_cast<std::ptrdiff_t>(base),
                   scratch_.end());
  scratch_.resize(base);
  out.push_back(def);
  return true;
}

bool StatementLexer::lex_expression(Statement& st, std::vector<Arg>& out) {
  const SourceLoc at = loc();
  const size_t start = pos_;
  double value = 0;
  ExprError e;
  if (!eval_expression(src_, pos_, value, e)) return problem(st, loc_at(e.at), e.message);
  out.push_back(Arg{Arg::Kind::kNumber, src_.substr(start, pos_ - start), {value}, at});
  return true;
}

void StatementLexer::lex_text(Statement& st) {
  join(st, true);
  auto [i, j] = first_word(src_);
  st.form = Statement::Form::kText;
  st.major = add_upper(src_.substr(i, j - i));
  st.loc = SourceLoc{st.first_line, static_cast<uint32_t>(i + 1)};
  st.args.clear();
  st.modifiers.clear();
  st.nested.clear();
  st.problem.message.clear();
  size_t k = j;
  while (k < src_.size() && is_blank_char(src_[k])) ++k;
  if (k < src_.size() && src_[k] == '/') ++k;
  st.text = trim(src_.substr(k));
  st.source = trim(src_);
}

}  // namespace clpost::reader

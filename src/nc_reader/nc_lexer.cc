#include "nc_reader/nc_lexer.h"

#include <fmt/format.h>

#include "reader/number.h"
#include "support/text.h"

namespace clpost {

NcSyntax nc_syntax(const Machine& m) {
  NcSyntax s;
  s.block_address = m.block_address;
  s.comment_open = m.comment_open;
  s.comment_close = m.comment_close;
  return s;
}

namespace {

bool is_letter(char c) {
  return (c >= 'A' && c <= 'Z') || (c >= 'a' && c <= 'z') || c == '_';
}
char upper(char c) {
  return (c >= 'a' && c <= 'z') ? static_cast<char>(c - 'a' + 'A') : c;
}
// Trimmed text drops trailing CRs too, as lex_nc_line does at the line's end: one can still
// stand inside a line given to lex_nc_line, or in the machine's block address and comment text.
// trim(s, "\r") without a search of that set for the last character (a call of memchr for
// each of two texts a line).
std::string_view trim_cr(std::string_view s) {
  s = trim(s);
  while (!s.empty() && s.back() == '\r') s = trim(s.substr(0, s.size() - 1));
  return s;
}

struct Lexer {
  std::string_view s;
  size_t i = 0;
  NcBlock& b;
  NcLexError& err;

  uint32_t col(size_t at) const { return static_cast<uint32_t>(at + 1); }
  bool fail(size_t at, std::string message) {
    err.col = col(at);
    err.message = std::move(message);
    return false;
  }
  void skip_blanks() {
    while (i < s.size() && is_blank(s[i])) ++i;
  }

  bool call(size_t start, std::string name) {
    NcCall c;
    c.name = std::move(name);
    c.col = col(start);
    ++i;  // '('
    size_t arg_start = i;
    bool quoted = false;
    for (; i < s.size(); ++i) {
      const char ch = s[i];
      if (ch == '"') quoted = !quoted;
      if (quoted) continue;
      if (ch == ',' || ch == ')') {
        std::string_view a = s.substr(arg_start, i - arg_start);
        size_t lead = 0;
        while (lead < a.size() && is_blank(a[lead])) ++lead;
        c.args.emplace_back(trim_cr(a));
        c.cols.push_back(col(arg_start + lead));
        arg_start = i + 1;
        if (ch == ')') {
          ++i;
          b.calls.push_back(std::move(c));
          return true;
        }
      }
    }
    return fail(start, fmt::format("'{}(' has no closing ')'", c.name));
  }

  bool word() {
    const size_t start = i;
    size_t j = i;
    // LinuxCNC's spindle number `$1` (M3 $1 S2000: the live tool, docs/millturn.md) is a word
    // of address '$'.
    if (s[j] == '$') ++j;
    while (j < s.size() && is_letter(s[j])) ++j;
    // A call: an identifier of two letters or more, then letters or digits, then '(' at once
    // ("CYCLE99(" — "X1 (" and "X1(" are a word and a comment).
    if (j - start >= 2) {
      size_t k = j;
      while (k < s.size() && (is_letter(s[k]) || is_digit(s[k]))) ++k;
      if (k < s.size() && s[k] == '(') {
        std::string name;
        for (size_t q = start; q < k; ++q) name += upper(s[q]);
        i = k;
        return call(start, std::move(name));
      }
    }
    // The word is made in its place in the block (its strings reused from the last block's).
    NcWord& w = b.words.emplace_back();
    w.col = col(start);
    if (j == start + 1) {
      w.address.assign(1, upper(s[start]));  // most words: X, Z, G
    } else {
      w.address.assign(s.data() + start, j - start);
      for (char& ch : w.address) ch = upper(ch);
    }
    i = j;
    if (i < s.size() && s[i] == '=') {
      w.address += '=';
      ++i;
      skip_blanks();
    }
    size_t n = i;
    if (n < s.size() && (s[n] == '+' || s[n] == '-')) ++n;
    while (n < s.size() && (is_digit(s[n]) || s[n] == '.')) ++n;
    if (n == i) {
      if (w.address.back() == '=' || w.address == "$") return unword(start, "'{}' has no value");
      return true;  // a bare word: DIAMON, MACHINING, END
    }
    // The number runs to the next blank, letter or comment; anything else in it is an error.
    size_t end = n;
    while (end < s.size() && !is_blank(s[end]) && !is_letter(s[end]) && s[end] != '(' &&
           s[end] != '[' && s[end] != ';')
      ++end;
    w.text.assign(s.data() + i, end - i);
    // The CL reader's number grammar (no exponent here: a letter ends the number).
    switch (reader::parse_number(w.text, w.value)) {
      case reader::NumberStatus::kOk:
        break;
      case reader::NumberStatus::kInvalid:
        return unword(start, "invalid number '{}{}'");
      case reader::NumberStatus::kOutOfRange:
        return unword(start, "number out of range '{}{}'");
    }
    i = end;
    return true;
  }

  // The word just begun is not one: taken out of the block, the error `format` (of its address
  // and text) at `start`.
  bool unword(size_t start, fmt::format_string<const std::string&, const std::string&> format) {
    const NcWord w = std::move(b.words.back());
    b.words.pop_back();
    return fail(start, fmt::format(format, w.address, w.text));
  }

  bool comment(const NcSyntax& syn, std::string_view open) {
    const size_t start = i;
    i += open.size();
    if (syn.comment_close.empty()) {
      b.comments.emplace_back(trim_cr(s.substr(i)));
      i = s.size();
      return true;
    }
    size_t close = s.find(syn.comment_close, i);
    if (close == std::string_view::npos)
      return fail(start, fmt::format("comment has no closing '{}'", syn.comment_close));
    b.comments.emplace_back(trim_cr(s.substr(i, close - i)));
    i = close + syn.comment_close.size();
    return true;
  }

  bool run(const NcSyntax& syn) {
    skip_blanks();
    if (i < s.size() && s[i] == '%') {
      b.program_delimiter = true;
      return true;
    }
    if (i < s.size() && s[i] == '/') {  // block delete: the block is optional
      b.block_delete = true;
      ++i;
    }
    // Block number.
    std::string_view addr = trim_cr(syn.block_address);
    if (!addr.empty() && s.substr(i, addr.size()) == addr) {
      size_t j = i + addr.size();
      while (j < s.size() && is_blank(s[j])) ++j;
      if (j < s.size() && is_digit(s[j]) && (j > i + addr.size() || addr.size() == 1)) {
        while (j < s.size() && is_digit(s[j])) ++j;
        i = j;
      }
    }
    const std::string_view open = trim_cr(syn.comment_open);
    const bool other_open = open != "(";
    while (true) {
      skip_blanks();
      if (i >= s.size()) return true;
      const char c = s[i];
      if (!open.empty() && c == open[0] && s.substr(i, open.size()) == open) {
        if (!comment(syn, open)) return false;
      } else if (c == '(' && other_open) {
        // An ISO comment in another dialect (INSERT text passed through): read as a comment.
        if (!comment(NcSyntax{syn.block_address, "(", ")"}, "(")) return false;
      } else if (c == ';') {
        b.comments.emplace_back(trim_cr(s.substr(i + 1)));
        return true;
      } else if (is_letter(c) || c == '$') {
        if (!word()) return false;
      } else {
        return fail(i, fmt::format("unexpected '{}'", c));
      }
    }
  }
};

}  // namespace

bool lex_nc_line(std::string_view line, uint32_t line_no, const NcSyntax& syntax, NcBlock& block,
                 NcLexError& error) {
  block.line = line_no;
  block.words.clear();
  block.calls.clear();
  block.comments.clear();
  block.program_delimiter = false;
  block.block_delete = false;
  block.letters = 0;
  while (!line.empty() && (line.back() == '\r' || is_blank(line.back()))) line.remove_suffix(1);
  Lexer lx{line, 0, block, error};
  const bool ok = lx.run(syntax);
  for (const NcWord& w : block.words) block.letters |= NcBlock::letter_bit(w.address);
  return ok;
}

}  // namespace clpost

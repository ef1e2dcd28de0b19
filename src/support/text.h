#pragma once
// Character classes and trimming for the hand-written scanners of every stage (the CL and NC
// readers, the machine's templates, the simulator's words). ASCII only and locale-free, unlike
// <cctype>: a number reads the same whatever the C locale, and a negative char is no undefined
// behaviour.
#include <string_view>

namespace clpost {

constexpr bool is_digit(char c) {
  return c >= '0' && c <= '9';
}

// A blank between words: space or tab.
constexpr bool is_blank(char c) {
  return c == ' ' || c == '\t';
}

// `s` without its leading and trailing blanks. Characters in `also_trailing` are dropped from
// the end too, mixed with the blanks (the NC lexer's "\r").
constexpr std::string_view trim(std::string_view s, std::string_view also_trailing = {}) {
  while (!s.empty() && is_blank(s.front())) s.remove_prefix(1);
  while (!s.empty() &&
         (is_blank(s.back()) || also_trailing.find(s.back()) != std::string_view::npos))
    s.remove_suffix(1);
  return s;
}

}  // namespace clpost

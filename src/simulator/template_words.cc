// A template line taken apart into words, as the simulation reads a program through the machine
// file: constant codes, and addresses with their fields (sim_state.h, TemplateToken).
#include <algorithm>
#include <cctype>

#include "simulator/sim_state.h"
#include "support/text.h"

namespace clpost::sim {

namespace {

// "{tool:02}{offset:02}" -> {tool, 2}, {offset, 2}; false when `text` is not only fields.
bool parse_fields(std::string_view text, std::vector<TemplateField>& out) {
  while (!text.empty()) {
    if (text.front() != '{') return false;
    const size_t close = text.find('}');
    if (close == std::string_view::npos) return false;
    const std::string_view inner = text.substr(1, close - 1);
    const size_t colon = inner.find(':');
    TemplateField f{std::string(inner.substr(0, colon)), 0};
    if (colon != std::string_view::npos)
      for (char c : inner.substr(colon + 1))
        if (is_digit(c)) f.width = f.width * 10 + (c - '0');
    out.push_back(std::move(f));
    text.remove_prefix(close + 1);
  }
  return true;
}

}  // namespace

std::vector<TemplateToken> template_tokens(const Machine& m, std::string_view line) {
  std::vector<TemplateToken> out;
  size_t i = 0;
  while (i < line.size()) {
    const size_t end = std::min(line.find(' ', i), line.size());
    const std::string_view token = line.substr(i, end - i);
    i = end + 1;
    if (token.empty()) continue;
    if (!m.comment_open.empty() && token.rfind(m.comment_open, 0) == 0) break;
    size_t a = 0;
    while (a < token.size() && std::isalpha(static_cast<unsigned char>(token[a]))) ++a;
    if (a > 0 && a < token.size() && token[a] == '=') ++a;
    TemplateToken t;
    if (a < token.size() && token[a] == '{') {
      if (a == 0 || !parse_fields(token.substr(a), t.fields)) continue;
      for (size_t k = 0; k < a; ++k)
        t.address += static_cast<char>(std::toupper(static_cast<unsigned char>(token[k])));
    } else if (token.find('{') == std::string_view::npos) {
      t.code = parse_code(token);
      // LinuxCNC's spindle number `$1`: a word of address '$', as the NC lexer reads it.
      if (token.size() > 1 && token[0] == '$' && t.code.address == token) {
        const Code n = parse_code("N" + std::string(token.substr(1)));
        if (n.number) t.code = Code{"$", n.number};
      }
    } else {
      continue;
    }
    out.push_back(std::move(t));
  }
  return out;
}

}  // namespace clpost::sim

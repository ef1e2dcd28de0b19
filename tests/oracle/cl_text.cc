#include "cl_text.h"

#include <cctype>
#include <cstdlib>

namespace oracle {

namespace {

std::string upper_without_blanks(std::string_view s) {
  std::string out;
  for (char c : s)
    if (!std::isspace(static_cast<unsigned char>(c)))
      out += static_cast<char>(std::toupper(static_cast<unsigned char>(c)));
  return out;
}

std::string trim(std::string_view s) {
  size_t b = 0, e = s.size();
  while (b < e && std::isspace(static_cast<unsigned char>(s[b]))) ++b;
  while (e > b && std::isspace(static_cast<unsigned char>(s[e - 1]))) --e;
  return std::string(s.substr(b, e - b));
}

// The code of a physical line: without a `$$` comment.
std::string_view code_of(std::string_view line) {
  const size_t c = line.find("$$");
  return c == std::string_view::npos ? line : line.substr(0, c);
}

ClStatement parse_statement(const std::string& code, int line) {
  ClStatement st;
  st.line = line;
  st.text = trim(code);
  const size_t slash = st.text.find('/');
  st.major = upper_without_blanks(std::string_view(st.text).substr(0, slash));
  if (slash == std::string::npos) return st;
  if (st.major == "PARTNO" || st.major == "PPRINT" || st.major == "INSERT") return st;
  std::string_view rest = std::string_view(st.text).substr(slash + 1);
  while (true) {
    const size_t comma = rest.find(',');
    st.args.push_back(upper_without_blanks(rest.substr(0, comma)));
    if (comma == std::string_view::npos) break;
    rest = rest.substr(comma + 1);
  }
  return st;
}

}  // namespace

bool ClStatement::is_number(size_t i) const {
  if (i >= args.size() || args[i].empty()) return false;
  char* end = nullptr;
  std::strtod(args[i].c_str(), &end);
  return end && *end == '\0';
}

double ClStatement::number(size_t i) const {
  return is_number(i) ? std::strtod(args[i].c_str(), nullptr) : 0;
}

bool ClStatement::has(std::string_view word) const {
  return find(word) >= 0;
}

int ClStatement::find(std::string_view word) const {
  for (size_t i = 0; i < args.size(); ++i)
    if (args[i] == word) return static_cast<int>(i);
  return -1;
}

int ClStatement::first_number() const {
  for (size_t i = 0; i < args.size(); ++i)
    if (is_number(i)) return static_cast<int>(i);
  return -1;
}

std::vector<ClStatement> read_cl(std::string_view text) {
  std::vector<ClStatement> out;
  std::string pending;
  int pending_line = 0, line = 0;
  while (!text.empty()) {
    const size_t nl = text.find('\n');
    std::string_view raw = text.substr(0, nl);
    text = nl == std::string_view::npos ? std::string_view() : text.substr(nl + 1);
    ++line;
    if (!raw.empty() && raw.back() == '\r') raw.remove_suffix(1);
    std::string code = trim(code_of(raw));
    if (pending.empty()) pending_line = line;
    if (!code.empty() && code.back() == '$') {
      code.pop_back();
      pending += code;
      continue;
    }
    pending += code;
    if (!trim(pending).empty()) out.push_back(parse_statement(pending, pending_line));
    pending.clear();
  }
  if (!trim(pending).empty()) out.push_back(parse_statement(pending, pending_line));
  return out;
}

}  // namespace oracle

// Arguments and text as messages show them (reader/statement.h).
#include "reader/statement.h"

#include <functional>

namespace clpost {

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

namespace {

std::string describe(const Arg& a, bool last, std::string_view whole) {
  switch (a.kind) {
    case Arg::Kind::kWord:
      return quoted(a.text);
    case Arg::Kind::kNumber:
      return "number " + shown(a.text);
    case Arg::Kind::kText:
      return a.text.empty() ? std::string("an empty quoted text") : "the text " + quoted(a.text);
    case Arg::Kind::kDefinition:
      return "(" + shown(a.text) + "/…)";
    case Arg::Kind::kEmpty:
      break;
  }
  return last ? "the end of " + std::string(whole) + " after ','" : "an empty argument";
}

}  // namespace

std::string describe_arg(std::span<const Arg> args, size_t i, std::string_view whole) {
  if (i >= args.size()) return "the end of " + std::string(whole);
  return describe(args[i], i + 1 == args.size(), whole);
}

std::string describe_arg(const Statement& st, const Arg& a) {
  const std::span<const Arg> args(st.args);
  const std::less<const Arg*> before;
  const bool in_args =
      !args.empty() && !before(&a, args.data()) && before(&a, args.data() + args.size());
  return in_args ? describe_arg(args, static_cast<size_t>(&a - args.data()))
                 : describe(a, false, "the statement");
}

}  // namespace clpost

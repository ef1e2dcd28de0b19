#pragma once
// Test helpers for the reader: read a text through ClReader (from memory and from a FILE*, which
// must agree) and dump what it delivered, one line per statement.
#include <gtest/gtest.h>

#include <cstdint>
#include <cstdio>
#include <filesystem>
#include <functional>
#include <string>
#include <vector>

#include "reader/cl_reader.h"

namespace clpost::reader_test {

using Form = Statement::Form;
using Kind = Arg::Kind;

// Owned copies of what the reader delivered (its views die at the next call).
struct OwnedArg {
  Kind kind;
  std::string text;
  double number;
  SourceLoc loc;
  std::vector<OwnedArg> nested;  // a definition's arguments
};
struct Owned {
  Form form;
  std::string major;
  SourceLoc loc;
  std::vector<OwnedArg> args;
  std::string text;
  uint32_t first_line;
  std::vector<std::string> lines;
  std::vector<std::string> modifiers;
  std::string source;
  SourceLoc problem_loc;
  std::string problem;
};
struct Result {
  std::vector<Owned> st;
  std::string diags;  // Diagnostics::render_all()
  size_t errors = 0;
  size_t bytes = 0;
  uint32_t line = 0;
};

inline OwnedArg own_arg(const Statement& s, const Arg& a) {
  OwnedArg o{a.kind, std::string(a.text), a.is_definition() ? 0 : a.number, a.loc, {}};
  if (a.is_definition()) {
    for (const Arg& n : s.args_of(a)) o.nested.push_back(own_arg(s, n));
  }
  return o;
}

inline Owned own(const Statement& s) {
  Owned o{s.form,
          std::string(s.major),
          s.loc,
          {},
          std::string(s.text),
          s.first_line,
          {},
          {},
          std::string(s.source),
          s.problem.loc,
          s.problem.message};
  for (const Arg& a : s.args) o.args.push_back(own_arg(s, a));
  for (std::string_view l : s.lines) o.lines.emplace_back(l);
  for (const Arg& m : s.modifiers) o.modifiers.emplace_back(m.text);
  return o;
}

inline Result read_all(ClReader& reader, Diagnostics& diags) {
  Result r;
  Statement s;
  while (reader.next(s)) r.st.push_back(own(s));
  EXPECT_FALSE(reader.next(s));  // stays at the end
  r.diags = diags.render_all();
  r.errors = diags.error_count();
  r.bytes = reader.bytes_read();
  r.line = reader.line();
  return r;
}

inline std::string at(SourceLoc loc) {
  // Piece by piece: `"@" + std::to_string(...)` trips GCC 12's false -Wrestrict at -O3.
  std::string out = "@";
  out += std::to_string(loc.line);
  out += ':';
  out += std::to_string(loc.col);
  return out;
}

// "W:TEXT", "N:text=value", "E" (empty), "T:'text'", "D:NAME(args)", then "@line:col".
inline std::string dump_arg(const OwnedArg& a) {
  char buf[64];
  std::string out;
  switch (a.kind) {
    case Kind::kWord:
      out = "W:" + a.text;
      break;
    case Kind::kNumber:
      std::snprintf(buf, sizeof buf, "=%.17g", a.number);
      out = "N:" + a.text + buf;
      break;
    case Kind::kEmpty:
      out = "E";
      break;
    case Kind::kText:
      out = "T:'" + a.text + "'";
      break;
    case Kind::kDefinition:
      out = "D:" + a.text + "(";
      for (size_t i = 0; i < a.nested.size(); ++i) out += (i ? "," : "") + dump_arg(a.nested[i]);
      out += ")";
      break;
  }
  return out + at(a.loc);
}

// One line per statement: "line:col FORM MODIFIERS,MAJOR/args 'text' !problem [lines]".
inline std::string dump(const Result& r) {
  std::string out;
  for (const Owned& s : r.st) {
    out += std::to_string(s.loc.line) + ":" + std::to_string(s.loc.col) + " ";
    out += s.form == Form::kRecord ? "R " : s.form == Form::kBare ? "B " : "T ";
    for (const std::string& m : s.modifiers) out += m + ",";
    out += s.major;
    if (s.form == Form::kRecord) out += "/";
    for (size_t i = 0; i < s.args.size(); ++i) out += (i ? "," : "") + dump_arg(s.args[i]);
    if (s.form == Form::kText) out += " '" + s.text + "'";
    if (!s.problem.empty()) out += " !" + at(s.problem_loc).substr(1) + " " + s.problem;
    out += " [" + std::to_string(s.first_line) + "+" + std::to_string(s.lines.size()) + "]\n";
  }
  return out;
}

inline Result read_memory(std::string_view text) {
  Diagnostics diags("t.cl");
  ClReader reader(text, diags);
  return read_all(reader, diags);
}

inline Result read_file(const std::string& text) {
  std::FILE* f = std::tmpfile();
  EXPECT_NE(f, nullptr);
  EXPECT_EQ(std::fwrite(text.data(), 1, text.size(), f), text.size());
  std::rewind(f);
  Diagnostics diags("t.cl");
  ClReader reader(f, diags);
  Result r = read_all(reader, diags);
  std::fclose(f);
  return r;
}

// Reads `text` from memory and through a FILE*; both must give the same result.
inline Result read(const std::string& text) {
  Result m = read_memory(text);
  Result f = read_file(text);
  EXPECT_EQ(dump(m), dump(f));
  EXPECT_EQ(m.diags, f.diags);
  EXPECT_EQ(m.bytes, f.bytes);
  EXPECT_EQ(m.line, f.line);
  return m;
}

// Reads the whole file `path` with ClReader (text or binary), handing every statement to
// `each`; checks that every byte was read. The reader's error count and rendered diagnostics
// go to `errors` and `diags` (the real-CAM-file tests).
inline size_t read_whole_file(const std::filesystem::path& path,
                              const std::function<void(const Statement&)>& each, size_t& errors,
                              std::string& diags_text) {
  size_t statements = 0;
  std::FILE* f = std::fopen(path.c_str(), "rb");
  EXPECT_NE(f, nullptr) << path;
  if (f == nullptr) return 0;
  Diagnostics diags(path.string());
  ClReader reader(f, diags);
  Statement s;
  while (reader.next(s)) {
    ++statements;
    each(s);
  }
  EXPECT_EQ(reader.bytes_read(), std::filesystem::file_size(path)) << path;
  errors = diags.error_count();
  diags_text = diags.render_all();
  std::fclose(f);
  return statements;
}

}  // namespace clpost::reader_test

// Text statements (PARTNO, PPRINT, INSERT), NX's TOOL PATH header, and unknown statements.
#include <fmt/format.h>

#include <algorithm>

#include "interpreter/statement_table.h"

namespace clpost {

void partno_stmt(PostState& s, const Statement& st) {
  // Before the program starts PARTNO names it (the start template's {program_name}).
  if (s.started) {
    s.prog.comment(st.text);
  } else {
    s.partno = std::string(st.text);
  }
}

void pprint_stmt(PostState& s, const Statement& st) {
  // ICAM's CATIA tables name the next tool so: `PPRINT TOOL: Thread Tool.1`.
  if (st.text.starts_with("TOOL:")) {
    std::string_view name = st.text.substr(5);
    name.remove_prefix(std::min(name.find_first_not_of(" \t"), name.size()));
    s.next_tool.text = std::string(name);
  }
  ensure_started(s);
  s.prog.comment(st.text);
}

void insert_stmt(PostState& s, const Statement& st) {
  ensure_started(s);
  s.prog.raw(st.text);
  // The text may set a motion mode, a feed or a position the program does not know of: the next
  // move states them all again.
  s.prog.forget_modal();
}

void tool_path_stmt(PostState& s, const Statement& st) {
  // NX operation header: TOOL PATH/<operation>,TOOL,<tool name>
  ensure_started(s);
  std::string text = "operation";
  for (const Arg& a : st.args) text += ' ' + std::string(a.text);
  s.prog.comment(text);
  // The tool it names describes the next tool change (the program header's tool list).
  for (size_t i = 0; i + 1 < st.args.size(); ++i)
    if (st.args[i].is("TOOL")) s.next_tool.text = std::string(st.args[i + 1].text);
}

void unknown_stmt(PostState& s, const Statement& st) {
  if (s.opts.strict) {
    error(s, st, st.loc, fmt::format("unknown statement '{}' (--strict)", st.major));
    return;
  }
  std::string text(st.major);
  // As written when the arguments say more than their texts (quotes, nested definitions,
  // modifier words) or could not be read.
  const bool as_written = st.has_problem() || !st.modifiers.empty() ||
                          std::any_of(st.args.begin(), st.args.end(), [](const Arg& a) {
                            return a.is_text() || a.is_definition();
                          });
  if (as_written) {
    text = st.source;
  } else if (st.form == Statement::Form::kRecord) {
    text += '/';
    for (size_t i = 0; i < st.args.size(); ++i)
      text += (i ? "," : "") + std::string(st.args[i].text);
  } else if (st.form == Statement::Form::kText) {
    text += ' ' + std::string(st.text);
  }
  warning(s, st, st.loc, fmt::format("unknown statement '{}' written as a comment", st.major));
  ensure_started(s);
  s.prog.comment(text);
}

void odd_statement(PostState& s, const Statement& st, bool known) {
  if (st.has_problem() && known) return error(s, st, st.problem.loc, st.problem.message);
  if (st.modifiers.empty()) return unknown_stmt(s, st);
  std::string head;
  for (const Arg& m : st.modifiers) head += std::string(m.text) + ',';
  error(s, st, st.modifiers[0].loc,
        fmt::format("{}{}/: words before the major word (APT motion modifiers) are not supported; "
                    "the statement may move the tool, so it cannot be left out",
                    head, st.major));
}

}  // namespace clpost

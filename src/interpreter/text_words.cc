// Text statements (PARTNO, PPRINT, INSERT), NX's TOOL PATH header, and unknown statements.
#include <fmt/format.h>

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
  ensure_started(s);
  s.prog.comment(st.text);
}

void insert_stmt(PostState& s, const Statement& st) {
  ensure_started(s);
  s.prog.raw(st.text);
}

void tool_path_stmt(PostState& s, const Statement& st) {
  // NX operation header: TOOL PATH/<operation>,TOOL,<tool name>
  ensure_started(s);
  std::string text = "operation";
  for (const Arg& a : st.args) text += ' ' + std::string(a.text);
  s.prog.comment(text);
}

void unknown_stmt(PostState& s, const Statement& st) {
  if (s.opts.strict) {
    error(s, st, st.loc, fmt::format("unknown statement '{}' (--strict)", st.major));
    return;
  }
  std::string text(st.major);
  if (st.form == Statement::Form::kRecord) {
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

}  // namespace clpost

#include "interpreter/interpreter.h"

#include <fmt/format.h>

#include "interpreter/statement_table.h"
#include "interpreter/tool_paths.h"

namespace clpost {

namespace {

// The handler of `st` (after SYN/ renamed it).
void dispatch(PostState& s, const Statement& st) {
  if (s.thread.kind != ThreadSequence::Kind::kNone && !sequence_accepts(s, st)) return;
  const StatementEntry* e = find_statement(st.major);
  if (st.has_problem() || (!st.modifiers.empty() && !is_motion_word(st.major))) [[unlikely]]
    return odd_statement(s, st, e != nullptr);
  if (e) return e->handler(s, st);
  unknown_stmt(s, st);
}

}  // namespace

Interpreter::Interpreter(const Machine& m, NcProgram& prog, Diagnostics& diags,
                         const PostOptions& opts)
    : state_(std::make_unique<PostState>(m, prog, diags, opts)) {}

Interpreter::~Interpreter() = default;

void Interpreter::statement(const Statement& st) {
  PostState& s = *state_;
  ++s.stats.statements;
  if (s.ended) {
    if (st.major != "FINI") note_once(s, st, "after-fini", "statements after FINI are ignored");
    return;
  }
  // The common case first: a plain GOTO outside a thread sequence.
  if (st.major == "GOTO" && s.thread.kind == ThreadSequence::Kind::kNone && !st.has_problem() &&
      st.modifiers.empty() && s.synonyms.empty())
    return goto_stmt(s, st);
  if (!s.synonyms.empty()) [[unlikely]] {
    if (const std::string* to = synonym_of(s, st.major)) {
      if (to->empty()) return;  // SYN/'W','$$…': ignored (noted at SYN/)
      Statement renamed = st;
      renamed.major = *to;
      return dispatch(s, renamed);
    }
  }
  dispatch(s, st);
}

void Interpreter::end_of_input(uint32_t last_line) {
  PostState& s = *state_;
  if (s.ended) return;
  end_sequences(s);  // an unterminated thread is the first thing to say
  s.diags.warning(SourceLoc{last_line, 0}, {},
                  "the file ends without FINI: the program end was added");
  Statement end;  // what the program end writes belongs to the file's last line
  end.loc = SourceLoc{last_line, 0};
  finish_program(s, end);
}

const std::string& Interpreter::partno() const {
  return state_->partno;
}

std::vector<MillSegment> Interpreter::take_mill() {
  return clpost::take_mill(*state_);
}

ClPath Interpreter::take_path() {
  hand_over_motion(*state_);
  return std::move(state_->cl_path);
}

void Interpreter::finish() {
  finish_program(*state_, Statement{});
}

}  // namespace clpost

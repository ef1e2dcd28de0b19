// CYCLE/UNDCUT,DIAM,d,AT,z,FORM,A|B|C|D: a thread undercut, read and checked here and written by
// the machine's undercut output (emitters/undercut_output.h: its control's cycle, else the DIN
// 76-1 contour as moves).
#include "laws/din76_undercut.h"

#include <fmt/format.h>

#include <array>
#include <cmath>

#include "emitters/undercut_output.h"
#include "interpreter/statement_table.h"
#include "support/number_text.h"

namespace clpost {

namespace {

// CYCLE/UNDCUT,DIAM,d,AT,z,FORM,A|B|C|D as read (words in any order).
struct UndercutWords {
  double diam = 0, at = 0;
  char form = 'A';
  SourceLoc diam_loc, form_loc;
};

// The value after word `a` (at index i) into `u`; false (reported) when it is not right.
bool read_undercut_value(PostState& s, const Statement& st, const Arg& a, const Arg& v,
                         UndercutWords& u) {
  if (a.is("FORM")) {
    if (!v.is_word() || v.text.size() != 1 || v.text[0] < 'A' || v.text[0] > 'D') {
      error(s, st, v.loc,
            fmt::format("CYCLE/UNDCUT: FORM must be A, B (external) or C, D (internal); got {}",
                        v.text));
      return false;
    }
    u.form = v.text[0];
    u.form_loc = v.loc;
    return true;
  }
  if (!v.is_number()) {
    error(s, st, v.loc,
          fmt::format("CYCLE/UNDCUT: {} needs a number, found {}", a.text, describe_arg(st, v)));
    return false;
  }
  (a.is("DIAM") ? u.diam : u.at) = v.number;
  if (a.is("DIAM")) u.diam_loc = v.loc;
  return true;
}

bool read_undercut_words(PostState& s, const Statement& st, UndercutWords& u) {
  const char* kValid = "DIAM, AT, FORM";
  bool seen[3] = {false, false, false};  // DIAM, AT, FORM
  u.diam_loc = u.form_loc = st.loc;
  for (size_t i = 1; i < st.args.size(); ++i) {
    const Arg& a = st.args[i];
    if (!a.is_word()) {
      error(s, st, a.loc,
            fmt::format("CYCLE/UNDCUT: expected a word, found {}; valid words: {}",
                        describe_arg(st, a), kValid));
      return false;
    }
    const int which = a.is("DIAM") ? 0 : a.is("AT") ? 1 : a.is("FORM") ? 2 : -1;
    if (which < 0) {
      error(s, st, a.loc,
            fmt::format("CYCLE/UNDCUT: unknown word '{}'; valid words: {}", a.text, kValid));
      return false;
    }
    if (i + 1 >= st.args.size()) {
      error(s, st, a.loc, fmt::format("CYCLE/UNDCUT: {} needs a value", a.text));
      return false;
    }
    if (!read_undercut_value(s, st, a, st.args[++i], u)) return false;
    seen[which] = true;
  }
  if (seen[0] && seen[1] && seen[2]) return true;
  error(s, st, st.loc,
        fmt::format("CYCLE/UNDCUT needs DIAM, AT and FORM: CYCLE/UNDCUT,DIAM,d,AT,z,FORM,A|B|C|D; "
                    "missing {}",
                    !seen[0]   ? "DIAM"
                    : !seen[1] ? "AT"
                               : "FORM"));
  return false;
}

}  // namespace

void undercut_stmt(PostState& s, const Statement& st) {
  UndercutWords u;
  if (!read_undercut_words(s, st, u)) return;
  const std::unique_ptr<CycleOutput<Undercut>> cycle = make_undercut_cycle(s.m);
  if (s.units == LengthUnit::kInch) {
    error(s, st, st.loc,
          "CYCLE/UNDCUT is for metric ISO threads (DIN 76-1, M3 ... M68): this program is in "
          "inches");
    return;
  }
  const std::optional<double> pitch = iso_coarse_pitch(u.diam);
  if (!pitch) {
    error(s, st, u.diam_loc,
          fmt::format("CYCLE/UNDCUT: DIAM {} is not a metric ISO coarse thread M3 ... M68 (3, 4, "
                      "5, 6, 8, 10, 12, 14, 16, 18, 20, 22, 24, 27, 30, 33, 36, 39, 42, 45, 48, "
                      "52, 56, 60, 64, 68){}",
                      num_text(u.diam),
                      cycle ? fmt::format(": {} stops with an alarm", cycle->name()) : ""));
    return;
  }
  if (!s.feed_given) {
    error(s, st, st.loc, "CYCLE/UNDCUT cuts at the feed in force: no FEDRAT/ before it");
    return;
  }
  ensure_started(s);
  restart_stopped_spindle(s, st);
  Undercut job;
  job.diam = u.diam;
  job.at = u.at;
  job.form = u.form;
  job.pitch = *pitch;
  if (s.pos) job.tool = cl2(s, *s.pos);
  job.feed = s.feed;
  job.feed_mode = s.feed_mode;
  job.tool_offset = s.tool.offset;
  job.diam_loc = u.diam_loc;
  job.form_loc = u.form_loc;
  const SavedLines lines = SavedLines::of(st);
  UndercutWritten written;
  if (!write_undercut(
          s.prog, job,
          EmitContext{.diags = s.diags, .lines = lines, .loc = st.loc, .used = &s.outputs},
          written))
    return;
  if (written.exit) record_exit(s, st.loc.line, *written.exit);
  s.stats.motions += written.moves;
}

}  // namespace clpost

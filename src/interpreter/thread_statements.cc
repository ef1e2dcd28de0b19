// Thread statements: PITCH/, THREAD/ON … THREAD/OFF (and Pro/E's OP/THREAD,TURN …
// OP/THREAD,NOMORE), THREAD/TURN|FACE|TAPER and its GOTOs, COUPLE/ON … COUPLE/OFF. These
// handlers only collect what the planner needs (ThreadSequence); the planner plans every form
// and thread_cutting.cc writes the plan.
#include <fmt/format.h>

#include <algorithm>
#include <cmath>

#include "interpreter/statement_table.h"
#include "interpreter/thread_cutting.h"

namespace clpost {

namespace {

using Kind = ThreadSequence::Kind;

// Opens a sequence of `kind` at `st`.
void open_sequence(PostState& s, const Statement& st, Kind kind) {
  ThreadSequence& t = s.thread;
  t.kind = kind;
  t.loc = st.loc;
  t.lines = SavedLines::of(st);
  t.failed = false;
}

// THREAD/ON (or OP/THREAD,TURN|FACE|TAPER): a multi-pass thread, planned at THREAD/OFF.
void open_multi(PostState& s, const Statement& st, size_t first) {
  open_sequence(s, st, Kind::kMulti);
  MultiThreadInput& in = s.thread.multi;
  in = MultiThreadInput{};
  if (st.major == "OP") {
    in.on_word = fmt::format("OP/THREAD,{}", st.args[first].text);
    in.off_word = "OP/THREAD,NOMORE";
  }
  // On a bad word the sequence is still entered, so that its GOTOs are not posted as ordinary
  // moves, but it is not planned (one error, not a cascade).
  s.thread.failed = !parse_thread_words(st, first + 1, s.units, in.words, s.diags);
  in.on_lines = s.thread.lines;
  in.on_loc = st.loc;
  in.modal_pitch = s.thread.pitch;
  in.units = s.units;
  if (!s.pos) {
    error(s, st, st.loc, "THREAD/ON needs the initial point: no GOTO or FROM before it");
    s.thread.failed = true;
  }
  in.p0 = s.pos ? cl2(s, *s.pos) : Vec2{};
  in.feed_approach = !s.rapid_next && s.feed_given;
  s.rapid_next = false;
}

// The largest radius of a THREAD/ON thread's line (a chain: of its contour), as
// cut_multi_thread takes it for the spindle speed.
double thread_radius(const MultiThreadInput& in) {
  const size_t n = in.words.chain.set ? in.gotos.size() : std::min<size_t>(in.gotos.size(), 2);
  double radius = 0;
  for (size_t j = 0; j < n; ++j) radius = std::max(radius, std::abs(in.gotos[j].point.x));
  return radius;
}

void close_multi(PostState& s, const Statement& st) {
  ThreadSequence& t = s.thread;
  t.kind = Kind::kNone;
  t.multi.off_loc = st.loc;
  ThreadPlan plan;
  if (t.failed) return;
  t.multi.rpm = thread_rpm(s, thread_radius(t.multi));
  const bool planned = t.multi.words.chain.set
                           ? plan_chain_thread(t.multi, t.settings, plan, s.diags)
                           : plan_multi_thread(t.multi, t.settings, plan, s.diags);
  if (!planned) return;
  cut_multi_thread(s, plan, t.multi.on_lines);
}

// Decision (CATIA V5, NC_LATHE_THREADING: `THREAD/TURN,%MFG_THREAD_PITCH`): a bare number right
// after THREAD/TURN|FACE|TAPER is the pitch in CL units, not threads per unit as on PITCH/; the
// statement is read as if PERREV followed it. Anything else is returned as it is.
Statement bare_pitch_in_cl_units(const Statement& st, size_t i) {
  const auto unit = [](const Arg& a) {
    return a.is("TPI") || a.is("IPR") || a.is("MMPR") || a.is("PERREV");
  };
  if (i >= st.args.size() || !st.args[i].is_number() ||
      (i + 1 < st.args.size() && unit(st.args[i + 1])))
    return st;
  Statement copy = st;
  Arg perrev;
  perrev.text = "PERREV";
  perrev.loc = st.args[i].loc;
  copy.args.insert(copy.args.begin() + static_cast<std::ptrdiff_t>(i + 1), perrev);
  return copy;
}

// THREAD/TURN|FACE|TAPER[,pitch couplets]: a single-pass thread, cut at the first statement
// after its GOTOs.
void open_single(PostState& s, const Statement& st, size_t first) {
  open_sequence(s, st, Kind::kSingle);
  SingleThreadInput& in = s.thread.single;
  in = SingleThreadInput{};
  in.loc = st.loc;
  in.lines = s.thread.lines;
  in.word = fmt::format("THREAD/{}", st.args[first].text);
  in.pitch = s.thread.pitch;
  in.units = s.units;
  in.p0 = s.pos ? cl2(s, *s.pos) : Vec2{};
  s.thread.failed = !parse_pitch_words(bare_pitch_in_cl_units(st, first + 1), first + 1, s.units,
                                       in.pitch, s.diags);
}

void close_single(PostState& s) {
  ThreadSequence& t = s.thread;
  t.kind = Kind::kNone;
  ThreadPlan plan;
  if (t.failed || !plan_single_thread(t.single, t.settings, plan, s.diags)) return;
  const CutSite at{t.single.loc, t.single.lines.text(t.single.loc.line)};
  ensure_started(s);
  if (!begin_thread_spindle(s, std::max(std::abs(plan.p1.x), std::abs(plan.p2.x)), at)) return;
  if (cut_path_move(s, plan, plan.passes.front(), 0, at)) {
    set_run_in_out(plan, s.thread.rpm, t.settings.lead_law);
    warn_no_right_lead(s, plan, at);
    thread_planned(s, plan);
    record_exit(s, plan.loc.line, plan.passes.front().to);
  }
  end_thread_spindle(s);
}

// COUPLE/ON[,pitch couplets]: every GOTO up to COUPLE/OFF is one synchronized move, planned
// and cut as it is read.
void open_couple(PostState& s, const Statement& st) {
  ThreadSequence& t = s.thread;
  open_sequence(s, st, Kind::kCouple);
  t.couple_cutting = false;
  t.couple_travel = 0;
  CoupleInput in;
  in.loc = st.loc;
  in.lines = t.lines;
  in.pitch = t.pitch;
  in.units = s.units;
  // On an error the sequence is still entered, so that its GOTOs are not posted as ordinary
  // moves, but none of it is cut.
  if (!parse_pitch_words(st, 1, s.units, in.pitch, s.diags)) {
    t.failed = true;
    return;
  }
  if (!s.pos) {
    error(s, st, st.loc, "COUPLE/ON needs a start point: no GOTO or FROM before it");
    t.failed = true;
    return;
  }
  in.start = cl2(s, *s.pos);
  t.failed = !t.couple.begin(in, t.settings, s.diags);
}

void close_couple(PostState& s) {
  ThreadSequence& t = s.thread;
  t.kind = Kind::kNone;
  if (t.failed) return;
  ThreadPlan plan;
  if (!t.couple.finish(plan, s.diags)) return;
  set_run_in_out(plan, s.thread.rpm, t.settings.lead_law);
  warn_no_right_lead(s, plan, CutSite{t.loc, t.lines.text(t.loc.line)});
  thread_planned(s, plan);
  if (!plan.path.empty()) record_exit(s, plan.loc.line, plan.path.back());
  end_thread_spindle(s);
}

// A GOTO inside COUPLE/ON … OFF: one synchronized move, cut now.
void couple_goto(PostState& s, const Statement& st, Vec2 v) {
  ThreadSequence& t = s.thread;
  if (t.failed) return;
  const ThreadPass* pass = t.couple.add(v, st.loc, st.line_text(st.loc.line), s.diags);
  if (!pass) return;
  if (!t.couple_cutting) {
    t.couple_cutting = true;
    ensure_started(s);
    const double radius = std::max(std::abs(pass->from.x), std::abs(pass->to.x));
    if (!begin_thread_spindle(s, radius, CutSite{t.loc, t.lines.text(t.loc.line)})) {
      t.failed = true;
      return;
    }
  }
  if (!cut_path_move(s, t.couple.plan(), *pass, t.couple_travel,
                     CutSite{st.loc, st.line_text(st.loc.line)})) {
    t.failed = true;
    return;
  }
  t.couple_travel += std::hypot(pass->to.x - pass->from.x, pass->to.z - pass->from.z);
}

void thread_words(PostState& s, const Statement& st, size_t first) {
  ThreadSequence& t = s.thread;
  if (st.args.size() <= first || !st.args[first].is_word()) {
    error(s, st, st.args.size() > first ? st.args[first].loc : st.loc,
          "expected THREAD/ON, THREAD/OFF or THREAD/TURN, FACE or TAPER");
    return;
  }
  const Arg& a = st.args[first];
  if (a.is("OFF") || a.is("NOMORE")) {
    if (t.kind == Kind::kMulti) return close_multi(s, st);
    error(s, st, a.loc,
          fmt::format("{} without a THREAD/ON before it",
                      st.major == "OP" ? "OP/THREAD,NOMORE" : "THREAD/OFF"));
    return;
  }
  if (t.kind == Kind::kMulti || t.kind == Kind::kCouple) {
    error(s, st, st.loc,
          t.kind == Kind::kMulti
              ? fmt::format("THREAD/{} inside the thread started at line {}: {} missing", a.text,
                            t.loc.line, t.multi.off_word)
              : fmt::format("THREAD/{} inside COUPLE/ON of line {}: COUPLE/OFF missing", a.text,
                            t.loc.line));
    return;
  }
  const bool kind_word = a.is("TURN") || a.is("FACE") || a.is("TAPER");
  if (a.is("ON") || (st.major == "OP" && kind_word)) return open_multi(s, st, first);
  if (kind_word) return open_single(s, st, first);
  error(s, st, a.loc,
        fmt::format("unknown THREAD word '{}': expected ON, OFF, TURN, FACE or TAPER", a.text));
}

// The statements a THREAD/ON or COUPLE/ON sequence may hold besides its GOTOs.
bool allowed_inside(const ThreadSequence& t, const Statement& st) {
  const std::string_view w = st.major;
  // FINI ends the program: the open sequence is reported there.
  if (st.form == Statement::Form::kText || w == "GOTO" || w == "FEDRAT" || w == "THREAD" ||
      w == "FINI")
    return true;
  if (t.kind == Kind::kCouple) return w == "GODLTA" || w == "COUPLE";
  return w == "RAPID" || (w == "OP" && !st.args.empty() && st.args[0].is("THREAD"));
}

}  // namespace

void pitch_stmt(PostState& s, const Statement& st) {
  PitchSpec p;
  if (parse_pitch_words(st, 0, s.units, p, s.diags)) s.thread.pitch = p;
}

void thread_stmt(PostState& s, const Statement& st) {
  thread_words(s, st, 0);
}

void op_stmt(PostState& s, const Statement& st) {
  // Pro/ENGINEER and Creo: OP/THREAD,TURN,<THREAD/ON parameters> … OP/THREAD,NOMORE.
  if (!st.args.empty() && st.args[0].is("THREAD")) return thread_words(s, st, 1);
  unknown_stmt(s, st);
}

void couple_stmt(PostState& s, const Statement& st) {
  ThreadSequence& t = s.thread;
  if (st.args.empty() || !st.args[0].is_word()) {
    error(s, st, st.args.empty() ? st.loc : st.args[0].loc, "expected COUPLE/ON or COUPLE/OFF");
    return;
  }
  const Arg& a = st.args[0];
  if (a.is("OFF")) {
    if (t.kind == Kind::kCouple) return close_couple(s);
    error(s, st, a.loc, "COUPLE/OFF without a COUPLE/ON before it");
    return;
  }
  if (!a.is("ON")) {
    error(s, st, a.loc, fmt::format("unknown COUPLE word '{}': expected ON or OFF", a.text));
    return;
  }
  if (t.kind == Kind::kCouple) {
    error(s, st, st.loc,
          fmt::format("COUPLE/ON inside COUPLE/ON of line {}: COUPLE/OFF missing", t.loc.line));
    return;
  }
  if (t.kind == Kind::kMulti) {
    error(s, st, st.loc, fmt::format("COUPLE/ON inside the thread started at line {}", t.loc.line));
    return;
  }
  open_couple(s, st);
}

void thread_goto(PostState& s, const Statement& st, const Point3& p) {
  ThreadSequence& t = s.thread;
  const Vec2 v = cl2(s, p);
  if (t.kind == Kind::kSingle && t.single.gotos.empty() && !t.failed) {
    move_to(s, st, p);  // GOTO/start: an ordinary move
  } else {
    s.pos = p;
    s.rapid_next = false;
  }
  // The lists are kept bounded: one GOTO too many is what the planner needs to report.
  const size_t multi_max = t.multi.words.chain.set ? kMaxChainGotos + 1 : 4;
  if (t.kind == Kind::kMulti && t.multi.gotos.size() < multi_max)
    t.multi.gotos.push_back(ThreadGoto{v, st.loc, SavedLines::of(st)});
  if (t.kind == Kind::kSingle && t.single.gotos.size() < 3)
    t.single.gotos.push_back(ThreadGoto{v, st.loc, SavedLines::of(st)});
  if (t.kind == Kind::kCouple) couple_goto(s, st, v);
}

bool sequence_accepts(PostState& s, const Statement& st) {
  const ThreadSequence& t = s.thread;
  if (t.kind == Kind::kSingle) {
    // Before its first GOTO, RAPID and FEDRAT set up the move to the thread start; after it,
    // the GOTOs end at the first other statement: the thread is cut now.
    const std::string_view w = st.major;
    const bool approach = t.single.gotos.empty() && (w == "RAPID" || w == "FEDRAT");
    if (w != "GOTO" && w != "GODLTA" && !approach) close_single(s);
    return true;
  }
  if (allowed_inside(t, st)) return true;
  const bool multi = t.kind == Kind::kMulti;
  const std::string_view on = multi ? std::string_view(t.multi.on_word) : "COUPLE/ON";
  const std::string_view off = multi ? std::string_view(t.multi.off_word) : "COUPLE/OFF";
  error(s, st, st.loc,
        fmt::format("{} is not allowed inside {} (line {}) ... {}; expected GOTO or {}", st.major,
                    on, t.loc.line, off, off));
  return false;
}

void end_sequences(PostState& s) {
  ThreadSequence& t = s.thread;
  if (t.kind == Kind::kSingle) return close_single(s);
  if (t.kind == Kind::kNone) return;
  const bool multi = t.kind == Kind::kMulti;
  s.diags.error(
      t.loc, t.lines.text(t.loc.line),
      multi ? fmt::format("{} without {} (the file ends first)", t.multi.on_word, t.multi.off_word)
            : std::string("COUPLE/ON without COUPLE/OFF (the file ends first)"));
  t.kind = Kind::kNone;
}

}  // namespace clpost

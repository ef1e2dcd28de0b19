// The interpreter's thread statements: PITCH/, THREAD/ON … THREAD/OFF (and the Pro/E form
// OP/THREAD,TURN … OP/THREAD,NOMORE), THREAD/TURN|FACE|TAPER single passes, COUPLE/ON … OFF.
#include <fmt/format.h>

#include <cmath>
#include <numbers>
#include <tuple>

#include "interpreter/interpreter.h"

namespace clpost {

void Interpreter::pitch_stmt(const Statement& st) {
  PitchSpec p;
  if (parse_pitch_words(st, 0, units_, p, diags_)) pitch_ = p;
}

void Interpreter::thread_stmt(const Statement& st, size_t first) {
  if (st.args.size() <= first || !st.args[first].is_word()) {
    error(st, st.args.size() > first ? st.args[first].loc : st.loc,
          "expected THREAD/ON, THREAD/OFF or THREAD/TURN, FACE or TAPER");
    return;
  }
  const Arg& a = st.args[first];
  if (a.is("OFF") || a.is("NOMORE")) {
    if (seq_ != Seq::kMulti) {
      error(st, a.loc,
            fmt::format("{} without a THREAD/ON before it",
                        st.major == "OP" ? "OP/THREAD,NOMORE" : "THREAD/OFF"));
      return;
    }
    seq_ = Seq::kNone;
    multi_.off_loc = st.loc;
    ThreadPlan plan;
    if (multi_failed_ || !plan_multi_thread(multi_, planner_settings_, plan, diags_)) return;
    emit_thread(plan, multi_.on_lines);
    // The tool ends where the plan leaves it (clear, above the start).
    return;
  }
  if (seq_ == Seq::kMulti) {
    error(st, st.loc,
          fmt::format("THREAD/{} inside the thread started at line {}: THREAD/OFF missing", a.text,
                      seq_loc_.line));
    return;
  }
  if (seq_ == Seq::kCouple) {
    error(st, st.loc,
          fmt::format("THREAD/{} inside COUPLE/ON of line {}: COUPLE/OFF missing", a.text,
                      seq_loc_.line));
    return;
  }
  if (a.is("ON") || (st.major == "OP" && (a.is("TURN") || a.is("FACE") || a.is("TAPER")))) {
    multi_ = MultiThreadInput{};
    if (st.major == "OP") {
      multi_.on_word = fmt::format("OP/THREAD,{}", a.text);
      multi_.off_word = "OP/THREAD,NOMORE";
    }
    // On a bad word the sequence is still entered, so that its GOTOs are not posted as ordinary
    // moves, but it is not planned (one error, not a cascade).
    multi_failed_ = !parse_thread_words(st, first + 1, units_, multi_.words, diags_);
    multi_.on_lines = SavedLines::of(st);
    multi_.on_loc = st.loc;
    multi_.modal_pitch = pitch_;
    multi_.units = units_;
    if (!pos_) {
      error(st, st.loc, "THREAD/ON needs the initial point: no GOTO or FROM before it");
    }
    Vec2 p0 = pos_ ? cl2(*pos_) : Vec2{};
    multi_.p0 = p0;
    multi_.feed_approach = !rapid_next_ && feed_given_;
    rapid_next_ = false;
    seq_ = Seq::kMulti;
    seq_loc_ = st.loc;
    return;
  }
  if (a.is("TURN") || a.is("FACE") || a.is("TAPER")) {
    PitchSpec p = pitch_;
    if (!parse_pitch_words(st, first + 1, units_, p, diags_)) return;
    couple_ = ThreadPlan{};
    couple_.form = ThreadForm::kSingle;
    couple_.loc = st.loc;
    couple_.pitch = p;
    couple_.units = units_;
    seq_lines_ = SavedLines::of(st);
    single_gotos_.clear();
    seq_ = Seq::kSingle;
    seq_loc_ = st.loc;
    return;
  }
  error(st, a.loc,
        fmt::format("unknown THREAD word '{}': expected ON, OFF, TURN, FACE or TAPER", a.text));
}

void Interpreter::op_stmt(const Statement& st) {
  // Pro/ENGINEER and Creo: OP/THREAD,TURN,<THREAD/ON parameters> … OP/THREAD,NOMORE.
  if (!st.args.empty() && st.args[0].is("THREAD")) return thread_stmt(st, 1);
  unknown(st);
}

void Interpreter::couple_stmt(const Statement& st) {
  if (st.args.empty() || !st.args[0].is_word()) {
    error(st, st.args.empty() ? st.loc : st.args[0].loc, "expected COUPLE/ON or COUPLE/OFF");
    return;
  }
  const Arg& a = st.args[0];
  if (a.is("OFF")) {
    if (seq_ != Seq::kCouple) {
      error(st, a.loc, "COUPLE/OFF without a COUPLE/ON before it");
      return;
    }
    seq_ = Seq::kNone;
    if (!couple_.pitch.set) return;  // COUPLE/ON had an error
    ++stats_.threads;
    if (on_thread_) on_thread_(couple_);
    end_thread_spindle();
    return;
  }
  if (!a.is("ON")) {
    error(st, a.loc, fmt::format("unknown COUPLE word '{}': expected ON or OFF", a.text));
    return;
  }
  if (seq_ == Seq::kCouple) {
    error(st, st.loc,
          fmt::format("COUPLE/ON inside COUPLE/ON of line {}: COUPLE/OFF missing", seq_loc_.line));
    return;
  }
  if (seq_ == Seq::kMulti) {
    error(st, st.loc, fmt::format("COUPLE/ON inside the thread started at line {}", seq_loc_.line));
    return;
  }
  PitchSpec p = pitch_;
  if (!parse_pitch_words(st, 1, units_, p, diags_)) return;
  couple_ = ThreadPlan{};
  couple_.form = ThreadForm::kCouple;
  couple_.loc = st.loc;
  couple_.pitch = p;
  couple_.lead = p.pitch * p.starts;
  couple_.units = units_;
  seq_lines_ = SavedLines::of(st);
  seq_ = Seq::kCouple;
  seq_loc_ = st.loc;
  couple_started_ = false;
  // On an error the sequence is still entered, so that its GOTOs are not posted as ordinary
  // moves, but none of it is cut: thread_goto skips GOTOs while the pitch is not set.
  if (!check_pitch(st, p)) {
    couple_.pitch.set = false;
    return;
  }
  if (!pos_) {
    error(st, st.loc, "COUPLE/ON needs a start point: no GOTO or FROM before it");
    couple_.pitch.set = false;
    return;
  }
  couple_.path.push_back(cl2(*pos_));
  couple_.p1 = cl2(*pos_);
}

bool Interpreter::check_pitch(const Statement& st, const PitchSpec& p) {
  if (!p.set) {
    error(st, st.loc,
          "no pitch in force: give PITCH/ before the thread or a pitch on this statement");
    return false;
  }
  if (p.lead_change != 0 && !m_.variable_lead) {
    error(st, p.lead_change_loc.line ? p.lead_change_loc : st.loc,
          fmt::format("variable lead (INCR/DECR {}) cannot be cut on machine '{}': it has no "
                      "variable-lead threading",
                      p.lead_change, m_.name));
    return false;
  }
  return true;
}

void Interpreter::thread_goto(const Statement& st, Point3 p) {
  Vec2 v = cl2(p);
  if (seq_ == Seq::kMulti) {
    multi_.gotos.push_back(ThreadGoto{v, st.loc, SavedLines::of(st)});
    if (multi_.gotos.size() > 3) {
      // Reported once by the planner at THREAD/OFF; keep the list bounded.
      multi_.gotos.resize(4);
    }
    pos_ = p;
    return;
  }
  if (seq_ == Seq::kSingle) {
    if (single_gotos_.empty()) {
      // GOTO/start: an ordinary move.
      single_gotos_.push_back(ThreadGoto{v, st.loc, SavedLines::of(st)});
      seq_ = Seq::kNone;  // move_to must not see the sequence
      move_to(st, p);
      seq_ = Seq::kSingle;
      couple_.p1 = v;
      couple_.path.push_back(v);
      return;
    }
    seq_ = Seq::kNone;
    if (!check_pitch(st, couple_.pitch)) return;
    couple_.lead = couple_.pitch.pitch * couple_.pitch.starts;
    couple_.p2 = v;
    couple_.path.push_back(v);
    single_pass_plan(couple_);
    if (!begin_thread_spindle(couple_, seq_lines_)) return;
    prog_.thread(lathe(p), couple_.lead);
    ++stats_.motions;
    pos_ = p;
    ++stats_.threads;
    ++stats_.passes;
    if (on_thread_) on_thread_(couple_);
    end_thread_spindle();
    return;
  }
  // COUPLE: every GOTO is one synchronized move, streamed.
  if (!couple_.pitch.set) return;  // reported at COUPLE/ON
  if (!couple_started_) {
    couple_started_ = true;
    ThreadPlan probe = couple_;
    probe.p2 = v;
    if (!begin_thread_spindle(probe, seq_lines_)) return;
  }
  prog_.thread(lathe(p), couple_.lead);
  ++stats_.motions;
  if (couple_.path.size() < kMaxKeptPath) {
    couple_.path.push_back(v);
    ThreadPass pass;
    pass.n = static_cast<int>(couple_.passes.size()) + 1;
    pass.from = couple_.path[couple_.path.size() - 2];
    pass.to = v;
    pass.approach = pass.from;
    pass.pullout_end = pass.clear = v;
    couple_.passes.push_back(pass);
  }
  couple_.p2 = v;
  ++stats_.passes;
  pos_ = p;
}

void Interpreter::single_pass_plan(ThreadPlan& plan) {
  Vec2 d{plan.p2.x - plan.p1.x, plan.p2.z - plan.p1.z};
  plan.kind = std::abs(d.x) < 1e-9   ? ThreadKind::kTurn
              : std::abs(d.z) < 1e-9 ? ThreadKind::kFace
                                     : ThreadKind::kTaper;
  plan.lead_along_z = std::abs(d.z) >= std::abs(d.x);
  ThreadPass pass;
  pass.n = 1;
  pass.approach = pass.from = plan.p1;
  pass.to = pass.pullout_end = pass.clear = plan.p2;
  plan.passes.assign(1, pass);
  plan.end_position = plan.p2;
}

// Before a thread: the spindle must turn at a constant speed (G97) and the machine must be able
// to feed lead x rpm.
bool Interpreter::begin_thread_spindle(const ThreadPlan& plan, const SavedLines& lines) {
  auto fail = [&](std::string msg) {
    diags_.error(plan.loc, lines.text(plan.loc.line), std::move(msg));
    return false;
  };
  if (!spindle_on_)
    return fail("thread cut with the spindle stopped: program SPINDL/ before the thread");
  double rpm = spindle_value_;
  forced_rpm_ = false;
  if (css_) {
    // Constant surface speed cannot cut a thread: turn it into the rpm it gives at the thread's
    // largest diameter, limited by the CSS speed limit, and restore CSS afterwards.
    double radius = std::max({std::abs(plan.p1.x), std::abs(plan.p2.x), 1e-9});
    double diameter = 2 * radius;
    double per_unit = units_ == LengthUnit::kInch ? 12.0 : 1000.0;  // ft/min or m/min
    rpm = std::floor(spindle_value_ * per_unit / (std::numbers::pi * diameter));
    rpm = std::min(rpm, css_max_rpm_);
    if (rpm < 1) rpm = 1;
    ensure_started();
    prog_.comment(
        fmt::format("constant surface speed {} off for the thread: {} rpm", spindle_value_, rpm));
    if (TemplateWrite r = prog_.spindle_rpm(rpm, spindle_dir_); !r)
      return fail(template_error(m_, r));
    forced_rpm_ = true;
  }
  double lead = plan.pitch.pitch * plan.pitch.starts;
  double feed = lead * rpm;
  if (m_.max_feed > 0 && feed > m_.max_feed + 1e-9) {
    return fail(
        fmt::format("thread feed too fast for machine '{}': lead {} x {} rpm = {} per minute, "
                    "above its maximum feed {}",
                    m_.name, lead, rpm, feed, m_.max_feed));
  }
  // Each axis moves its share of the lead: the lead axis all of it, the other one in proportion
  // to the thread's slope (a taper's X, a face-taper's Z).
  double dx = std::abs(plan.p2.x - plan.p1.x), dz = std::abs(plan.p2.z - plan.p1.z);
  double fz = plan.lead_along_z ? feed : (dx > 0 ? feed * dz / dx : 0);
  double fx = plan.lead_along_z ? (dz > 0 ? feed * dx / dz : 0) : feed;
  for (auto [axis, f, limit] :
       {std::tuple{'X', fx, m_.max_feed_x}, std::tuple{'Z', fz, m_.max_feed_z}}) {
    if (limit > 0 && f > limit + 1e-9)
      return fail(
          fmt::format("thread feed too fast for machine '{}': the {} axis moves {} per "
                      "minute (lead {} x {} rpm), above its limit {} (limits.max_feed_{})",
                      m_.name, axis, f, lead, rpm, limit, static_cast<char>(axis + 32)));
  }
  thread_rpm_ = rpm;
  return true;
}

void Interpreter::end_thread_spindle() {
  if (!forced_rpm_) return;
  forced_rpm_ = false;
  // CSS was written at its SPINDL line, so the template is there.
  if (TemplateWrite r = prog_.spindle_css(spindle_value_, css_max_rpm_, spindle_dir_); !r)
    diags_.error(SourceLoc{}, {}, template_error(m_, r));
}

void Interpreter::emit_thread(ThreadPlan& plan, const SavedLines& lines) {
  ensure_started();
  if (!begin_thread_spindle(plan, lines)) return;
  ++stats_.threads;
  stats_.passes += plan.passes.size();
  if (on_thread_) on_thread_(plan);
  prog_.comment(fmt::format("thread line {}: {} passes, pitch {:.6g}, depth {:.6g}", plan.loc.line,
                            plan.passes.size(), plan.pitch.pitch, plan.depth));
  EmitContext ctx{diags_, lines, thread_rpm_, feed_, feed_mode_};
  emitter_->emit(plan, prog_, ctx);
  stats_.motions += plan.passes.size() * 4;
  // Where the tool is now, in the CL frame (radial, axial; the third axis 0).
  Point3 p;
  double r = m_.cl_x_is_diameter ? plan.end_position.x * 2 : plan.end_position.x;
  double* axes[3] = {&p.x, &p.y, &p.z};
  *axes[static_cast<int>(m_.cl_radial)] = r;
  *axes[static_cast<int>(m_.cl_axial)] = plan.end_position.z;
  pos_ = p;
  end_thread_spindle();
}

void Interpreter::end_sequence_errors(uint32_t line) {
  (void)line;
  if (seq_ == Seq::kNone) return;
  const char* what = seq_ == Seq::kMulti    ? "THREAD/ON without THREAD/OFF"
                     : seq_ == Seq::kCouple ? "COUPLE/ON without COUPLE/OFF"
                                            : "single-pass thread without its second GOTO";
  diags_.error(
      seq_loc_,
      seq_ == Seq::kMulti ? multi_.on_lines.text(seq_loc_.line) : seq_lines_.text(seq_loc_.line),
      fmt::format("{} (the file ends first)", what));
  seq_ = Seq::kNone;
}

}  // namespace clpost

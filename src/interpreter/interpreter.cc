#include "interpreter/interpreter.h"

#include <fmt/format.h>

#include <algorithm>
#include <cmath>
#include <numbers>
#include <optional>

namespace clpost {

namespace {

constexpr double kMmPerInch = 25.4;

double axis_value(double x, double y, double z, ClAxis a) {
  return a == ClAxis::kX ? x : a == ClAxis::kY ? y : z;
}

// Records that carry nothing a lathe program needs: understood and skipped, noted once.
constexpr std::string_view kSkipped[] = {"TLDATA",
                                         "MSYS",
                                         "PAINT",
                                         "END-OF-PATH",
                                         "MACHIN",
                                         "CUTTER",
                                         "SELECT",
                                         "TRNTYP",
                                         "CSYS",
                                         "CNTRL",
                                         "SETUP",
                                         "CSI_SET_FLUTE_LENGTH",
                                         "CSI_SET_EXTENSION_LENGTH",
                                         "MFGNO",
                                         "FEATNO",
                                         "CLEARP",
                                         "TOLER",
                                         "INTOL",
                                         "OUTTOL",
                                         "DISPLY",
                                         "AUTOPS",
                                         "PLABEL",
                                         "CALSUB",
                                         "ORIGIN"};

// The major words statement() acts on or skips: for these a statement the reader could not read
// is an error (at its problem); any other word is unknown.
bool known_major(std::string_view w) {
  static constexpr std::string_view kActed[] = {
      "GOTO",   "RAPID",  "FEDRAT", "FROM",   "GODLTA", "CIRCLE", "UNITS",     "UNIT",
      "SPINDL", "LOADTL", "LOAD",   "TURRET", "COOLNT", "CUTCOM", "DELAY",     "PITCH",
      "THREAD", "COUPLE", "OP",     "CYCLE",  "STOP",   "OPSTOP", "END",       "FINI",
      "GOHOME", "MULTAX", "NURBS",  "KNOT",   "PARTNO", "PPRINT", "TOOL PATH", "INSERT"};
  for (std::string_view k : kActed) {
    if (w == k) return true;
  }
  for (std::string_view k : kSkipped) {
    if (w == k) return true;
  }
  return false;
}

// Out of line: the plain statement path keeps no string of it.
[[gnu::noinline, gnu::cold]] std::string modifiers_refused(const Statement& st) {
  std::string head;
  for (const Arg& m : st.modifiers) head += std::string(m.text) + ',';
  return fmt::format(
      "{}{}/: words before the major word (APT motion modifiers) are not supported; the "
      "statement may move the tool, so it cannot be left out",
      head, st.major);
}

std::string upper_list(std::initializer_list<std::string_view> words) {
  std::string s;
  for (std::string_view w : words) s += (s.empty() ? "" : ", ") + std::string(w);
  return s;
}

}  // namespace

Interpreter::Interpreter(const Machine& m, NcProgram& prog, Diagnostics& diags,
                         const PostOptions& opts)
    : m_(m), prog_(prog), diags_(diags), opts_(opts), emitter_(make_emitter(m)) {
  units_ = m.default_units == "in" ? LengthUnit::kInch : LengthUnit::kMm;
  planner_settings_ = planner_settings(m);
}

Interpreter::~Interpreter() = default;

// ---------------------------------------------------------------------------------------------
// Diagnostics

void Interpreter::error(const Statement& st, SourceLoc loc, std::string msg) {
  diags_.error(loc, st.line_text(loc.line), std::move(msg));
}

void Interpreter::warning(const Statement& st, SourceLoc loc, std::string msg) {
  diags_.warning(loc, st.line_text(loc.line), std::move(msg));
}

void Interpreter::note_once(const Statement& st, std::string_view key, std::string msg) {
  if (std::find(noted_.begin(), noted_.end(), key) != noted_.end()) return;
  noted_.emplace_back(key);
  diags_.note(st.loc, st.line_text(st.loc.line), std::move(msg));
}

bool Interpreter::bad_number_arg(const Statement& st, size_t i, std::string_view what) {
  if (i >= st.args.size()) {
    SourceLoc end = st.args.empty() ? st.loc : st.args.back().loc;
    error(st, end, fmt::format("{}/ needs {} (argument {})", st.major, what, i + 1));
    return false;
  }
  const Arg& a = st.args[i];
  if (!a.is_number()) {
    error(st, a.loc, fmt::format("expected {} but found '{}'", what, a.text));
    return false;
  }
  return in_range(st, a, what);  // false: its error is reported
}

bool Interpreter::in_range(const Statement& st, const Arg& a, std::string_view what) {
  if (within_limits(a.number)) return true;
  error(st, a.loc,
        fmt::format("{} '{}' is out of range: CL values must be between -{} and {}", what, a.text,
                    kMaxValue, kMaxValue));
  return false;
}

// ---------------------------------------------------------------------------------------------
// Dispatch

void Interpreter::statement(const Statement& st) {
  ++stats_.statements;
  const std::string_view w = st.major;
  if (ended_) {
    if (w != "FINI") note_once(st, "after-fini", "statements after FINI are ignored");
    return;
  }
  if (st.form == Statement::Form::kText) {
    if (w == "PARTNO") {
      if (started_) {
        prog_.comment(st.text);
      } else {
        partno_ = std::string(st.text);
      }
    } else if (w == "PPRINT") {
      ensure_started();
      prog_.comment(st.text);
    } else if (w == "INSERT") {
      ensure_started();
      prog_.raw(st.text);
    } else {
      unknown(st);
    }
    return;
  }
  // Thread sequences accept only motion and a few modal statements inside.
  if (seq_ == Seq::kMulti || seq_ == Seq::kSingle) {
    bool closing =
        (w == "THREAD" && !st.args.empty() && st.args[0].is("OFF")) ||
        (w == "OP" && st.args.size() >= 2 && st.args[0].is("THREAD") && st.args[1].is("NOMORE"));
    // A THREAD/ON (or THREAD/TURN...) inside THREAD/ON: thread_stmt says THREAD/OFF is missing.
    const bool nested_thread = seq_ == Seq::kMulti && w == "THREAD";
    if (w != "GOTO" && w != "RAPID" && w != "FEDRAT" && !closing && !nested_thread) {
      if (seq_ == Seq::kSingle) {
        error(st, st.loc,
              fmt::format(
                  "expected the second GOTO of the single-pass thread started at line {}, found {}",
                  seq_loc_.line, w));
        seq_ = Seq::kNone;
      } else {
        error(st, st.loc,
              fmt::format("{} is not allowed inside THREAD/ON (line {}) ... THREAD/OFF; "
                          "expected GOTO or THREAD/OFF",
                          w, seq_loc_.line));
        return;
      }
    }
  }

  // What the reader could not read (reader/statement.h): an error at its problem for a word this
  // post knows, else an unknown statement. Words before the major word (TLON,GOFWD/...,
  // RAPID,GOTO/...) are APT motion: not acted on yet, and a motion must not become a comment.
  if (st.has_problem() || !st.modifiers.empty()) [[unlikely]] {
    if (st.has_problem() && known_major(w)) return error(st, st.problem.loc, st.problem.message);
    if (st.modifiers.empty()) return unknown(st);
    return error(st, st.modifiers[0].loc, modifiers_refused(st));
  }

  if (w == "GOTO") return goto_stmt(st);
  if (w == "RAPID") {
    rapid_next_ = true;
    return;
  }
  if (w == "FEDRAT") return fedrat_stmt(st);
  if (w == "FROM") return from_stmt(st);
  if (w == "GODLTA") return godlta_stmt(st);
  if (w == "CIRCLE") return circle_stmt(st);
  if (w == "UNITS" || w == "UNIT") return units_stmt(st);
  if (w == "SPINDL") return spindl_stmt(st);
  if (w == "LOADTL") return loadtl_stmt(st, 0);
  if (w == "LOAD") {
    if (!st.args.empty() && st.args[0].is("TOOL")) return loadtl_stmt(st, 1);
    return unknown(st);
  }
  if (w == "TURRET") return loadtl_stmt(st, 0);
  if (w == "COOLNT") return coolnt_stmt(st);
  if (w == "CUTCOM") return cutcom_stmt(st);
  if (w == "DELAY") return delay_stmt(st);
  if (w == "PITCH") return pitch_stmt(st);
  if (w == "THREAD") return thread_stmt(st, 0);
  if (w == "COUPLE") return couple_stmt(st);
  if (w == "OP") return op_stmt(st);
  if (w == "CYCLE") return cycle_stmt(st);
  if (w == "STOP" || w == "OPSTOP") {
    ensure_started();
    prog_.program_stop(w == "OPSTOP");
    return;
  }
  if (w == "END") {
    end_seen_ = true;
    return;
  }
  if (w == "FINI") {
    finish(st.loc.line);
    ended_ = true;
    return;
  }
  if (w == "GOHOME") {
    warning(st, st.loc, "GOHOME: this machine has no home position in its machine file; ignored");
    return;
  }
  if (w == "TOOL PATH") {
    // NX operation header: TOOL PATH/<operation>,TOOL,<tool name>
    ensure_started();
    std::string text = "operation";
    for (const Arg& a : st.args) text += ' ' + std::string(a.text);
    prog_.comment(text);
    return;
  }
  if (w == "MULTAX") {
    if (!st.args.empty() && st.args[0].is("ON"))
      note_once(st, "MULTAX", "MULTAX/ON: tool axis vectors are ignored on a lathe");
    return;
  }
  for (std::string_view s : kSkipped) {
    if (w == s) return skipped(st, "nothing a lathe program needs");
  }
  if (w == "NURBS" || w == "KNOT") {
    error(st, st.loc,
          fmt::format("{}/ spline motion cannot be cut on a lathe post; output it as GOTO points "
                      "from the CAM system",
                      w));
    return;
  }
  unknown(st);
}

void Interpreter::skipped(const Statement& st, std::string_view why) {
  note_once(st, st.major, fmt::format("{} records skipped ({})", st.major, why));
}

void Interpreter::unknown(const Statement& st) {
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
  if (opts_.strict) {
    error(st, st.loc, fmt::format("unknown statement '{}' (--strict)", st.major));
    return;
  }
  warning(st, st.loc, fmt::format("unknown statement '{}' written as a comment", st.major));
  ensure_started();
  prog_.comment(text);
}

// ---------------------------------------------------------------------------------------------
// Modal statements

void Interpreter::ensure_started() {
  if (started_) return;
  started_ = true;
  prog_.start(partno_, units_ == LengthUnit::kInch, diags_.file());
  if (!partno_.empty()) prog_.comment(partno_);
}

void Interpreter::units_stmt(const Statement& st) {
  if (st.args.empty() || !st.args[0].is_word()) {
    error(st, st.args.empty() ? st.loc : st.args[0].loc, "expected UNITS/MM or UNITS/INCHES");
    return;
  }
  const Arg& a = st.args[0];
  LengthUnit u;
  if (a.is("MM") || a.is("MILLIMETERS") || a.is("METRIC")) {
    u = LengthUnit::kMm;
  } else if (a.is("INCHES") || a.is("INCH") || a.is("IN")) {
    u = LengthUnit::kInch;
  } else {
    error(st, a.loc, fmt::format("unknown unit '{}': expected MM or INCHES", a.text));
    return;
  }
  if (started_ && u != units_) {
    if (pos_)
      warning(st, st.loc, "units change after motion: later coordinates are read in the new units");
    prog_.writer().code(m_.code(u == LengthUnit::kInch ? "inch" : "metric")).end_block();
  }
  units_ = u;
  units_given_ = true;
}

void Interpreter::fedrat_stmt(const Statement& st) {
  double value = 0;
  bool have_value = false;
  FeedMode mode = FeedMode::kPerMinute;
  double factor = 1;  // to CL units
  double to_cl_from_mm = units_ == LengthUnit::kInch ? 1 / kMmPerInch : 1;
  double to_cl_from_in = units_ == LengthUnit::kInch ? 1 : kMmPerInch;
  for (const Arg& a : st.args) {
    if (a.is_number()) {
      if (have_value) {
        error(st, a.loc,
              fmt::format("FEDRAT/ takes one feed value; found a second number '{}'", a.text));
        return;
      }
      if (!in_range(st, a, "feed")) return;
      value = a.number;
      have_value = true;
    } else if (a.is("MMPM")) {
      mode = FeedMode::kPerMinute, factor = to_cl_from_mm;
    } else if (a.is("MMPR")) {
      mode = FeedMode::kPerRev, factor = to_cl_from_mm;
    } else if (a.is("IPM")) {
      mode = FeedMode::kPerMinute, factor = to_cl_from_in;
    } else if (a.is("IPR")) {
      mode = FeedMode::kPerRev, factor = to_cl_from_in;
    } else if (a.is("PERMIN") || a.is("FPM")) {
      mode = FeedMode::kPerMinute;
    } else if (a.is("PERREV") || a.is("FPR")) {
      mode = FeedMode::kPerRev;
    } else {
      error(st, a.loc,
            fmt::format("unknown FEDRAT word '{}': expected a feed and one of {}", a.text,
                        upper_list({"MMPM", "MMPR", "IPM", "IPR", "PERMIN", "PERREV"})));
      return;
    }
  }
  if (!have_value) {
    error(st, st.loc, "FEDRAT/ needs a feed value");
    return;
  }
  if (!(value > 0)) {
    SourceLoc l = st.loc;
    for (const Arg& a : st.args)
      if (a.is_number()) l = a.loc;
    error(st, l, fmt::format("feed must be positive, got {}", value));
    return;
  }
  feed_ = value * factor;
  feed_mode_ = mode;
  feed_given_ = true;
  if (m_.max_feed > 0 && mode == FeedMode::kPerMinute && feed_ > m_.max_feed) {
    warning(st, st.loc,
            fmt::format("feed {} exceeds the machine's maximum feed {}", feed_, m_.max_feed));
  }
  prog_.set_feed(feed_, feed_mode_);
}

void Interpreter::spindl_stmt(const Statement& st) {
  std::optional<double> value, max_rpm;
  bool css = false, off = false, on = false;
  std::optional<SpindleDir> dir;
  SourceLoc value_loc = st.loc;
  for (size_t i = 0; i < st.args.size(); ++i) {
    const Arg& a = st.args[i];
    if (a.is_number()) {
      if (value) {
        error(st, a.loc,
              fmt::format("SPINDL/ takes one speed; found a second number '{}'", a.text));
        return;
      }
      if (!in_range(st, a, "spindle speed")) return;
      value = a.number, value_loc = a.loc;
    } else if (a.is("RPM")) {
      css = false;
    } else if (a.is("SMM") || a.is("SFM")) {
      css = true;
      // SMM: metres per minute, SFM: feet per minute; converted to the output unit's speed.
      if (a.is("SMM") && units_ == LengthUnit::kInch)
        note_once(st, "SMM-inch",
                  "SMM in an inch program: written as metres per minute in the G96 word");
    } else if (a.is("CLW")) {
      dir = SpindleDir::kCw;
    } else if (a.is("CCLW")) {
      dir = SpindleDir::kCcw;
    } else if (a.is("OFF")) {
      off = true;
    } else if (a.is("ON")) {
      on = true;
    } else if (a.is("MAXRPM")) {
      if (i + 1 >= st.args.size() || !st.args[i + 1].is_number()) {
        error(st, a.loc, "MAXRPM needs a speed limit");
        return;
      }
      if (!in_range(st, st.args[i + 1], "MAXRPM")) return;
      max_rpm = st.args[++i].number;
    } else if (a.is("RANGE")) {
      if (i + 1 < st.args.size() && st.args[i + 1].is_number()) ++i;
    } else {
      error(st, a.loc,
            fmt::format("unknown SPINDL word '{}': expected a speed and {}", a.text,
                        upper_list({"RPM", "SMM", "SFM", "CLW", "CCLW", "MAXRPM", "OFF", "ON"})));
      return;
    }
  }
  ensure_started();
  if (off) {
    spindle_on_ = false;
    prog_.spindle_stop();
    return;
  }
  if (!value) {
    if (on && spindle_value_ > 0)
      value = spindle_value_, css = css_;
    else {
      error(st, st.loc, "SPINDL/ needs a speed (or SPINDL/ON after an earlier speed)");
      return;
    }
  }
  if (!(*value > 0)) {
    error(st, value_loc, fmt::format("spindle speed must be positive, got {}", *value));
    return;
  }
  if (dir) spindle_dir_ = *dir;
  if (!css && m_.max_rpm > 0 && *value > m_.max_rpm) {
    error(st, value_loc,
          fmt::format("spindle speed {} rpm exceeds the machine's maximum {} rpm", *value,
                      m_.max_rpm));
    return;
  }
  css_ = css;
  spindle_value_ = *value;
  spindle_on_ = true;
  if (css) {
    double limit = max_rpm.value_or(m_.max_rpm);
    if (!(limit > 0)) {
      error(st, st.loc,
            "constant surface speed needs a speed limit: add MAXRPM,n or set limits.max_rpm in the "
            "machine file");
      return;
    }
    if (m_.max_rpm > 0 && limit > m_.max_rpm) limit = m_.max_rpm;
    css_max_rpm_ = limit;
    prog_.spindle_css(*value, limit, spindle_dir_);
  } else {
    prog_.spindle_rpm(*value, spindle_dir_);
  }
}

void Interpreter::loadtl_stmt(const Statement& st, size_t first) {
  double tool = 0;
  if (!number_arg(st, first, "a tool number", tool)) return;
  if (tool < 0 || tool != std::floor(tool) || tool > 9999) {
    error(st, st.args[first].loc,
          fmt::format("tool number must be a whole number 0..9999, got {}", st.args[first].text));
    return;
  }
  int offset = static_cast<int>(tool);
  for (size_t i = first + 1; i + 1 < st.args.size(); ++i) {
    if ((st.args[i].is("ADJUST") || st.args[i].is("OSETNO") || st.args[i].is("OFFSET")) &&
        st.args[i + 1].is_number()) {
      const Arg& o = st.args[i + 1];
      if (o.number < 0 || o.number != std::floor(o.number) || o.number > 9999) {
        error(st, o.loc, fmt::format("tool offset must be a whole number 0..9999, got {}", o.text));
        return;
      }
      offset = static_cast<int>(o.number);
    }
  }
  ensure_started();
  tool_offset_ = offset;
  prog_.tool_change(static_cast<int>(tool), offset, "");
  // A tool change cancels what the control knew of the position.
}

void Interpreter::coolnt_stmt(const Statement& st) {
  if (st.args.empty() || !st.args[0].is_word()) {
    error(st, st.args.empty() ? st.loc : st.args[0].loc,
          "expected COOLNT/ON, FLOOD, MIST, THRU, AIR or OFF");
    return;
  }
  const Arg& a = st.args[0];
  Coolant c;
  if (a.is("ON") || a.is("FLOOD"))
    c = Coolant::kFlood;
  else if (a.is("MIST"))
    c = Coolant::kMist;
  else if (a.is("THRU") || a.is("TOOL"))
    c = Coolant::kThrough;
  else if (a.is("AIR"))
    c = Coolant::kAir;
  else if (a.is("OFF"))
    c = Coolant::kOff;
  else {
    error(st, a.loc,
          fmt::format("unknown COOLNT word '{}': expected ON, FLOOD, MIST, THRU, AIR or OFF",
                      a.text));
    return;
  }
  ensure_started();
  prog_.coolant(c);
}

void Interpreter::cutcom_stmt(const Statement& st) {
  if (st.args.empty() || !st.args[0].is_word()) {
    error(st, st.args.empty() ? st.loc : st.args[0].loc, "expected CUTCOM/LEFT, RIGHT or OFF");
    return;
  }
  const Arg& a = st.args[0];
  CutterComp c;
  if (a.is("LEFT"))
    c = CutterComp::kLeft;
  else if (a.is("RIGHT"))
    c = CutterComp::kRight;
  else if (a.is("OFF"))
    c = CutterComp::kOff;
  else {
    error(st, a.loc, fmt::format("unknown CUTCOM word '{}': expected LEFT, RIGHT or OFF", a.text));
    return;
  }
  ensure_started();
  prog_.cutter_comp(c);
}

// DELAY/t dwells t seconds, DELAY/REV,n n spindle revolutions. The machine's dwell template
// asks for {seconds} or {revolutions}; one becomes the other through the spindle speed in RPM.
void Interpreter::delay_stmt(const Statement& st) {
  const bool in_revs = !st.args.empty() && st.args[0].is("REV");
  const size_t i = in_revs ? 1 : 0;
  double v = 0;
  if (!number_arg(st, i, in_revs ? "a dwell in revolutions" : "a dwell time in seconds", v)) return;
  if (!(v >= 0)) {
    error(st, st.args[i].loc,
          fmt::format("{} must not be negative, got {}",
                      in_revs ? "a dwell in revolutions" : "dwell time", v));
    return;
  }
  if (!m_.templates.count("dwell")) {
    error(st, st.loc,
          fmt::format("machine '{}' has no 'dwell' template: the dwell cannot be posted", m_.name));
    return;
  }
  const bool rpm_known = spindle_on_ && !css_ && spindle_value_ > 0;
  std::optional<double> seconds, revolutions;
  if (in_revs) {
    revolutions = v;
    if (rpm_known) seconds = v * 60 / spindle_value_;
  } else {
    seconds = v;
    if (rpm_known) revolutions = v * spindle_value_ / 60;
  }
  ensure_started();
  if (prog_.dwell(seconds, revolutions)) return;
  error(st, st.loc,
        fmt::format("machine '{}' dwells in {}: a dwell of {} {} needs the spindle turning at a "
                    "set RPM to convert, and the spindle {}",
                    m_.name, in_revs ? "seconds" : "revolutions", v,
                    in_revs ? "revolutions" : "seconds",
                    !spindle_on_ ? "is stopped"
                    : css_       ? "runs at constant surface speed"
                                 : "has no speed"));
}

void Interpreter::cycle_stmt(const Statement& st) {
  if (!st.args.empty() && st.args[0].is("OFF")) {
    in_cycle_ = false;
    return;
  }
  if (!st.args.empty() && st.args[0].is("UNDCUT")) return undercut_stmt(st);
  in_cycle_ = true;  // its hole positions are not posted as plain moves
  std::string kind = st.args.empty() ? std::string("?") : std::string(st.args[0].text);
  error(st, st.loc,
        fmt::format("CYCLE/{} is not supported on machine '{}': its holes would be lost; "
                    "post the drilling with a milling post or output it as motion",
                    kind, m_.name));
}

// ---------------------------------------------------------------------------------------------
// Motion

Vec2 Interpreter::cl2(Point3 p) const {
  double r = axis_value(p.x, p.y, p.z, m_.cl_radial);
  if (m_.cl_x_is_diameter) r /= 2;
  return Vec2{r, axis_value(p.x, p.y, p.z, m_.cl_axial)};
}

LathePoint Interpreter::lathe(Point3 p) const {
  Vec2 v = cl2(p);
  return LathePoint{v.x, v.z};
}

void Interpreter::from_stmt(const Statement& st) {
  Point3 p;
  if (!number_arg(st, 0, "X", p.x) || !number_arg(st, 1, "Y", p.y)) return;
  if (st.args.size() >= 3 && !number_arg(st, 2, "Z", p.z)) return;
  pos_ = p;
}

void Interpreter::goto_stmt(const Statement& st) {
  size_t n = st.args.size();
  if (n != 2 && n != 3 && n != 6) {
    error(st, n ? st.args[std::min<size_t>(n, 6) - 1].loc : st.loc,
          fmt::format("GOTO/ takes x,y[,z[,i,j,k]]: 2, 3 or 6 numbers, found {}", n));
    return;
  }
  Point3 p;
  if (!number_arg(st, 0, "X", p.x) || !number_arg(st, 1, "Y", p.y)) return;
  if (n >= 3) {
    if (!number_arg(st, 2, "Z", p.z)) return;
  } else {
    p.z = pos_ ? pos_->z : 0;
  }
  if (n == 6) {
    for (size_t i = 3; i < 6; ++i) {
      double v;
      if (!number_arg(st, i, "a tool axis component", v)) return;
    }
    note_once(st, "tool-axis", "tool axis vectors (GOTO i,j,k) are ignored on a lathe");
  }
  if (in_cycle_) return;  // reported at CYCLE/
  if (seq_ != Seq::kNone) return thread_goto(st, p);
  move_to(st, p);
}

void Interpreter::godlta_stmt(const Statement& st) {
  if (!pos_) {
    error(st, st.loc, "GODLTA/ needs a known position: no GOTO or FROM before it");
    return;
  }
  Point3 d;
  if (st.args.size() == 1) {
    if (!number_arg(st, 0, "a Z distance", d.z)) return;
  } else {
    if (!number_arg(st, 0, "dX", d.x) || !number_arg(st, 1, "dY", d.y)) return;
    if (st.args.size() >= 3 && !number_arg(st, 2, "dZ", d.z)) return;
  }
  Point3 p{pos_->x + d.x, pos_->y + d.y, pos_->z + d.z};
  if (seq_ != Seq::kNone) return thread_goto(st, p);
  move_to(st, p);
}

void Interpreter::circle_stmt(const Statement& st) {
  Circle c{};
  if (!number_arg(st, 0, "the centre X", c.cx) || !number_arg(st, 1, "the centre Y", c.cy) ||
      !number_arg(st, 2, "the centre Z", c.cz) || !number_arg(st, 3, "the axis I", c.ax) ||
      !number_arg(st, 4, "the axis J", c.ay) || !number_arg(st, 5, "the axis K", c.az) ||
      !number_arg(st, 6, "the radius", c.radius))
    return;
  c.loc = st.loc;
  // The arc turns about its axis; in the lathe frame that axis must be normal to the plane.
  ClAxis third =
      static_cast<ClAxis>(3 - static_cast<int>(m_.cl_radial) - static_cast<int>(m_.cl_axial));
  double ax[3] = {c.ax, c.ay, c.az};
  double len = std::sqrt(c.ax * c.ax + c.ay * c.ay + c.az * c.az);
  if (!(len > 0) || std::abs(std::abs(ax[static_cast<int>(third)] / len) - 1) > 1e-6) {
    error(st, st.loc,
          fmt::format("CIRCLE axis ({}, {}, {}) is not normal to the lathe plane: the arc cannot "
                      "be cut on a lathe",
                      c.ax, c.ay, c.az));
    return;
  }
  circle_ = c;
}

void Interpreter::move_to(const Statement& st, Point3 p) {
  // The lathe plane is spanned by the radial and axial CL axes; the third must stay at 0.
  ClAxis third =
      static_cast<ClAxis>(3 - static_cast<int>(m_.cl_radial) - static_cast<int>(m_.cl_axial));
  double off = axis_value(p.x, p.y, p.z, third);
  if (std::abs(off) > 1e-6) {
    if (y_warnings_++ == 0)
      warning(st, st.loc,
              fmt::format("{} = {} but a lathe has no such axis: ignored (the first of "
                          "such points; is this a milling program?)",
                          "XYZ"[static_cast<int>(third)], off));
  }
  ensure_started();
  ++stats_.motions;
  LathePoint target = lathe(p);
  if (circle_) {
    Circle c = *circle_;
    circle_.reset();
    double ax[3] = {c.ax, c.ay, c.az};
    double normal =
        ax[static_cast<int>(third)] / std::sqrt(c.ax * c.ax + c.ay * c.ay + c.az * c.az);
    if (!pos_) {
      error(st, st.loc, "an arc needs a start point: no GOTO or FROM before CIRCLE/");
    } else {
      LathePoint from = lathe(*pos_);
      LathePoint center = lathe(Point3{c.cx, c.cy, c.cz});
      double r0 = std::hypot(from.r - center.r, from.z - center.z);
      double r1 = std::hypot(target.r - center.r, target.z - center.z);
      double tol = std::max(1e-3, 1e-4 * std::max(r0, r1));
      if (std::abs(r0 - r1) > tol) {
        error(st, st.loc,
              fmt::format("arc end point is not on the circle of line {}: distance from the centre "
                          "{:.6g} at the start, {:.6g} at the end",
                          c.loc.line, r0, r1));
      } else {
        // Positive rotation about the axis: G3 when it turns axial toward radial (axis along
        // axial x radial), as ISO G18 defines it.
        int e_r = static_cast<int>(m_.cl_radial), e_z = static_cast<int>(m_.cl_axial);
        // Sign of the permutation (e_z, e_r, third): cross(e_z, e_r) = +third when even.
        bool even = (e_z + 1) % 3 == e_r;
        bool ccw = (normal > 0) == even;
        prog_.arc(target, center, ccw);
        pos_ = p;
        rapid_next_ = false;
        return;
      }
    }
  }
  if (rapid_next_) {
    prog_.rapid(target);
  } else {
    if (!feed_given_) {
      error(st, st.loc, "feed move before any FEDRAT/: the feed is unknown");
    }
    prog_.linear(target);
  }
  rapid_next_ = false;
  pos_ = p;
}

// ---------------------------------------------------------------------------------------------
// End of input

void Interpreter::end_of_input(uint32_t last_line) {
  if (ended_) return;
  end_sequence_errors(last_line);  // an unterminated thread is the first thing to say
  diags_.warning(SourceLoc{last_line, 0}, {},
                 "the file ends without FINI: the program end was added");
  finish(last_line);
}

void Interpreter::finish(uint32_t last_line) {
  if (ended_) return;
  end_sequence_errors(last_line);
  ensure_started();
  prog_.end(partno_);
  ended_ = true;
}

}  // namespace clpost

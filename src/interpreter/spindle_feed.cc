// Feed, spindle and dwell: FEDRAT/, SPINDL/, DELAY/.
#include <fmt/format.h>

#include <cmath>
#include <optional>

#include "interpreter/millturn.h"
#include "interpreter/spindle_words.h"
#include "interpreter/statement_table.h"
#include "interpreter/tool_path.h"
#include "machine/template_values.h"

namespace clpost {

namespace {

constexpr double kMmPerInch = 25.4;

// Reads SPINDL/'s words into `w`; false (reported) on a bad one.
bool read_spindle_words(PostState& s, const Statement& st, SpindleWords& w) {
  w.value_loc = st.loc;
  for (size_t i = 0; i < st.args.size(); ++i) {
    const Arg& a = st.args[i];
    if (a.is_number()) {
      if (w.value) {
        error(s, st, a.loc,
              fmt::format("SPINDL/ takes one speed; found a second number '{}'", a.text));
        return false;
      }
      if (!in_range(s, st, a, "spindle speed")) return false;
      w.value = a.number, w.value_loc = a.loc;
    } else if (a.is("RPM")) {
      w.css = false;
    } else if (a.is("SMM") || a.is("SFM")) {
      w.css = true;
      w.surface_word = &a;
    } else if (a.is("CLW") || a.is("CCLW")) {
      w.dir = a.is("CLW") ? SpindleDir::kCw : SpindleDir::kCcw;
    } else if (a.is("OFF") || a.is("ON")) {
      (a.is("OFF") ? w.off : w.on) = true;
    } else if (a.is("MAXRPM")) {
      if (i + 1 >= st.args.size() || !st.args[i + 1].is_number()) {
        error(s, st, a.loc, "MAXRPM needs a speed limit");
        return false;
      }
      if (!in_range(s, st, st.args[i + 1], "MAXRPM")) return false;
      w.max_rpm = st.args[++i].number;
    } else if (a.is("RANGE")) {
      if (i + 1 < st.args.size() && st.args[i + 1].is_number()) ++i;
    } else {
      error(s, st, a.loc,
            unknown_word(st, a, "SPINDL", "a speed and RPM, SMM, SFM, CLW, CCLW, MAXRPM, OFF, ON"));
      return false;
    }
  }
  return true;
}

// SFM or SMM whose unit is not the file's (SFM in a metric file): CATIA V5 writes SFM for any
// surface speed in the file's unit (cl.surface_speed: file); NX and ICAM mean feet or metres
// (`word`: converted). docs/reading-cam-output.md gives the sources.
void surface_speed_unit(PostState& s, const Statement& st, SpindleWords& w) {
  if (!w.css || !w.surface_word || !w.value) return;
  const bool feet = w.surface_word->is("SFM"), inch_file = s.units == LengthUnit::kInch;
  if (feet == inch_file) return;
  const std::string_view file_unit = inch_file ? "ft/min" : "m/min";
  if (!s.m.surface_speed_by_word) {
    note_once(s, st, "surface-speed-unit",
              fmt::format("{} in {} file: read as {}, the file's unit (cl.surface_speed: file, as "
                          "CATIA V5 writes it; `word` converts)",
                          w.surface_word->text, inch_file ? "an inch" : "a metric", file_unit));
    return;
  }
  const double from = *w.value;
  w.value = feet ? from * 0.3048 : from / 0.3048;
  note_once(s, st, "surface-speed-unit",
            fmt::format("{} {} written as {:.6g} {} (cl.surface_speed: word)", from,
                        w.surface_word->text, *w.value, file_unit));
}

// Turns the spindle on at the speed of `w` (the earlier speed for SPINDL/ON).
void spindle_on(PostState& s, const Statement& st, SpindleWords w) {
  SpindleState& sp = s.spindle;
  if (!w.value) {
    if (!w.on || !(sp.value > 0)) {
      error(s, st, st.loc, "SPINDL/ needs a speed (or SPINDL/ON after an earlier speed)");
      return;
    }
    w.value = sp.value, w.css = sp.css;
  }
  if (!(*w.value > 0)) {
    error(s, st, w.value_loc, fmt::format("spindle speed must be positive, got {}", *w.value));
    return;
  }
  if (w.dir) sp.dir = *w.dir;
  if (!speed_written(s, st, w)) return;
  if (!w.css && s.m.max_rpm > 0 && *w.value > s.m.max_rpm) {
    error(s, st, w.value_loc,
          fmt::format("spindle speed {} rpm exceeds the machine's maximum {} rpm", *w.value,
                      s.m.max_rpm));
    return;
  }
  sp.css = w.css;
  sp.value = *w.value;
  sp.on = true;
  s.spindle_line = st.loc.line;
  release_c(s);  // the C axis is the main spindle again before it turns
  if (!w.css) {
    if (TemplateWrite r = s.prog.spindle_rpm(*w.value, sp.dir); !r)
      error(s, st, st.loc, template_error(s.m, r));
    return;
  }
  // MAXRPM stays in force until changed (SPINDL/ON and a later SPINDL/…,SMM keep it).
  if (w.max_rpm) sp.cl_max_rpm = *w.max_rpm;
  double limit = sp.cl_max_rpm.value_or(s.m.max_rpm);
  if (!(limit > 0)) {
    error(s, st, st.loc,
          "constant surface speed needs a speed limit: add MAXRPM,n or set limits.max_rpm in the "
          "machine file");
    return;
  }
  if (s.m.max_rpm > 0 && limit > s.m.max_rpm) limit = s.m.max_rpm;
  sp.css_max_rpm = limit;
  if (TemplateWrite r = s.prog.spindle_css(*w.value, limit, sp.dir); !r)
    error(s, st, st.loc, template_error(s.m, r));
}

}  // namespace

bool speed_written(PostState& s, const Statement& st, const SpindleWords& w) {
  const NumberFormat& f = s.m.format_for("S");
  if (std::llround(*w.value * f.scale * std::pow(10.0, f.decimals)) != 0) return true;
  error(s, st, w.value_loc,
        fmt::format("spindle speed {} would be written as S{} (formats.S: {} decimals): the "
                    "spindle would not turn",
                    *w.value, s.prog.num("S", *w.value), f.decimals));
  return false;
}

void fedrat_stmt(PostState& s, const Statement& st) {
  double value = 0;
  bool have_value = false;
  // Without a mode word the feed keeps the mode in force (docs/cl-meaning.md); per minute before
  // any.
  FeedMode mode = s.feed_given ? s.feed_mode : FeedMode::kPerMinute;
  double factor = 1;  // to CL units
  const double to_cl_from_mm = s.units == LengthUnit::kInch ? 1 / kMmPerInch : 1;
  const double to_cl_from_in = s.units == LengthUnit::kInch ? 1 : kMmPerInch;
  SourceLoc value_loc = st.loc;
  for (const Arg& a : st.args) {
    if (a.is_number()) {
      if (have_value) {
        error(s, st, a.loc,
              fmt::format("FEDRAT/ takes one feed value; found a second number '{}'", a.text));
        return;
      }
      if (!in_range(s, st, a, "feed")) return;
      value = a.number, have_value = true, value_loc = a.loc;
    } else if (a.is("MMPM") || a.is("MMPR")) {
      mode = a.is("MMPM") ? FeedMode::kPerMinute : FeedMode::kPerRev, factor = to_cl_from_mm;
    } else if (a.is("IPM") || a.is("IPR")) {
      mode = a.is("IPM") ? FeedMode::kPerMinute : FeedMode::kPerRev, factor = to_cl_from_in;
    } else if (a.is("PERMIN") || a.is("FPM")) {
      mode = FeedMode::kPerMinute;
    } else if (a.is("PERREV") || a.is("FPR")) {
      mode = FeedMode::kPerRev;
    } else {
      error(
          s, st, a.loc,
          unknown_word(st, a, "FEDRAT", "a feed and one of MMPM, MMPR, IPM, IPR, PERMIN, PERREV"));
      return;
    }
  }
  if (!have_value) return error(s, st, st.loc, "FEDRAT/ needs a feed value");
  if (!(value > 0))
    return error(s, st, value_loc, fmt::format("feed must be positive, got {}", value));
  s.feed = value * factor;
  s.feed_mode = mode;
  s.feed_line = st.loc.line;
  s.feed_given = true;
  time_feed_rate(s);
  if (s.m.max_feed > 0 && mode == FeedMode::kPerMinute && s.feed > s.m.max_feed) {
    warning(s, st, st.loc,
            fmt::format("feed {} exceeds the machine's maximum feed {}", s.feed, s.m.max_feed));
  }
  s.prog.set_feed(s.feed, s.feed_mode);
}

namespace {

void restate_spindle(PostState& s, SourceLoc loc, std::string_view line_text) {
  const SpindleState& sp = s.spindle;
  const TemplateWrite r = sp.css ? s.prog.spindle_css(sp.value, sp.css_max_rpm, sp.dir)
                                 : s.prog.spindle_rpm(sp.value, sp.dir);
  if (!r) s.diags.error(loc, line_text, template_error(s.m, r));
}

}  // namespace

void restate_spindle(PostState& s, const Statement& st) {
  restate_spindle(s, st.loc, st.line_text(st.loc.line));
}

void restart_stopped_spindle(PostState& s, SourceLoc loc, std::string_view line_text) {
  if (!s.spindle_stopped || !s.path->turns_main_spindle()) return;  // a live tool keeps it
  release_c(s);
  s.spindle_stopped = false;
  if (s.before_skip) s.spindle_in_skip = true;  // a skipped block: stated again after the range
  restate_spindle(s, loc, line_text);
}

void spindl_stmt(PostState& s, const Statement& st) {
  SpindleWords w;
  if (read_spindle_words(s, st, w)) s.path->spindle(s, st, w);
}

void main_spindl(PostState& s, const Statement& st, SpindleWords w) {
  s.spindle_stopped = false;  // this statement says what the spindle does
  if (s.before_skip) s.spindle_in_skip = true;
  surface_speed_unit(s, st, w);
  ensure_started(s);
  if (w.off) {
    s.spindle.on = false;
    s.spindle_line = st.loc.line;
    if (TemplateWrite r = s.prog.spindle_stop(); !r) error(s, st, st.loc, template_error(s.m, r));
    return;
  }
  spindle_on(s, st, w);
  time_feed_rate(s);
}

// DELAY/t dwells t seconds, DELAY/REV,n n spindle revolutions. The machine's dwell template
// asks for {seconds} or {revolutions}; one becomes the other through the spindle speed in RPM.
void delay_stmt(PostState& s, const Statement& st) {
  // DELAY/REV,n and DELAY/n,REV (the order CATIA's tables write) are revolutions.
  const bool rev_first = !st.args.empty() && st.args[0].is("REV");
  const bool in_revs = rev_first || (st.args.size() == 2 && st.args[1].is("REV"));
  const size_t i = rev_first ? 1 : 0;
  double v = 0;
  if (!number_arg(s, st, i, in_revs ? "a dwell in revolutions" : "a dwell time in seconds", v))
    return;
  if (!(v >= 0)) {
    error(s, st, st.args[i].loc,
          fmt::format("{} must not be negative, got {}",
                      in_revs ? "a dwell in revolutions" : "dwell time", v));
    return;
  }
  const SpindleState& sp = s.spindle;
  const bool rpm_known = sp.on && !sp.css && sp.value > 0;
  std::optional<double> seconds, revolutions;
  if (in_revs) {
    revolutions = v;
    if (rpm_known) seconds = v * 60 / sp.value;
  } else {
    seconds = v;
    if (rpm_known) revolutions = v * sp.value / 60;
  }
  ensure_started(s);
  const TemplateWrite r = s.prog.dwell(seconds, revolutions);
  if (r && seconds) time_dwell(s, *seconds);
  if (r) return;
  if (r.status != TemplateWrite::Status::kNoValue)
    return error(s, st, st.loc, template_error(s.m, r));
  error(s, st, st.loc,
        fmt::format("machine '{}' dwells in {}: a dwell of {} {} needs the spindle turning at a "
                    "set RPM to convert, and the spindle {}",
                    s.m.name, in_revs ? "seconds" : "revolutions", v,
                    in_revs ? "revolutions" : "seconds",
                    !sp.on   ? "is stopped"
                    : sp.css ? "runs at constant surface speed"
                             : "has no speed"));
}

}  // namespace clpost

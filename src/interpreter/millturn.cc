// Mill-turn (docs/millturn.md): the main spindle as the C axis (held, engaged, released), C
// positioning (ROTABL/…,CAXIS, ROTATE/CAXIS,…) and clamping (CLAMP/…,CAXIS), and the words of a
// multi-channel machine (SYNC/, CHANNEL). Every code comes from the machine file (millturn.*,
// codes.c_engage …, templates.c_index …).
#include "interpreter/millturn.h"

#include <fmt/format.h>

#include <algorithm>
#include <cmath>

#include "interpreter/statement_table.h"
#include "interpreter/tool_path.h"
#include "machine/template_values.h"

namespace clpost {

namespace {

// A bare code block (codes.c_engage …); nothing when the machine has no such code.
void code_block(PostState& s, const std::string& key) {
  const std::string& code = s.m.code(key);
  if (!code.empty()) s.prog.writer().code(code).end_block();
}

}  // namespace

void hold_main_spindle(PostState& s, const Statement& st) {
  if (!s.spindle.on || s.spindle_stopped) return;
  s.spindle_stopped = true;  // turns again, as the CL left it, before the next turning motion
  if (TemplateWrite r = s.prog.spindle_stop(); !r) error(s, st, st.loc, template_error(s.m, r));
}

void engage_c(PostState& s, const Statement& st) {
  if (!s.m.c_axis || s.c.engaged) return;
  hold_main_spindle(s, st);
  code_block(s, "c_engage");
  s.c.engaged = true;
  s.c.clamped = false;
  s.c.angle.reset();
}

void release_c(PostState& s) {
  if (!s.c.engaged) return;
  if (s.c.clamped) code_block(s, "c_unclamp");
  time_c(s, 0, s.c.clamped ? 1 : 0);
  code_block(s, "c_disengage");
  s.c = CAxisState{};
}

bool c_at_index(const PostState& s) {
  return !s.c.index || !s.c.angle || std::fabs(std::remainder(*s.c.angle - *s.c.index, 360)) < 1e-9;
}

}  // namespace clpost

namespace clpost {

namespace {

// ROTABL/ or ROTATE/ as read: the words in any order.
struct RotaryWords {
  std::optional<double> angle;
  SourceLoc angle_loc;
  bool incremental = false;
  std::optional<int> sign;    // +1 increasing C, -1 decreasing (CLW, CCLW), none: shortest
  const Arg* axis = nullptr;  // CAXIS, AAXIS, BAXIS
};

bool read_rotary_words(PostState& s, const Statement& st, RotaryWords& w) {
  const int clw = s.m.c_clw_increasing ? 1 : -1;
  for (const Arg& a : st.args) {
    if (a.is_number()) {
      if (w.angle) {
        error(s, st, a.loc,
              fmt::format("{}/ takes one angle; found a second number '{}'", st.major, a.text));
        return false;
      }
      if (!in_range(s, st, a, "a rotary angle")) return false;
      w.angle = a.number, w.angle_loc = a.loc;
    } else if (a.is("CAXIS") || a.is("AAXIS") || a.is("BAXIS")) {
      w.axis = &a;
    } else if (a.is("CLW") || a.is("CCLW")) {
      w.sign = a.is("CLW") ? clw : -clw;
    } else if (a.is("INCR")) {
      w.incremental = true;
    } else if (!(a.is("TABLE") || a.is("ATANGL") || a.is("ABSOL") || a.text.empty())) {
      error(s, st, a.loc,
            unknown_word(st, a, st.major, "an angle and CAXIS, TABLE, ATANGL, INCR, CLW, CCLW"));
      return false;
    }
  }
  if (w.angle) return true;
  error(s, st, st.loc, fmt::format("{}/ needs an angle", st.major));
  return false;
}

// `a` in 0 <= a < 360, to a millionth of a degree (so that 359.9999999 is written as 0).
double in_one_turn(double a) {
  double r = std::fmod(a, 360.0);
  if (r < 0) r += 360;
  r = std::round(r * 1e6) / 1e6;
  return r >= 360 ? 0 : r;
}

}  // namespace

std::vector<double> c_steps(const Machine& m, std::optional<double> from, double angle,
                            bool incremental, std::optional<int> sign) {
  const bool rollover = m.c_rotation == CRotation::kRollover;
  if (!from) return {rollover ? in_one_turn(angle) : angle};
  double d = 0;
  if (incremental) {
    d = sign ? *sign * std::abs(angle) : angle;
  } else {
    const double r = in_one_turn(angle - *from);
    if (r != 0) d = sign ? (*sign > 0 ? r : r - 360) : (r <= 180 ? r : r - 360);
  }
  if (!(std::abs(d) > 1e-9)) return {};
  if (!rollover) return {*from + d};
  // A rollover control goes the shortest way: a turn of 180 degrees or more, or one the CL
  // gives the other way, is written as equal steps under 180 degrees.
  const int n = std::abs(d) < 180 ? 1 : static_cast<int>(std::floor(std::abs(d) / 180)) + 1;
  std::vector<double> steps;
  for (int k = 1; k <= n; ++k) steps.push_back(in_one_turn(*from + d * k / n));
  return steps;
}

// ROTABL/a[,CAXIS][,TABLE][,CLW|CCLW][,INCR] (CATIA, ICAM) and ROTATE/CAXIS,ATANGL|INCR,a,CLW
// (NX-to-APT): positions the C axis. Without an axis word on a machine without C it is the
// comment it always was.
void rotabl_stmt(PostState& s, const Statement& st) {
  RotaryWords w;
  const bool names_axis = std::any_of(st.args.begin(), st.args.end(), [](const Arg& a) {
    return a.is("CAXIS") || a.is("AAXIS") || a.is("BAXIS");
  });
  if (!names_axis && !s.m.c_axis) return unknown_stmt(s, st);
  if (!read_rotary_words(s, st, w)) return;
  if (w.axis && !w.axis->is("CAXIS"))
    return error(s, st, w.axis->loc,
                 fmt::format("{}/…,{}: a lathe's rotary axis is C; machine '{}' has no {} axis",
                             st.major, w.axis->text, s.m.name, w.axis->text.substr(0, 1)));
  if (!s.m.c_axis)
    return error(s, st, w.axis ? w.axis->loc : st.loc,
                 fmt::format("{}/ positions a C axis, and machine '{}' has none "
                             "(millturn.c_axis: false)",
                             st.major, s.m.name));
  ensure_started(s);
  engage_c(s, st);
  s.path->before_c_index(s, st);  // a live tool leaves polar interpolation: C is an axis again
  if (w.incremental && !s.c.angle)
    return error(s, st, st.loc,
                 fmt::format("{}/…,INCR: C's position is not known yet (no ROTABL since the C "
                             "axis was engaged)",
                             st.major));
  // INCR turns the part frame from its index: a hole off the X axis may have moved C on.
  std::optional<double> from = s.c.angle;
  if (w.incremental && s.c.index) from = s.c.index;
  std::vector<double> steps = c_steps(s.m, from, *w.angle, w.incremental, w.sign);
  if (from != s.c.angle) {
    const double to = steps.empty() ? *from : steps.back();
    steps = c_steps(s.m, s.c.angle, to, false, w.sign);
  }
  if (write_c_steps(s, st, steps)) s.c.index = s.c.angle;
}

bool write_c_steps(PostState& s, const Statement& st, const std::vector<double>& steps) {
  if (steps.empty()) return true;  // C is there: nothing moves, nothing unclamps
  int clamps = s.c.clamped ? 1 : 0;
  if (s.c.clamped) code_block(s, "c_unclamp");
  double turned = 0;  // degrees, the way the control turns (rollover: each step the short way)
  std::optional<double> from = s.c.angle;
  for (double c : steps) {
    if (from)
      turned += std::fabs(s.m.c_rotation == CRotation::kRollover ? std::remainder(c - *from, 360.0)
                                                                 : c - *from);
    from = c;
    TemplateFill<tmpl::kCIndex> v;
    v.text<"c">(s.prog.num("C", c)).text<"address">(s.m.c_address);
    if (TemplateWrite r = s.prog.write_template(v); !r) {
      error(s, st, st.loc, template_error(s.m, r));
      return false;
    }
  }
  s.c.angle = steps.back();
  if (!s.c.cl_unclamped) code_block(s, "c_clamp");
  s.c.clamped = !s.c.cl_unclamped && !s.m.code("c_clamp").empty();
  time_c(s, turned, clamps + (s.c.clamped ? 1 : 0));
  s.prog.forget_modal();  // the motion code of c_index may not be the one in force
  return true;
}

namespace {

// The ON, OFF or AUTO of CLAMP/…,CAXIS (first or second word); null (reported) otherwise.
const Arg* clamp_mode(PostState& s, const Statement& st) {
  for (size_t i = 0; i < std::min<size_t>(2, st.args.size()); ++i)
    if (st.args[i].is("ON") || st.args[i].is("OFF") || st.args[i].is("AUTO")) {
      for (size_t k = 0; k < st.args.size(); ++k)
        if (k != i && !st.args[k].is("CAXIS")) {
          error(s, st, st.args[k].loc,
                fmt::format("CLAMP/…,CAXIS: '{}' is not read (ICAM's CLAMP/OFF,axis,position "
                            "moves the axis in a way no source states): position C with "
                            "ROTABL/a,CAXIS",
                            st.args[k].text));
          return nullptr;
        }
      return &st.args[i];
    }
  error(s, st, st.loc, "expected CLAMP/ON|OFF|AUTO,CAXIS or CLAMP/CAXIS,ON|OFF");
  return nullptr;
}

}  // namespace

// CLAMP/ON,CAXIS clamps C now (when engaged and not clamped) and after each index as before;
// CLAMP/OFF,CAXIS unclamps it and leaves it unclamped after the indexes until CLAMP/ON or AUTO
// (or until C is released); CLAMP/AUTO,CAXIS gives the clamping back to the post.
namespace {

// CLAMP/ON|OFF|AUTO for the C axis, `mode` the statement's word saying which.
void clamp_c(PostState& s, const Statement& st, const Arg* mode) {
  if (!s.m.c_axis)
    return error(s, st, st.loc,
                 fmt::format("CLAMP/…,CAXIS clamps a C axis, and machine '{}' has none "
                             "(millturn.c_axis: false)",
                             s.m.name));
  const bool on = !mode->is("OFF");
  const std::string key = on ? "c_clamp" : "c_unclamp";
  if (s.m.code(key).empty()) {
    warning(s, st, st.loc,
            fmt::format("CLAMP/: machine '{}' has no code '{}' (its C axis is not clamped): "
                        "written as a comment",
                        s.m.name, key));
    ensure_started(s);
    return s.prog.comment(st.source);
  }
  if (mode->is("ON") && !s.c.engaged)
    return error(s, st, st.loc,
                 "CLAMP/ON,CAXIS: C is not engaged (no milling tool since the main spindle "
                 "last turned): nothing to clamp");
  s.c.cl_unclamped = !on;
  if (!s.c.engaged || s.c.clamped == on) return;
  ensure_started(s);
  code_block(s, key);
  s.c.clamped = on;
  time_c(s, 0, 1);
}

}  // namespace

void clamp_c_stmt(PostState& s, const Statement& st) {
  if (const Arg* mode = clamp_mode(s, st)) clamp_c(s, st, mode);
}

// CLAMP/TABLE,ALL,ON|OFF|AUTO (Fusion's APT post, ../shared/reference/millturn.md §1): every
// rotary axis, which on a lathe is C. A machine without C has nothing to clamp: a note.
void clamp_table_stmt(PostState& s, const Statement& st) {
  const Arg* mode = nullptr;
  for (const Arg& a : st.args) {
    if (a.is("ON") || a.is("OFF") || a.is("AUTO")) {
      mode = &a;
    } else if (!a.is("TABLE") && !a.is("ALL")) {
      return error(s, st, a.loc, unknown_word(st, a, st.major, "TABLE, ALL, ON, OFF, AUTO"));
    }
  }
  if (mode == nullptr) return error(s, st, st.loc, "expected CLAMP/TABLE,ALL,ON|OFF|AUTO");
  if (!s.m.c_axis)
    return note_once(s, st, "CLAMP/TABLE",
                     fmt::format("CLAMP/TABLE clamps rotary axes, and machine '{}' has none "
                                 "(millturn.c_axis: false): nothing to clamp",
                                 s.m.name));
  clamp_c(s, st, mode);
}

// SYNC/…: waits between channels of a multi-channel machine (CATIA's Swiss-type programs).
void sync_stmt(PostState& s, const Statement& st) {
  warning(s, st, st.loc,
          fmt::format("{}/ synchronises this program with another channel, and machine '{}' has "
                      "one channel (no second channel to wait for): written as a comment",
                      st.major, s.m.name));
  ensure_started(s);
  s.prog.comment(st.source);
}

}  // namespace clpost

namespace clpost {

// CHANNEL,n (CATIA's multi-channel programs, read as CHANNEL/n): which channel this program is
// for. A comment; channel 2 or more is a warning that names the missing channel.
void channel_stmt(PostState& s, const Statement& st) {
  const Arg* n = st.args.empty() || !st.args[0].is_number() ? nullptr : &st.args[0];
  if (n != nullptr && n->number >= 2)
    warning(s, st, n->loc,
            fmt::format("the CL is the program of channel {} of a multi-channel machine, and "
                        "machine '{}' has one channel (no channel {}): posted as a one-channel "
                        "program",
                        n->text, s.m.name, n->text));
  ensure_started(s);
  s.prog.comment(st.source);
}

}  // namespace clpost

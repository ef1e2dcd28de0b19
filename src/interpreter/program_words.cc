// Program words: UNITS, COOLNT, CUTCOM, STOP/OPSTOP, END, FINI, MULTAX, spline motion
// (refused) and the records a lathe program skips.
#include <fmt/format.h>

#include "interpreter/clock.h"
#include "interpreter/statement_table.h"
#include "interpreter/tool_path.h"

namespace clpost {

namespace {

// What the CL has already given keeps its physical value when UNITS changes how later numbers
// are read (docs/cl-meaning.md): every length the state holds, converted by `f` (new units per
// old), and a surface speed from m/min to ft/min or back.
void convert_units(PostState& s, LengthUnit to) {
  const double f = to == LengthUnit::kInch ? 1 / 25.4 : 25.4;
  auto scale = [f](double& v) { v *= f; };
  if (s.pos) s.pos = Point3{s.pos->x * f, s.pos->y * f, s.pos->z * f};
  if (s.circle) {
    Circle& c = *s.circle;
    for (double* v : {&c.cx, &c.cy, &c.cz, &c.radius}) scale(*v);
  }
  scale(s.feed);
  scale(s.thread.pitch.pitch);
  scale(s.thread.pitch.lead_change);
  if (s.tool.nose_radius) scale(*s.tool.nose_radius);
  for (ToolInfo* t : {&s.tool, &s.next_tool})
    if (t->diameter) scale(*t->diameter);
  scale(s.cutter_diameter);
  if (HoleCycle* h = s.hole_cycle ? &*s.hole_cycle : nullptr) {
    for (double* v : {&h->depth, &h->first_peck, &h->peck}) scale(*v);
    for (std::optional<double>* v : {&h->clearance, &h->retract, &h->feed, &h->lead})
      if (*v) scale(**v);
  }
  if (s.clock_at) s.clock_at = Vec2{s.clock_at->x * f, s.clock_at->z * f};
  if (s.clock_feed > 0) scale(s.clock_feed);
  if (s.spindle.css) s.spindle.value *= to == LengthUnit::kInch ? 1 / 0.3048 : 0.3048;
  s.prog.units_changed(f, to == LengthUnit::kInch);
}

}  // namespace

void units_stmt(PostState& s, const Statement& st) {
  if (st.args.empty() || !st.args[0].is_word()) {
    error(s, st, st.args.empty() ? st.loc : st.args[0].loc, "expected UNITS/MM or UNITS/INCHES");
    return;
  }
  const Arg& a = st.args[0];
  LengthUnit u;
  if (a.is("MM") || a.is("MILLIMETERS") || a.is("METRIC")) {
    u = LengthUnit::kMm;
  } else if (a.is("INCHES") || a.is("INCH") || a.is("IN")) {
    u = LengthUnit::kInch;
  } else {
    error(s, st, a.loc, fmt::format("unknown unit '{}': expected MM or INCHES", a.text));
    return;
  }
  const LengthUnit machine_unit = s.m.default_units == "in" ? LengthUnit::kInch : LengthUnit::kMm;
  if (s.m.control && s.m.control->one_unit_per_program && u != machine_unit) {
    // A control whose unit parameter is the CL's takes the whole file: the machine's units key.
    const bool inch = u == LengthUnit::kInch;
    error(s, st, a.loc,
          fmt::format("machine '{}' ({}) reads the whole program in {}: the unit is set once, "
                      "outside the program's blocks, and UNITS/{} cannot change it (a control "
                      "set to {} takes the whole CL with the machine key units: {}, e.g. "
                      "--set units={})",
                      s.m.name, s.m.control->name, s.m.default_units, a.text,
                      inch ? "inches" : "mm", inch ? "in" : "mm", inch ? "in" : "mm"));
    return;
  }
  if (s.started && u != s.units) {
    if (s.pos)
      warning(s, st, st.loc,
              "units change after motion: later coordinates are read in the new units");
    s.prog.writer().code(s.m.code(u == LengthUnit::kInch ? "inch" : "metric")).end_block();
  }
  if (u != s.units) convert_units(s, u);
  s.units = u;
  // The control reads the surface speed in force in the new units (G96 S200 after G20 is 200
  // ft/min): it is written again, converted.
  if (s.started && s.spindle.on && s.spindle.css) restate_spindle(s, st);
}

// COOLNT/ with nothing after it: CATIA's tool change writes COOLNT/%MFG_COOLNT_SNTX, empty for a
// tool with no coolant set, and ICAM's interface kit catches it with a dummy macro (the table's
// history, 07-10-2005: reference/cam/ICAM_MM_pptable_cycles_and_millturn_excerpt.txt). It
// changes nothing.
void coolnt_stmt(PostState& s, const Statement& st) {
  constexpr const char* kExpected = "expected COOLNT/ON, FLOOD, MIST, THRU, AIR or OFF";
  if (st.args.empty() && st.form == Statement::Form::kRecord) {
    note_once(s, st, "empty-coolant",
              "COOLNT/ without a coolant (CATIA's tool change for a tool with none set): "
              "the coolant does not change");
    return;
  }
  if (st.args.empty() || !st.args[0].is_word()) {
    error(s, st, st.args.empty() ? st.loc : st.args[0].loc, kExpected);
    return;
  }
  const Arg& a = st.args[0];
  Coolant c;
  if (a.is("ON") || a.is("FLOOD")) {
    c = Coolant::kFlood;
  } else if (a.is("MIST")) {
    c = Coolant::kMist;
  } else if (a.is("THRU") || a.is("TOOL")) {
    c = Coolant::kThrough;
  } else if (a.is("AIR")) {
    c = Coolant::kAir;
  } else if (a.is("OFF")) {
    c = Coolant::kOff;
  } else {
    error(s, st, a.loc,
          fmt::format("unknown COOLNT word '{}': expected ON, FLOOD, MIST, THRU, AIR or OFF",
                      a.text));
    return;
  }
  // COOLNT/FLOOD,HIGH, COOLNT/ON,2 …: what follows the coolant is said, not dropped silently.
  if (const std::string rest = rest_of_args(st, 1); !rest.empty())
    warning(s, st, st.args[1].loc,
            fmt::format("COOLNT/{}: the words after it are not written ('{}')", a.text, rest));
  ensure_started(s);
  // One coolant at a time (docs/cl-meaning.md): M7 after M8 would add mist to the flood on the
  // control, so the one in force is turned off first.
  if (c != s.coolant && c != Coolant::kOff && s.coolant != Coolant::kOff)
    s.prog.coolant(Coolant::kOff);
  s.coolant = c;
  s.prog.coolant(c);
}

void cutcom_stmt(PostState& s, const Statement& st) {
  if (st.args.empty() || !st.args[0].is_word()) {
    error(s, st, st.args.empty() ? st.loc : st.args[0].loc, "expected CUTCOM/LEFT, RIGHT or OFF");
    return;
  }
  const Arg& a = st.args[0];
  CutterComp c;
  if (a.is("LEFT")) {
    c = CutterComp::kLeft;
  } else if (a.is("RIGHT")) {
    c = CutterComp::kRight;
  } else if (a.is("OFF")) {
    c = CutterComp::kOff;
  } else {
    error(s, st, a.loc,
          fmt::format("unknown CUTCOM word '{}': expected LEFT, RIGHT or OFF", a.text));
    return;
  }
  s.path->cutter_comp(s, st, a, c);
}

void stop_stmt(PostState& s, const Statement& st) {
  ensure_started(s);
  s.prog.program_stop(st.major == "OPSTOP");
}

void end_stmt(PostState&, const Statement&) {
  // APT's END (end of a tape section) asks nothing of a lathe program.
}

void finish_program(PostState& s, const Statement& at) {
  if (s.ended) return;
  end_sequences(s);
  ensure_started(s);
  s.path->leave(s, at, true);  // as before a tool change (polar interpolation off), C released
  end_nc_lines(s);             // the program end is no tool's
  if (TemplateWrite r = s.prog.end(s.partno); !r)
    s.diags.error(SourceLoc{}, {}, template_error(s.m, r));
  const NcWriter& w = s.prog.writer();
  if (w.wrapped_comments() > 0)
    s.diags.warning(SourceLoc{}, {},
                    fmt::format("{} comments longer than comments.max_length {} of machine '{}' "
                                "were wrapped onto more comment blocks",
                                w.wrapped_comments(), s.m.comment_max_length, s.m.name));
  if (w.long_lines() > 0)
    s.diags.error(SourceLoc{}, {},
                  fmt::format("{} blocks are longer than output.max_line_length {} of machine "
                              "'{}', the first at NC line {}",
                              w.long_lines(), s.m.max_line_length, s.m.name, w.first_long_line()));
  s.ended = true;
}

void fini_stmt(PostState& s, const Statement& st) {
  finish_program(s, st);
}

void multax_stmt(PostState& s, const Statement& st) {
  if (st.args.empty() || !st.args[0].is("ON")) return;
  // A machine with live tools reads a milling tool's axis: face or radial work (docs/millturn.md).
  note_once(s, st, "MULTAX",
            s.m.live_tools ? "MULTAX/ON: tool axis vectors are read for milling tools (face or "
                             "radial work), ignored for turning tools"
                           : "MULTAX/ON: tool axis vectors are ignored on a lathe");
}

void spline_stmt(PostState& s, const Statement& st) {
  error(s, st, st.loc,
        fmt::format("{}/ spline motion cannot be cut on a lathe post; output it as GOTO points "
                    "from the CAM system",
                    st.major));
}

void skipped_stmt(PostState& s, const Statement& st) {
  note_once(s, st, st.major,
            fmt::format("{} records skipped (nothing a lathe program needs)", st.major));
}

}  // namespace clpost

// CYCLE/UNDCUT: thread undercuts as CYCLE96 or as a DIN 76-1 contour (undercut.h).
#include "interpreter/undercut.h"

#include <fmt/format.h>

#include <array>
#include <cmath>

#include "controls/sinumerik/sinumerik_templates.h"
#include "interpreter/statement_table.h"
#include "planner/number_text.h"

namespace clpost {

namespace {

// ISO metric coarse pitches (ISO 261) for CYCLE96's range M3 ... M68. Source for M3 ... M64:
// the coarse "M<d>-<P>" sizes of gumyr/bd_warehouse src/bd_warehouse/data/hex_head_parameters.csv;
// M68 x 6 is the ISO 261 coarse pitch of 68 (not in that file).
struct CoarsePitch {
  double d, pitch;
};
constexpr std::array<CoarsePitch, 26> kCoarse = {
    {{3, 0.5},  {4, 0.7},  {5, 0.8},  {6, 1},  {8, 1.25}, {10, 1.5}, {12, 1.75}, {14, 2}, {16, 2},
     {18, 2.5}, {20, 2.5}, {22, 2.5}, {24, 3}, {27, 3},   {30, 3.5}, {33, 3.5},  {36, 4}, {39, 4},
     {42, 4.5}, {45, 4.5}, {48, 5},   {52, 5}, {56, 5.5}, {60, 5.5}, {64, 6},    {68, 6}}};

// DIN 76-1 thread undercuts for the coarse pitches above, as tabulated ("Undercut DIN 76,
// Parameters") in the HEIDENHAIN CNC PILOT 4290 User's Manual, section 11.1.1, manual page 426
// (https://www.manualsdir.com/manuals/798327/heidenhain-cnc-pilot-4290.html?page=438), columns
// Thr.pitch, I, K, R, W = 30 degrees, "in accordance with DIN 13 for metric threads"; internal
// rows from 1 mm up from the HEIDENHAIN CNC PILOT 640 Operation Manual, section 9.2 "Undercut
// parameters", page 616, which repeats the rows up to 0.8. I is the diameter step (external: the
// undercut diameter is d - I; internal: d + I, its depth measured from the core diameter as
// (N + I - core)/2), K the width, R the radius. The table has one external and one internal
// width per pitch: the normal undercuts, forms A and C. Cross-check (controllers.md, seed 001):
// P = 1.5 form A is depth 1.15 (radius, = I/2), width 5.2, radius 0.8, 30 degrees. The short
// forms B and D are not in the cited table, so clpost does not carry them.
constexpr std::array<Din76Row, 16> kFormA = {{{0.5, 0.8, 1.75, 0.2},
                                              {0.7, 1.1, 2.45, 0.4},
                                              {0.8, 1.3, 2.8, 0.4},
                                              {1, 1.6, 3.5, 0.6},
                                              {1.25, 2, 4.4, 0.6},
                                              {1.5, 2.3, 5.2, 0.8},
                                              {1.75, 2.6, 6.1, 1},
                                              {2, 3, 7, 1},
                                              {2.5, 3.6, 8.7, 1.2},
                                              {3, 4.4, 10.5, 1.6},
                                              {3.5, 5, 12, 1.6},
                                              {4, 5.7, 14, 2},
                                              {4.5, 6.4, 16, 2},
                                              {5, 7, 17.5, 2.5},
                                              {5.5, 7.7, 19, 3.2},
                                              {6, 8.3, 21, 3.2}}};
constexpr std::array<Din76Row, 16> kFormC = {{{0.5, 0.3, 2.7, 0.2},
                                              {0.7, 0.3, 3.8, 0.4},
                                              {0.8, 0.3, 4.2, 0.4},
                                              {1, 0.5, 5.2, 0.6},
                                              {1.25, 0.5, 6.7, 0.6},
                                              {1.5, 0.5, 7.8, 0.8},
                                              {1.75, 0.5, 9.1, 1},
                                              {2, 0.5, 10.3, 1},
                                              {2.5, 0.5, 13, 1.2},
                                              {3, 0.5, 15.2, 1.6},
                                              {3.5, 0.5, 17.7, 1.6},
                                              {4, 0.5, 20, 2},
                                              {4.5, 0.5, 23, 2},
                                              {5, 0.5, 26, 2.5},
                                              {5.5, 0.5, 28, 3.2},
                                              {6, 0.5, 30, 3.2}}};

// The core (minor) diameter of an ISO internal thread: d - 2 x 0.54127 P (controllers.md).
double internal_core(double d, double pitch) {
  return d - 2 * 0.54127 * pitch;
}

bool internal_form(char form) {
  return form == 'C' || form == 'D';
}

const char* form_name(char form) {
  switch (form) {
    case 'A':
      return "A (external, normal)";
    case 'B':
      return "B (external, short)";
    case 'C':
      return "C (internal, normal)";
    default:
      return "D (internal, short)";
  }
}

}  // namespace

std::optional<double> iso_coarse_pitch(double d) {
  for (const CoarsePitch& c : kCoarse)
    if (std::fabs(c.d - d) < 1e-6) return c.pitch;
  return std::nullopt;
}

const Din76Row* din76_row(char form, double pitch) {
  const auto* table = form == 'A' ? &kFormA : form == 'C' ? &kFormC : nullptr;
  if (!table) return nullptr;
  for (const Din76Row& r : *table)
    if (std::fabs(r.pitch - pitch) < 1e-9) return &r;
  return nullptr;
}

UndercutContour din76_contour(double d, double at, char form, int side, const Din76Row& row) {
  const double tan30 = std::tan(30 * 3.14159265358979323846 / 180);
  const double s = side < 0 ? -1 : 1;
  UndercutContour c;
  if (!internal_form(form)) {
    const double rt = d / 2, rb = (d - row.diameter_step) / 2, h = rt - rb;
    c.start = {rt + kUndercutClearance, at + s * row.width};
    c.to_fillet = {{rt, at + s * row.width},
                   {rb, at + s * (row.width - h / tan30)},
                   {rb, at + s * row.radius}};
    c.fillet_end = {rb + row.radius, at};
    c.fillet_center = {rb + row.radius, at + s * row.radius};
    c.fillet_ccw = s < 0;
    c.end = {rt + kUndercutClearance, at};
  } else {
    const double rc = internal_core(d, row.pitch) / 2, rb = (d + row.diameter_step) / 2;
    const double h = rb - rc;
    c.start = {rc - kUndercutClearance, at + s * row.width};
    c.to_fillet = {{rc, at + s * row.width},
                   {rb, at + s * (row.width - h / tan30)},
                   {rb, at + s * row.radius}};
    c.fillet_end = {rb - row.radius, at};
    c.fillet_center = {rb - row.radius, at + s * row.radius};
    c.fillet_ccw = s > 0;
    c.end = {rc - kUndercutClearance, at};
  }
  return c;
}

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
    error(s, st, v.loc, fmt::format("CYCLE/UNDCUT: {} needs a number, found '{}'", a.text, v.text));
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
            fmt::format("CYCLE/UNDCUT: expected a word, found number {}; valid words: {}", a.text,
                        kValid));
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

// CYCLE96 on a machine with the template, with the checks the control makes (seed 001).
void undercut_cycle96(PostState& s, const Statement& st, const UndercutWords& u, double pitch) {
  const Din76Row* ext = din76_row('A', pitch);
  if (!internal_form(u.form) && ext && u.diam - ext->diameter_step < 3 - 1e-9) {
    error(s, st, u.diam_loc,
          fmt::format("CYCLE/UNDCUT: the undercut's final diameter {} (M{} pitch {}: DIN 76-1 "
                      "d - {}) is below 3 mm: CYCLE96 stops with an alarm",
                      num_text(u.diam - ext->diameter_step), num_text(u.diam), num_text(pitch),
                      num_text(ext->diameter_step)));
    return;
  }
  if (s.tool.offset <= 0) {
    error(s, st, st.loc,
          s.tool.offset < 0
              ? std::string("CYCLE96 needs an active tool offset: no LOADTL/ before CYCLE/UNDCUT")
              : std::string("CYCLE96 needs an active tool offset: the tool was loaded with "
                            "offset 0 (D0), which selects none"));
    return;
  }
  NcProgram& prog = s.prog;
  prog.comment(fmt::format("thread undercut M{} form {} at Z{}", num_text(u.diam),
                           form_name(u.form), num_text(u.at)));
  // CYCLE96 moves at the feed programmed before it: make sure it is written.
  prog.writer()
      .code(s.m.code(s.feed_mode == FeedMode::kPerRev ? "feed_per_rev" : "feed_per_min"))
      .word("F", s.feed)
      .end_block();
  TemplateFill<tmpl::kCycle96> args;
  args.text<"diath">(prog.num("X", u.diam))
      .text<"axsa">(prog.num("Z", u.at))
      .text<"form">(std::string(1, u.form));
  if (TemplateWrite r = prog.write_template(args); !r)
    return error(s, st, st.loc, template_error(s.m, r));
  // The cycle returns to its starting point with G0 (seed 001).
  prog.cycle_ended_at(prog.position().value_or(LathePoint{}));
}

// The DIN 76-1 undercut cut as a contour (no cycle on the machine).
void undercut_contour(PostState& s, const Statement& st, const UndercutWords& u, double pitch) {
  const Din76Row* row = din76_row(u.form, pitch);
  if (!row) {
    error(s, st, u.form_loc,
          fmt::format("CYCLE/UNDCUT: no DIN 76-1 row for form {}, pitch {} (M{}) in clpost's "
                      "table: only the normal forms A and C are carried (cited in "
                      "src/interpreter/undercut.cc); use FORM,{} or a machine with CYCLE96",
                      form_name(u.form), num_text(pitch), num_text(u.diam),
                      internal_form(u.form) ? 'C' : 'A'));
    return;
  }
  if (!s.pos) {
    error(s, st, st.loc,
          "CYCLE/UNDCUT needs the tool position to tell the undercut's side: no GOTO or FROM "
          "before it");
    return;
  }
  const Vec2 here = cl2(s, *s.pos);
  if (std::fabs(here.z - u.at) < 1e-9) {
    error(s, st, st.loc,
          fmt::format("CYCLE/UNDCUT: the tool is at the undercut's Z {}: it must be on the side "
                      "of AT where the undercut lies",
                      num_text(u.at)));
    return;
  }
  const UndercutContour c = din76_contour(u.diam, u.at, u.form, here.z > u.at ? 1 : -1, *row);
  const double step = internal_form(u.form) ? row->diameter_step : -row->diameter_step;
  s.prog.comment(fmt::format(
      "thread undercut DIN 76-1 form {} for M{} at Z{}: diameter {}, width {}, radius {}",
      form_name(u.form), num_text(u.diam), num_text(u.at), num_text(u.diam + step),
      num_text(row->width), num_text(row->radius)));
  s.prog.rapid(lp(c.start));
  for (Vec2 p : c.to_fillet) s.prog.linear(lp(p));
  s.prog.arc(lp(c.fillet_end), lp(c.fillet_center), c.fillet_ccw);
  s.prog.linear(lp(c.end));
  s.prog.rapid(lp(here));
  record_exit(s, st.loc.line, here);
  s.stats.motions += c.to_fillet.size() + 4;
}

}  // namespace

void undercut_stmt(PostState& s, const Statement& st) {
  UndercutWords u;
  if (!read_undercut_words(s, st, u)) return;
  const bool cycle96 = s.m.templates.count("cycle96") > 0;
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
                      num_text(u.diam), cycle96 ? ": CYCLE96 stops with an alarm" : ""));
    return;
  }
  if (!s.feed_given) {
    error(s, st, st.loc, "CYCLE/UNDCUT cuts at the feed in force: no FEDRAT/ before it");
    return;
  }
  ensure_started(s);
  if (cycle96) return undercut_cycle96(s, st, u, *pitch);
  undercut_contour(s, st, u, *pitch);
}

}  // namespace clpost

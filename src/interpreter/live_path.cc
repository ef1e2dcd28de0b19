// What a live tool does alike at the face and across the axis (live_path.h, docs/millturn.md):
// its tool change, its spindle, cutter compensation, its holes and the end of its milling.
#include "interpreter/live_path.h"

#include <fmt/format.h>

#include "interpreter/hole_live.h"
#include "interpreter/milling_motion.h"
#include "interpreter/milling_polar.h"
#include "interpreter/millturn.h"
#include "interpreter/statement_table.h"
#include "interpreter/tool_paths.h"
#include "machine/template_values.h"

namespace clpost {

namespace {

// The live tool stops (template live_spindle_stop) when it turns.
void stop_live(PostState& s, LiveState& l, const Statement& st) {
  if (!l.spindle.on) return;
  l.spindle.on = false;
  if (TemplateWrite r = s.prog.write_template(TemplateFill<tmpl::kLiveSpindleStop>()); !r)
    error(s, st, st.loc, template_error(s.m, r));
}

// CUTCOM's side seen from +Z. APT's LEFT and RIGHT are seen looking down the tool axis from
// the tool; a control's G41/G42 in the face plane (G17) from +Z (docs/millturn.md, "A face tool
// on the -Z side"): for a tool whose axis is 0,0,-1 the two views are opposite.
CutterComp opposite_side(PostState& s, const Statement& st, CutterComp c) {
  if (c == CutterComp::kOff) return c;
  note_once(s, st, "cutcom-minus-z",
            "CUTCOM/ with a live tool whose axis is 0,0,-1: the CL's side is seen from the tool, "
            "on the -Z side; the control's G41/G42 from +Z: written as the other side");
  return c == CutterComp::kLeft ? CutterComp::kRight : CutterComp::kLeft;
}

}  // namespace

void LivePath::prepare(PostState& s, const Statement& st) {
  l_.reported = false;
  hold_main_spindle(s, st);
}

void LivePath::begin(PostState& s, const Statement& st) {
  engage_c(s, st);
}

void LivePath::leave(PostState& s, const Statement& st, bool program_end) {
  leave_milling(s, st, program_end ? Leave::kProgram : Leave::kTool);
}

void LivePath::leave_milling(PostState& s, const Statement& st, Leave how) {
  MillState& m = l_.mill;
  // G40 before polar interpolation ends and before the plane goes back: a control refuses
  // either under G41/G42 (docs/millturn.md).
  if (m.comp != CutterComp::kOff) s.prog.cutter_comp(CutterComp::kOff);
  polar_exit(s, l_);
  // The post's own return of Y to 0 (the CL asked for no such move), when Y as written is off
  // 0 (a Y that prints as 0 left the tool at the control's Y0: linear_3x_PATH2). Y 0 is the
  // centre line: the retract takes the tool clear of the part first.
  if (s.prog.num("Y", m.y) != s.prog.num("Y", 0.0)) {
    retract(s);
    s.prog.writer().code(s.m.code("rapid")).word("Y", 0.0).end_block();
  }
  if (m.plane != 18) {
    s.prog.writer().code(s.m.code("plane_lathe")).end_block();
    s.prog.forget_modal();
  }
  m = MillState{};
  if (how == Leave::kMilling) return;
  stop_live(s, l_, st);
  // Across a tool change C stays engaged for a next milling tool, until the main spindle turns.
  if (how == Leave::kProgram) release_c(s);
}

void LivePath::tool_axis(PostState& s, const Statement&) {
  follow_tool_axis(s);
}

void LivePath::hole(PostState& s, const Statement& st, Point3 p) {
  leave_milling(s, st, Leave::kMilling);  // the hole's C is hole_live.cc's
  live_hole(s, l_, st, p, radial_);
}

void LivePath::go_delta(PostState& s, const Statement& st, const Point3& p) {
  milling_goto(s, l_, st, p, radial_);
}

void LivePath::circle(PostState& s, const Statement& st, const Circle& c) {
  milling_circle(s, l_, st, c, radial_);
}

void LivePath::helical(PostState& s, const Statement& st) {
  milling_helical(s, l_, st, radial_);
}

void LivePath::go(PostState& s, const Statement& st) {
  milling_go(s, l_, st, radial_);
}

void LivePath::part_surface(PostState& s, const Statement& st) {
  // A milling tool's arcs lie across their drive surface's axis (milling_geometry.cc).
  skipped_stmt(s, st);
}

// SPINDL/ while a milling tool is loaded: the live tool's speed (templates live_spindle_rpm and
// live_spindle_stop, codes live_spindle_cw/ccw, millturn.live_max_rpm). The main spindle stays
// stopped.
void LivePath::spindle(PostState& s, const Statement& st, SpindleWords w) {
  if (!s.m.live_tools) return;  // the tool change was an error already
  SpindleState& sp = l_.spindle;
  ensure_started(s);
  if (w.off) {
    sp.on = false;
    if (TemplateWrite r = s.prog.write_template(TemplateFill<tmpl::kLiveSpindleStop>()); !r)
      error(s, st, st.loc, template_error(s.m, r));
    return;
  }
  if (w.css)
    return error(s, st, w.surface_word ? w.surface_word->loc : st.loc,
                 fmt::format("a live tool turns at a speed in RPM: a surface speed for milling "
                             "tool {} is not supported",
                             s.tool.number));
  if (!w.value && w.on && sp.value > 0) w.value = sp.value;
  if (!w.value) return error(s, st, st.loc, "SPINDL/ needs a speed for the live tool");
  if (!(*w.value > 0))
    return error(s, st, w.value_loc,
                 fmt::format("spindle speed must be positive, got {}", *w.value));
  if (!speed_written(s, st, w)) return;
  if (s.m.live_max_rpm > 0 && *w.value > s.m.live_max_rpm)
    return error(s, st, w.value_loc,
                 fmt::format("live tool speed {} rpm exceeds the machine's maximum {} rpm "
                             "(millturn.live_max_rpm)",
                             *w.value, s.m.live_max_rpm));
  if (w.dir) sp.dir = *w.dir;
  sp.value = *w.value, sp.on = true;
  TemplateFill<tmpl::kLiveSpindleRpm> v;
  v.text<"rpm">(s.prog.num("S", sp.value))
      .text<"direction">(
          s.m.code(sp.dir == SpindleDir::kCw ? "live_spindle_cw" : "live_spindle_ccw"));
  if (TemplateWrite r = s.prog.write_template(v); !r) error(s, st, st.loc, template_error(s.m, r));
}

void LivePath::cutter_comp(PostState& s, const Statement& st, const Arg& word, CutterComp c) {
  // Without Y (nor polar interpolation) the post computes X Z C itself: the control's G41/G42
  // would offset the lathe's X and Z, not the path on the face.
  // One cause per tool (milling_motion.cc): after this, or after its motion was refused, the
  // tool's milling is not reported again.
  if (!s.m.y_axis && !s.m.polar_interpolation && c != CutterComp::kOff) {
    if (l_.reported) return;
    l_.reported = true;
    return error(s, st, word.loc,
                 fmt::format("CUTCOM/{} with live tool {}: machine '{}' has no Y axis, and its "
                             "milling is X Z C computed by the post, where the control's cutter "
                             "compensation does not offset the path on the part: give the tool "
                             "centre's path (CUTCOM/OFF) (docs/millturn.md)",
                             word.text, s.tool.number, s.m.name));
  }
  ensure_started(s);
  // The plane first, G17 for a face tool, G19 for a radial one: a control refuses a plane change
  // under G41/G42 (docs/millturn.md).
  if (c != CutterComp::kOff && s.m.y_axis) plane_code(s, l_, s.prog.writer(), radial_ ? 19 : 17);
  l_.mill.comp = c;
  // A tool whose axis is 0,0,-1 stands on the -Z side of the face it works (milling_motion.cc,
  // side_turn).
  const bool from_minus_z = axis_value(s.tool_axis.dir, s.m.cl_axial) < -1 + 1e-6;
  s.prog.cutter_comp(from_minus_z ? opposite_side(s, st, c) : c);
}

void LivePath::before_c_index(PostState& s, const Statement& st) {
  if (l_.mill.polar) leave_milling(s, st, Leave::kMilling);
}

}  // namespace clpost

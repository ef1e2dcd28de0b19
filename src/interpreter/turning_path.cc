// The turning path (turning_path.h): each statement as a lathe writes it.
#include <fmt/format.h>

#include <cmath>

#include "interpreter/millturn.h"
#include "interpreter/statement_table.h"
#include "interpreter/turning_path.h"

namespace clpost {

void TurningPath::leave(PostState& s, const Statement&, bool program_end) {
  if (program_end) release_c(s);  // a ROTABL/ may have engaged C for a turning tool
}

void TurningPath::tool_axis(PostState& s, const Statement& st) {
  note_once(s, st, "tool-axis", "tool axis vectors (GOTO i,j,k) are ignored on a lathe");
}

void TurningPath::go_to(PostState& s, const Statement& st, const Point3& p) {
  if (s.in_cycle) {  // a hole cycle's GOTOs are holes; a refused cycle's were reported at CYCLE/
    if (s.hole_cycle) lathe_hole(s, st, p);
    return;
  }
  lathe_goto(s, st, p);
}

void TurningPath::go_delta(PostState& s, const Statement& st, const Point3& p) {
  lathe_goto(s, st, p);
}

void TurningPath::circle(PostState& s, const Statement& st, const Circle& c) {
  frame_normal(s, st, Point3{c.ax, c.ay, c.az});
  // The arc turns about its axis; in the lathe frame that axis must be normal to the plane.
  const double axis[3] = {c.ax, c.ay, c.az};
  const double len = std::sqrt(c.ax * c.ax + c.ay * c.ay + c.az * c.az);
  if (!(len > 0) || std::abs(std::abs(axis[static_cast<int>(third_axis(s))] / len) - 1) > 1e-6) {
    error(s, st, st.loc,
          fmt::format("CIRCLE axis ({}, {}, {}) is not normal to the lathe plane: the arc cannot "
                      "be cut on a lathe",
                      c.ax, c.ay, c.az));
    return;
  }
  if (!frame_point(s, st, Point3{c.cx, c.cy, c.cz})) return;
  s.circle = c;
}

void TurningPath::helical(PostState& s, const Statement& st) {
  unknown_stmt(s, st);  // a helix is a milling tool's: the comment an unknown statement is
}

void TurningPath::go(PostState& s, const Statement& st) {
  lathe_go(s, st);
}

void TurningPath::part_surface(PostState& s, const Statement& st) {
  lathe_part_surface(s, st);
}

void TurningPath::spindle(PostState& s, const Statement& st, SpindleWords w) {
  main_spindl(s, st, w);
}

void TurningPath::cutter_comp(PostState& s, const Statement&, const Arg&, CutterComp c) {
  ensure_started(s);
  s.prog.cutter_comp(c);
}

}  // namespace clpost

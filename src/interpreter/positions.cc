// Positions the machine file names: GOHOME (the machine's `home` template, one line per axis in
// the order the machine moves them) and the tool-change position written before every tool
// change (`tool_change_position`).
#include <fmt/format.h>

#include "interpreter/statement_table.h"

namespace clpost {

namespace {

// Writes template `t` (no fields); false (reported) when it cannot be.
bool write_position(PostState& s, const Statement& st, const TemplateSpec& t) {
  ensure_started(s);
  if (TemplateWrite r = s.prog.write_template(TemplateValues(t)); !r) {
    error(s, st, st.loc, template_error(s.m, r));
    return false;
  }
  // The tool is where the machine's position puts it: the next move writes both axes.
  s.prog.to_machine_position();
  s.clock_at.reset();
  return true;
}

}  // namespace

void gohome_stmt(PostState& s, const Statement& st) {
  // GOHOME is a motion: a RAPID before it applies to it, never to the motion after it.
  s.rapid_next = false;
  if (circle_waits(s, st)) return;
  std::optional<Point3> home;
  if (!st.args.empty()) {
    Point3 p;
    if (!number_arg(s, st, 0, "X", p.x) || !number_arg(s, st, 1, "Y", p.y)) return;
    if (st.args.size() >= 3 && !number_arg(s, st, 2, "Z", p.z)) return;
    home = p;
  }
  if (s.m.templates.count(std::string(tmpl::kHome.name)) > 0) {
    if (!write_position(s, st, tmpl::kHome)) return;
    s.pos = home;  // the CL's name for the home position, if it gave one
    s.home_line = st.loc.line;
    return;
  }
  if (home) {
    s.rapid_next = true;
    return move_to(s, st, *home);
  }
  warning(s, st, st.loc,
          fmt::format("GOHOME: machine '{}' has no template 'home' and the CL gives no home "
                      "point: written as a comment",
                      s.m.name));
  ensure_started(s);
  s.prog.comment(st.source);
}

void tool_change_position(PostState& s, const Statement& st) {
  if (s.m.templates.count(std::string(tmpl::kToolChangePosition.name)) == 0) return;
  if (write_position(s, st, tmpl::kToolChangePosition)) s.pos.reset();
}

}  // namespace clpost

// CYCLE/: thread undercuts (CYCLE/UNDCUT, undercut.cc), holes on the spindle axis (CYCLE/DRILL …,
// hole_cycles.cc); other cycles are refused with their holes, so that no hole is posted as a
// plain move.
#include <fmt/format.h>

#include "interpreter/statement_table.h"

namespace clpost {

void cycle_stmt(PostState& s, const Statement& st) {
  if (!st.args.empty() && st.args[0].is("OFF")) {
    s.in_cycle = false;
    s.hole_cycle.reset();
    return;
  }
  if (!st.args.empty() && st.args[0].is("UNDCUT")) return undercut_stmt(s, st);
  if (!st.args.empty() && st.args[0].is("LATHTHRD")) return lathe_thread_cycle(s, st);
  if (!st.args.empty() && st.args[0].is_word() && is_hole_cycle(st.args[0].text))
    return hole_cycle_stmt(s, st);
  s.in_cycle = true;  // its hole positions are not posted as plain moves
  if (st.args.empty() || !st.args[0].is_word()) {
    error(s, st, st.args.empty() ? st.loc : st.args[0].loc,
          fmt::format("CYCLE/ needs the cycle's kind first (DRILL, DEEP, BRKCHP, TAP, BORE, REAM, "
                      "OFF, …), found {}",
                      describe_arg(st.args, 0)));
    return;
  }
  error(s, st, st.loc,
        fmt::format("CYCLE/{} is not supported on machine '{}': its holes would be lost; "
                    "post the drilling with a milling post or output it as motion",
                    st.args[0].text, s.m.name));
}

}  // namespace clpost

// CATIA's CYCLE/LATHTHRD (reference/cam/SPWAEC_VTX550.pptable, NC_LATHE_THREADING): the thread
// as one record of named parameters. It gives the pitch, depth, passes, infeed angle, lift-off
// and the END of the thread (COORD, END_THRD_RAD) but not where along the axis the thread
// starts (LENGTH and LEAD_IN_DIST are lengths without a side or an origin): the planner cannot
// place its passes. Refused with that reason, naming what is missing,
// rather than guessed; CATIA writes the same thread as THREAD/ON … THREAD/OFF with ICAM's table.
#include <fmt/format.h>

#include <algorithm>
#include <array>
#include <string_view>

#include "interpreter/statement_table.h"

namespace clpost {

void lathe_thread_cycle(PostState& s, const Statement& st) {
  // The parameters a multi-pass plan needs, in the order CATIA writes them.
  constexpr std::array<std::string_view, 4> kNeeded = {"DEPTH", "NB_PATHES", "COORD",
                                                       "START_THRD_RAD"};
  std::string_view missing;
  for (std::string_view w : kNeeded) {
    const bool given = std::any_of(st.args.begin(), st.args.end(),
                                   [&](const Arg& a) { return a.is_word() && a.text == w; });
    if (!given) {
      missing = w;
      break;
    }
  }
  s.in_cycle = true;  // its GOTOs up to CYCLE/OFF are not plain moves
  if (!missing.empty()) {
    error(s, st, st.loc,
          fmt::format("CYCLE/LATHTHRD without {}: the thread cannot be planned", missing));
    return;
  }
  error(s, st, st.loc,
        "CYCLE/LATHTHRD does not say where the thread starts along the axis (COORD is its end; "
        "LENGTH and LEAD_IN_DIST give no side and no origin): the thread cannot be planned; "
        "write it as THREAD/ON … THREAD/OFF (CATIA's ICAM tables do)");
}

}  // namespace clpost

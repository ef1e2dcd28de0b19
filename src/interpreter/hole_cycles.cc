// CYCLE/DRILL|DEEP|BRKCHP|TAP|BORE|REAM …: hole-making on the spindle axis, in the forms CAM
// systems write them:
//   ICAM/APT, Pro/E   CYCLE/DRILL,[DEPTH,]d,IPM|MMPM|IPR|MMPR,f,[CLEAR,]c[,DWELL,t]
//                     CYCLE/DEEP,DEPTH,d,STEP|PECK,p,MMPM,f,CLEAR,c   CYCLE/TAP,DEPTH,d,TPI,n,…
//   SolidWorks CAM    CYCLE/DEEP2,FEDTO,d,1STPECK,p1,SUBPECK,p,MMPM,f,RAPTO,c,RTRCTO,r[,DWELL,t]
//   CATIA             CYCLE/TAP,d,c   (total depth, clearance; the feed in force)
//   NX                CYCLE/DRILL[,DEEP|BRKCHP],RAPTO,c,FEDTO,d,MMPM,f[,STEP,p]
// then a GOTO per hole (its top), until CYCLE/OFF. CYCLE/INIT (SolidWorks) says nothing.
// A hole must lie on the lathe's centre line: drilling off it needs live tooling.
#include <fmt/format.h>

#include <cmath>

#include "interpreter/statement_table.h"
#include "planner/number_text.h"

namespace clpost {

namespace {

constexpr double kMmPerInch = 25.4;

std::optional<HoleKind> kind_of(std::string_view w) {
  if (w == "DRILL") return HoleKind::kDrill;
  if (w == "DEEP" || w == "DEEP2" || w == "DEEPHL") return HoleKind::kDeep;
  if (w == "BRKCHP") return HoleKind::kChipBreak;
  if (w == "TAP") return HoleKind::kTap;
  if (w == "BORE") return HoleKind::kBore;
  if (w == "REAM") return HoleKind::kReam;
  return std::nullopt;
}

// A length in `unit_in` inches or mm, in CL units.
double cl_length(const PostState& s, double v, bool inch) {
  const bool cl_inch = s.units == LengthUnit::kInch;
  return inch == cl_inch ? v : inch ? v * kMmPerInch : v / kMmPerInch;
}

// The number after word `i` into `out`; false (reported) when there is none.
bool value_after(PostState& s, const Statement& st, size_t& i, double& out) {
  const Arg& w = st.args[i];
  if (i + 1 >= st.args.size() || !st.args[i + 1].is_number()) {
    error(s, st, w.loc,
          fmt::format("CYCLE/{}: {} needs a number after it", st.args[0].text, w.text));
    return false;
  }
  if (!in_range(s, st, st.args[i + 1], w.text)) return false;
  out = st.args[++i].number;
  return true;
}

// One word of the cycle (with its value); false (reported) when it is not one.
bool read_hole_word(PostState& s, const Statement& st, size_t& i, HoleCycle& c) {
  const Arg& a = st.args[i];
  double v = 0;
  const bool feed_word = a.is("IPM") || a.is("MMPM") || a.is("IPR") || a.is("MMPR");
  if (!a.is_word()) {
    error(s, st, a.loc,
          fmt::format("CYCLE/{}: expected a cycle word, found {}", c.word, describe_arg(st, a)));
    return false;
  }
  // NX: CYCLE/DRILL,DEEP,… or DRILL,BRKCHP,…: the kind as a word of DRILL.
  if (const std::optional<HoleKind> k = kind_of(a.text); k && c.kind == HoleKind::kDrill) {
    c.kind = *k;
    return true;
  }
  if (!value_after(s, st, i, v)) return false;
  if (a.is("DEPTH") || a.is("FEDTO")) {
    c.depth = v;
  } else if (a.is("STEP") || a.is("PECK") || a.is("INCR") || a.is("SUBPECK")) {
    c.peck = v;
  } else if (a.is("1STPECK")) {
    c.first_peck = v;
  } else if (feed_word) {
    const bool inch = a.is("IPM") || a.is("IPR");
    c.feed =
        s.units == LengthUnit::kInch ? (inch ? v : v / kMmPerInch) : (inch ? v * kMmPerInch : v);
    c.feed_mode = a.is("IPM") || a.is("MMPM") ? FeedMode::kPerMinute : FeedMode::kPerRev;
  } else if (a.is("TPI")) {
    c.lead = cl_length(s, 1 / v, true);
  } else if (a.is("PITCH") || a.is("LEAD")) {
    c.lead = v;
  } else if (a.is("CLEAR") || a.is("RAPTO")) {
    c.clearance = v;
  } else if (a.is("RTRCTO")) {
    c.retract = v;
  } else if (a.is("DWELL")) {
    c.dwell = v;
  } else {
    error(s, st, a.loc,
          fmt::format("CYCLE/{}: unknown word '{}'; valid words: DEPTH, FEDTO, STEP, PECK, "
                      "INCR, 1STPECK, SUBPECK, IPM, MMPM, IPR, MMPR, TPI, PITCH, CLEAR, RAPTO, "
                      "RTRCTO, DWELL",
                      c.word, a.text));
    return false;
  }
  if (v < 0 || (v == 0 && (a.is("TPI") || a.is("PITCH") || feed_word))) {
    error(s, st, st.args[i].loc,
          fmt::format("CYCLE/{}: {} {} must be positive", c.word, a.text, st.args[i].text));
    return false;
  }
  return true;
}

// The cycle's words; false (reported) on a bad one.
bool read_hole_cycle(PostState& s, const Statement& st, HoleCycle& c) {
  int positional = 0;  // bare numbers: the depth, then the clearance
  for (size_t i = 1; i < st.args.size(); ++i) {
    const Arg& a = st.args[i];
    if (a.is_number()) {
      if (!in_range(s, st, a, "a cycle value")) return false;
      if (positional == 0 && c.depth == 0) {
        c.depth = a.number;
      } else if (!c.clearance) {
        c.clearance = a.number;
      } else {
        error(s, st, a.loc,
              fmt::format("CYCLE/{}: unexpected number {}: the depth and the clearance are given "
                          "already",
                          c.word, a.text));
        return false;
      }
      ++positional;
      continue;
    }
    if (!read_hole_word(s, st, i, c)) return false;
  }
  if (!(c.depth > 0)) {
    error(s, st, st.loc, fmt::format("CYCLE/{} needs a depth greater than 0", c.word));
    return false;
  }
  if ((c.kind == HoleKind::kDeep || c.kind == HoleKind::kChipBreak) && c.peck <= 0)
    c.peck = c.first_peck;  // one peck given: every peck
  return true;
}

}  // namespace

bool is_hole_cycle(std::string_view word) {
  return word == "INIT" || kind_of(word).has_value();
}

void hole_cycle_stmt(PostState& s, const Statement& st) {
  const std::string_view word = st.args[0].text;
  if (word == "INIT") return;
  HoleCycle c;
  c.kind = *kind_of(word);
  c.word = std::string(word);
  c.loc = st.loc;
  c.line = st.loc.line;
  s.in_cycle = true;  // a refused cycle's holes are not moves either
  if (!read_hole_cycle(s, st, c)) return;
  s.hole_cycle = c;
}

}  // namespace clpost

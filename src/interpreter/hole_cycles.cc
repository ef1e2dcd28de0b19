// CYCLE/DRILL|DEEP|BRKCHP|TAP|BORE|REAM|FACE …: hole-making on the spindle axis, in the forms CAM
// systems write them:
//   ICAM/APT, Pro/E   CYCLE/DRILL,[DEPTH,]d,IPM|MMPM|IPR|MMPR,f,[CLEAR,]c[,DWELL,t]
//                     CYCLE/DEEP,DEPTH,d,STEP|PECK,p,MMPM,f,CLEAR,c   CYCLE/TAP,DEPTH,d,TPI,n,…
//   CATIA + ICAM      …,CLEAR,c[,backoff],RETURN,j[,REV|SEC|DWELL,t][,INVERS]; ORIENT refused
//                     (reference/cam/ICAM_MM_pptable_cycles_and_millturn_excerpt.txt)
//   SolidWorks CAM    CYCLE/DEEP2,FEDTO,d,1STPECK,p1,SUBPECK,p,MMPM,f,RAPTO,c,RTRCTO,r[,DWELL,t]
//   CATIA             CYCLE/TAP,d,c   (total depth, clearance; the feed in force)
//   NX                CYCLE/DRILL[,DEEP|BRKCHP],RAPTO,c,FEDTO,d,MMPM,f[,STEP,p]
// then a GOTO per hole (its top), until CYCLE/OFF. CYCLE/INIT (SolidWorks) says nothing.
// A hole must lie on the lathe's centre line: drilling off it needs live tooling.
// docs/reading-cam-output.md (section 5) says where each ICAM word's meaning comes from.
#include <fmt/format.h>

#include <cmath>

#include "interpreter/statement_table.h"
#include "support/number_text.h"

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
  if (w == "FACE") return HoleKind::kDrill;  // ICAM's countersinking: feed, dwell, rapid out
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

// ORIENT and INVERS, ICAM's words for CATIA's Boring Spindle Stop and Reverse Threading; false
// (reported) when the cycle cannot be written with them.
bool mode_word(PostState& s, const Statement& st, const Arg& a, HoleCycle& c) {
  if (a.is("ORIENT")) {
    error(s, st, a.loc,
          fmt::format("CYCLE/{}: ORIENT (CATIA's Boring Spindle Stop: the spindle stopped at an "
                      "angle and the tool moved off the wall before it leaves) cannot be written "
                      "for a hole on a lathe's spindle axis, where the part turns and the tool "
                      "does not",
                      c.word));
    return false;
  }
  if (c.kind != HoleKind::kTap) {
    error(s, st, a.loc,
          fmt::format("CYCLE/{}: INVERS (ICAM writes it on CYCLE/TAP for CATIA's Reverse "
                      "Threading) would make this a back boring, from the far side of the part: "
                      "not written for a hole on a lathe's spindle axis",
                      c.word));
    return false;
  }
  if (s.spindle.on && s.spindle.dir != SpindleDir::kCcw) {
    error(s, st, a.loc,
          fmt::format("CYCLE/TAP: INVERS (CATIA's Reverse Threading, a left-hand tap) while the "
                      "spindle turns clockwise (SPINDL of line {}): whether INVERS reverses it is "
                      "not written down, so the tap's direction is in doubt; program "
                      "SPINDL/…,CCLW for the tap",
                      s.spindle_line));
    return false;
  }
  c.invers = true;
  return true;
}

// Value word `a` with its value `v` into the cycle; false when it is not one (not reported).
bool set_value(const PostState& s, const Arg& a, double v, HoleCycle& c) {
  if (a.is("DEPTH") || a.is("FEDTO")) {
    c.depth = v;
  } else if (a.is("STEP") || a.is("PECK") || a.is("INCR") || a.is("SUBPECK")) {
    c.peck = v;
  } else if (a.is("1STPECK")) {
    c.first_peck = v;
  } else if (a.is("IPM") || a.is("MMPM") || a.is("IPR") || a.is("MMPR")) {
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
  } else if (a.is("RETURN")) {
    c.return_dist = v, c.return_loc = a.loc;
  } else if (a.is("DWELL") || a.is("SEC")) {
    c.dwell = v, c.dwell_revs.reset(), c.dwell_loc = a.loc;
  } else if (a.is("REV")) {
    c.dwell_revs = v, c.dwell = 0, c.dwell_loc = a.loc;
  } else {
    return false;
  }
  return true;
}

// One word of the cycle (with its value); false (reported) when it is not one.
bool read_hole_word(PostState& s, const Statement& st, size_t& i, HoleCycle& c) {
  const Arg& a = st.args[i];
  double v = 0;
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
  if (a.is("ORIENT") || a.is("INVERS")) return mode_word(s, st, a, c);
  if (!value_after(s, st, i, v)) return false;
  if (!set_value(s, a, v, c)) {
    error(s, st, a.loc,
          fmt::format("CYCLE/{}: unknown word '{}'; valid words: DEPTH, FEDTO, STEP, PECK, "
                      "INCR, 1STPECK, SUBPECK, IPM, MMPM, IPR, MMPR, TPI, PITCH, CLEAR, RAPTO, "
                      "RTRCTO, RETURN, DWELL, SEC, REV, INVERS",
                      c.word, a.text));
    return false;
  }
  const bool nonzero =
      a.is("TPI") || a.is("PITCH") || a.is("IPM") || a.is("MMPM") || a.is("IPR") || a.is("MMPR");
  if (v < 0 || (v == 0 && nonzero)) {
    error(s, st, st.args[i].loc,
          fmt::format("CYCLE/{}: {} {} must be positive", c.word, a.text, st.args[i].text));
    return false;
  }
  // ICAM's chip breaking: CLEAR,c,backoff — the number after the clearance is how far each peck
  // backs off (CATIA's MFG_OFFSET_RET).
  if (a.is("CLEAR") && c.kind == HoleKind::kChipBreak && i + 1 < st.args.size() &&
      st.args[i + 1].is_number()) {
    const Arg& b = st.args[++i];
    if (!in_range(s, st, b, "a chip-break back-off")) return false;
    if (!(b.number > 0)) {
      error(s, st, b.loc,
            fmt::format("CYCLE/{}: the chip-break back-off {} after CLEAR must be positive", c.word,
                        b.text));
      return false;
    }
    c.backoff = b.number;
  }
  return true;
}

// RETURN (ICAM's jump distance) becomes the retract plane, measured from the R plane; false
// (reported) when it cannot.
bool settle_hole_cycle(PostState& s, const Statement& st, HoleCycle& c) {
  if (c.return_dist) {
    if (!c.clearance) {
      error(s, st, c.return_loc,
            fmt::format("CYCLE/{}: RETURN is a distance above the CLEAR plane, and the cycle has "
                        "no CLEAR",
                        c.word));
      return false;
    }
    if (c.retract) {
      error(s, st, c.return_loc,
            fmt::format("CYCLE/{}: RETURN and RTRCTO both give the plane the tool retracts to",
                        c.word));
      return false;
    }
    c.retract = *c.clearance + *c.return_dist;
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
  return settle_hole_cycle(s, st, c);
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

// The major words the interpreter knows and their handlers (statement_table.h).
#include "interpreter/statement_table.h"

#include <algorithm>
#include <array>

namespace clpost {

namespace {

constexpr StatementEntry kEntries[] = {
    // Motion (motion.cc)
    {"GOTO", goto_stmt},
    {"FROM", from_stmt},
    {"GODLTA", godlta_stmt},
    {"CIRCLE", circle_stmt},
    {"MOVARC", movarc_stmt},
    {"HELICAL", helical_stmt},  // motion.cc
    {"RAPID", rapid_stmt},
    // Feed, spindle, dwell (spindle_feed.cc)
    {"FEDRAT", fedrat_stmt},
    {"SPINDL", spindl_stmt},
    {"DELAY", delay_stmt},
    // Tools (tool.cc)
    {"LOADTL", loadtl_stmt},
    {"LOAD", load_stmt},
    {"TURRET", loadtl_stmt},
    {"TOOLNO", toolno_stmt},
    {"TPRINT", tprint_stmt},
    {"SWITCH", switch_stmt},
    {"CUTTER", cutter_stmt},
    // CAM words (cam_words.cc) and APT geometric motion (geometric_motion.cc)
    {"SYN", syn_stmt},
    {"DNTCUT", dntcut_stmt},
    {"CUT", cut_stmt},
    {"PPFUN", ppfun_stmt},
    {"INDIRV", indirv_stmt},
    {"PSIS", psis_stmt},
    {"GOFWD", go_stmt},
    {"GOLFT", go_stmt},
    {"GORGT", go_stmt},
    {"GOBACK", go_stmt},
    // Program words (program_words.cc)
    {"UNITS", units_stmt},
    {"UNIT", units_stmt},
    {"COOLNT", coolnt_stmt},
    {"CUTCOM", cutcom_stmt},
    {"STOP", stop_stmt},
    {"OPSTOP", stop_stmt},
    {"END", end_stmt},
    {"FINI", fini_stmt},
    {"GOHOME", gohome_stmt},
    // Pass-through words (machine_words.cc)
    {"AUXFUN", auxfun_stmt},
    {"PREFUN", prefun_stmt},
    {"SELCTL", selctl_stmt},
    {"CLAMP", clamp_stmt},
    {"OPSKIP", opskip_stmt},
    {"MULTAX", multax_stmt},
    {"NURBS", spline_stmt},
    {"KNOT", spline_stmt},
    // Records that carry nothing a lathe program needs: understood and skipped, noted once.
    {"MSYS", skipped_stmt},
    {"PAINT", skipped_stmt},
    {"END-OF-PATH", skipped_stmt},
    {"MACHIN", skipped_stmt},
    {"SELECT", skipped_stmt},
    {"TRNTYP", skipped_stmt},
    {"CSYS", skipped_stmt},
    {"CNTRL", skipped_stmt},
    {"SETUP", skipped_stmt},
    {"CSI_SET_FLUTE_LENGTH", skipped_stmt},
    {"CSI_SET_EXTENSION_LENGTH", skipped_stmt},
    {"MFGNO", skipped_stmt},
    {"FEATNO", skipped_stmt},
    {"CLEARP", skipped_stmt},
    {"TOLER", skipped_stmt},
    {"INTOL", skipped_stmt},
    {"OUTTOL", skipped_stmt},
    {"DISPLY", skipped_stmt},
    {"AUTOPS", skipped_stmt},
    {"PLABEL", skipped_stmt},
    {"CALSUB", skipped_stmt},
    {"ORIGIN", skipped_stmt},
    {"TLAXIS", skipped_stmt},
    {"REWIND", skipped_stmt},
    // APT's comment statement; NCL's APT source and binary clfile begin with one.
    {"REMARK", skipped_stmt},
    // Mill-turn (millturn.cc)
    {"TDATA", tdata_stmt},
    {"TLDATA", tdata_stmt},
    {"APPLY", apply_stmt},
    {"SET", apply_stmt},
    {"MODE", apply_stmt},
    {"ROTABL", rotabl_stmt},
    {"ROTATE", rotabl_stmt},
    {"SYNC", sync_stmt},
    {"CHANNEL", channel_stmt},
    // Text (text_words.cc)
    {"PARTNO", partno_stmt},
    {"PPRINT", pprint_stmt},
    {"INSERT", insert_stmt},
    {"TOOL PATH", tool_path_stmt},
    // Threads (thread_statements.cc) and cycles (cycles.cc)
    {"PITCH", pitch_stmt},
    {"THREAD", thread_stmt},
    {"OP", op_stmt},
    {"COUPLE", couple_stmt},
    {"CYCLE", cycle_stmt},
};

// Sorted by major word for the lookup.
constexpr auto kSorted = [] {
  std::array<StatementEntry, std::size(kEntries)> t{};
  std::copy(std::begin(kEntries), std::end(kEntries), t.begin());
  std::sort(t.begin(), t.end(),
            [](const StatementEntry& a, const StatementEntry& b) { return a.major < b.major; });
  return t;
}();

static_assert(std::adjacent_find(kSorted.begin(), kSorted.end(),
                                 [](const StatementEntry& a, const StatementEntry& b) {
                                   return a.major == b.major;
                                 }) == kSorted.end(),
              "a major word is in the table twice");

}  // namespace

const StatementEntry* find_statement(std::string_view major) {
  auto it =
      std::lower_bound(kSorted.begin(), kSorted.end(), major,
                       [](const StatementEntry& e, std::string_view w) { return e.major < w; });
  return it != kSorted.end() && it->major == major ? &*it : nullptr;
}

std::span<const StatementEntry> statement_table() {
  return kSorted;
}

}  // namespace clpost

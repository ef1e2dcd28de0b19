// The planner's shared reporting and the one check of the pitch in force (plan_report.h).
#include "planner/plan_report.h"

#include <fmt/format.h>

#include <cmath>

#include "support/number_text.h"

namespace clpost::plan_report {

std::string pt(Vec2 p) {
  return fmt::format("(X {}, Z {})", num_text(p.x), num_text(p.z));
}

std::string machine_text(const PlannerSettings& s) {
  return s.machine_name.empty() ? std::string("this machine")
                                : fmt::format("machine '{}'", s.machine_name);
}

bool on_statement(const SavedLines& lines, SourceLoc loc) {
  return loc.line != 0 && loc.line >= lines.first_line &&
         loc.line - lines.first_line < lines.lines.size();
}

bool check_pitch(const PitchSpec& pitch, Site site, std::string_view word,
                 const PlannerSettings& settings, Reporter& r) {
  if (!pitch.set) {
    return r.error(site, fmt::format("no pitch in force at {}: give PITCH/ before it, or TPI, "
                                     "IPR, MMPR or PERREV on it",
                                     word));
  }
  if (pitch.lead_change != 0 && !settings.variable_lead) {
    const SourceLoc cl = pitch.lead_change_loc;
    const Site at = on_statement(*site.lines, cl) ? Site{cl, site.lines} : site;
    return r.error(at, fmt::format("variable lead ({} {} per revolution, CL line {}) cannot be "
                                   "cut on {}: it does not declare variable-lead threading "
                                   "(G34/G35)",
                                   pitch.lead_change > 0 ? "INCR" : "DECR",
                                   num_text(std::fabs(pitch.lead_change)),
                                   cl.line != 0 ? cl.line : site.loc.line, machine_text(settings)));
  }
  return true;
}

ThreadKind kind_of(Vec2 d) {
  if (std::fabs(d.x) <= kLengthEps) return ThreadKind::kTurn;
  if (std::fabs(d.z) <= kLengthEps) return ThreadKind::kFace;
  return ThreadKind::kTaper;
}

}  // namespace clpost::plan_report

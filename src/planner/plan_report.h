#pragma once
// What every planner form shares: how it reports (a diagnostic at a statement whose lines were
// saved), how it prints points, and the one check of the pitch in force. Internal to planner/.
#include <string>
#include <string_view>

#include "planner/planner.h"
#include "planner/thread_plan.h"
#include "reader/statement.h"
#include "support/diagnostics.h"

namespace clpost::plan_report {

// Lengths below this (CL units) are zero.
inline constexpr double kLengthEps = 1e-9;
// Angles closer than this (degrees) are equal.
inline constexpr double kAngleEps = 1e-9;

// "(X 1.5, Z -20)": a CL point in messages.
std::string pt(Vec2 p);
// "machine 'fanuc-0i-t'", or "this machine" when the settings have no name.
std::string machine_text(const PlannerSettings& s);
// Whether `loc` is on one of the statement's saved lines.
bool on_statement(const SavedLines& lines, SourceLoc loc);

// A statement's location and saved lines, for reporting.
struct Site {
  SourceLoc loc;
  const SavedLines* lines;
};

class Reporter {
 public:
  explicit Reporter(Diagnostics& d) : diags_(d) {}
  // Reports and returns false, for `return r.error(...)`.
  bool error(Site s, std::string message) {
    diags_.error(s.loc, s.lines->text(s.loc.line), std::move(message));
    return false;
  }
  void warning(Site s, std::string message) {
    diags_.warning(s.loc, s.lines->text(s.loc.line), std::move(message));
  }
  void note(Site s, std::string message) {
    diags_.note(s.loc, s.lines->text(s.loc.line), std::move(message));
  }

 private:
  Diagnostics& diags_;
};

// The pitch in force at `word` (the statement at `site`): present, and constant unless the
// machine can cut a variable lead. False, with the error reported, otherwise.
bool check_pitch(const PitchSpec& pitch, Site site, std::string_view word,
                 const PlannerSettings& settings, Reporter& r);

// Turn (no radial travel), face (no axial travel) or taper.
ThreadKind kind_of(Vec2 d);

}  // namespace clpost::plan_report

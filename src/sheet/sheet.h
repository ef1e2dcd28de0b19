#pragma once
// The setup sheet (clpost sheet, --sheet DIR): one self-contained HTML page per program for the
// operator — the tool list and times, every thread's passes and output, every hole, the backplot
// and the warnings — and the same data as JSON. It is written from the data the post itself
// keeps (the clock's CycleTime, the planner's ThreadPlans, the holes, the output each job was
// written by, the diagnostics), the same values `clpost check` and `clpost plan` print.
#include <string>
#include <vector>

#include "emitters/cycle_output.h"
#include "interpreter/cycle_time.h"
#include "laws/hole_law.h"
#include "planner/thread_plan.h"
#include "plot/path_thinner.h"
#include "support/diagnostics.h"

namespace clpost {

struct SheetData {
  std::string program;  // the CL file, as diagnostics name it
  std::string partno;   // PARTNO text ("" when none)
  std::string nc_file;  // the NC program the sheet goes with ("": none written)
  std::string machine;  // the machine's name
  std::string machine_description;
  std::string date;  // as printed (sheet_date())
  LengthUnit units = LengthUnit::kMm;
  bool diameter = true;  // X is written as a diameter (the tool list's X reach, as check prints)
  CycleTime cycle_time;
  std::vector<ThreadPlan> plans;
  std::vector<Hole> holes;
  // Per hole, in order: what wrote it as its reader calls it ("peck drilling (G83)",
  // hole_output_text); none: the output's name.
  std::vector<std::string> hole_outputs;
  std::vector<OutputUsed> outputs;      // what wrote each thread and hole
  std::vector<Diagnostic> diagnostics;  // the kept ones (warnings and notes)
  size_t warnings = 0;                  // all, kept or not
  ThinnedPath toolpath;  // the program as its control runs it, thinned (the backplot)
};

// The page: a complete HTML5 document, no external file, script or font.
std::string sheet_html(const SheetData& d);

// The same data as one JSON object ending in a newline; its "plan" is what
// `clpost plan --format json` writes for the file.
std::string sheet_json(const SheetData& d);

// The date a sheet shows: `given` when not empty, else SOURCE_DATE_EPOCH (`epoch`, when not
// null) as "YYYY-MM-DD HH:MM UTC", else now in UTC. False, with `error`, for an epoch that is not
// a whole number of seconds.
bool sheet_date(const std::string& given, const char* epoch, std::string& date, std::string& error);

}  // namespace clpost

#pragma once
// The JSON report of a batch (`clpost … --report report.json`), for pipeline dashboards:
//
//   {"machine": "generic-lathe", "output_dir": "out", "jobs": 2,
//    "summary": {"files": 3, "ok": 1, "with_warnings": 1, "failed": 1, "not_posted": 0,
//                "errors": 1, "warnings": 2, "bytes_in": 1200, "bytes_out": 900, "seconds": 0.01},
//    "files": [{"input": "in/a.cl", "output": "out/a.nc", "status": "ok", "errors": 0,
//               "warnings": 0, "statements": 40, "motions": 31, "threads": 1, "passes": 5,
//               "bytes_in": 400, "bytes_out": 300, "seconds": 0.002, "cycle_time": {…},
//               "sheet": "out/a.html",
//               "diagnostics": [{"severity": "warning", "line": 5, "column": 1,
//                                "message": "…"}]}, …]}
//
// "status" is ok | warnings | error | not-posted; "output" is null unless the program was
// written; "sheet" is the setup sheet written beside it (--sheets), else null; "line"/"column"
// are 0 when unknown. Written atomically like the NC programs.
#include <string>
#include <vector>

#include "cli/batch.h"

namespace clpost {

struct BatchReportInfo {
  std::string machine;
  std::string output_dir;
  unsigned jobs = 1;
};

std::string batch_report_json(const BatchReportInfo& info, const BatchSummary& summary,
                              const std::vector<FileResult>& results);

const char* status_name(FileStatus s);

}  // namespace clpost

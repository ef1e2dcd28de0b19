#pragma once
// `clpost plot`: SVG pictures of a CL file's plan or of an NC program's motion (plot/).
#include <string>

#include "machine/machine.h"

namespace clpost {

struct PlotRequest {
  std::string input;   // a CL file (by its extension, batch.h is_cl_file_name) or an NC program
  std::string cl;      // with an NC program: the CL file whose plan it is (for the sections)
  std::string output;  // "-": standard output
  int thread = 0;      // 0: the backplot with every thread's section; N: thread N's section only
  const Machine* machine = nullptr;
};

struct PlotOutcome {
  bool ok = false;
  std::string diagnostics;  // for standard error
  size_t threads = 0;
  size_t moves = 0;
};

// A CL file is posted on the machine (nothing written) and its program run through the control
// simulation for the backplot; its sections come from the plan. An NC program is run through
// the simulation; with `cl`, its sections show where its cuts are, measured against the plan.
PlotOutcome plot_file(const PlotRequest& req);

}  // namespace clpost

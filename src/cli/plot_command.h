#pragma once
// `clpost plot`: SVG pictures of a CL file's plan or of an NC program's motion (plot/).
#include <string>

#include <string_view>

#include "machine/machine.h"
#include "simulator/control_sim.h"

namespace clpost {

struct PlotRequest {
  std::string input;   // a CL file (by its extension, batch.h is_cl_file_name) or an NC program
  std::string cl;      // with an NC program: the CL file whose plan it is (for the sections)
  std::string output;  // "-": standard output
  int thread = 0;      // 0: the backplot with every thread's section; N: thread N's section only
  bool full = false;   // every move drawn and every section (else path_thinner.h, SectionGroups)
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
// Unless `full`, the moves stream from the simulation into a PathThinner (the program of a CL
// file through a temporary file), so memory and the picture stay bounded whatever the length,
// identical sections are drawn once with their count, and a note says what was simplified.
PlotOutcome plot_file(const PlotRequest& req);

// Runs the NC program `text` (shown in diagnostics as `name`) through the machine's control
// simulation into `sim`; its diagnostics are appended to `diagnostics`. False on errors.
bool simulate_text(std::string_view text, const std::string& name, const Machine& m,
                   Simulation& sim, std::string& diagnostics, const SimOptions& options = {});

}  // namespace clpost

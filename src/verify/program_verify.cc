#include "verify/program_verify.h"

#include <fmt/format.h>

#include "simulator/control_sim.h"
#include "verify/hole_verify.h"
#include "verify/verify.h"

namespace clpost {

VerifyOutcome verify_program(reader::LineSource& src, const std::string& program_name,
                             const std::vector<ThreadPlan>& plans, const ClExpected* cl,
                             const std::string& plan_name, const Machine& m, double tolerance) {
  VerifyOutcome out;
  Diagnostics diags(program_name);
  Simulation sim;
  SimOptions so;
  so.keep_moves = cl != nullptr && !cl->path.motions.empty();
  if (simulate_nc(src, m, diags, sim, so)) {
    VerifyOptions vo;
    vo.tolerance = tolerance;
    vo.plan_name = plan_name;
    VerifyReport report;
    out.ok = verify_cuts(plans, sim, m, vo, diags, report);
    out.report = verify_report_text(report, plans, program_name, m, vo);
    if (cl != nullptr) {
      const HoleReport hr = verify_holes(cl->holes, sim.holes, m, vo, diags);
      const PathReport pr = verify_path(cl->path, sim.path, m, vo, diags);
      out.ok = out.ok && hr.problems == 0 && pr.problems == 0;
      out.report += hr.text + pr.text;
    }
  } else {
    out.report =
        fmt::format("verify {}: the program cannot be read (see the errors)\n", program_name);
  }
  out.errors = diags.error_count();
  out.diagnostics = diags.render_all();
  for (const Diagnostic& d : diags.kept())
    if (d.severity == Severity::kError) {
      out.first_error = fmt::format("{}:{}: {}", program_name, d.loc.line, d.message);
      break;
    }
  return out;
}

}  // namespace clpost

#include "verify/program_verify.h"

#include <fmt/format.h>

#include <algorithm>

#include "simulator/control_sim.h"
#include "verify/hole_verify.h"
#include "verify/verify.h"

namespace clpost {

namespace {

// The program with block delete on against the CL without its OPSKIP ranges: every statement
// outside them is done exactly either way (docs/cl-meaning.md). Its differences that the run
// with block delete off has not go into `diags`, marked; the count of those.
size_t verify_block_delete(const ClPath& cl, const Simulation& on, const Machine& m,
                           const VerifyOptions& vo, Diagnostics& diags) {
  ClPath kept;
  kept.states = cl.states;
  for (const ClMotion& mo : cl.motions)
    if (!mo.optional) kept.motions.push_back(mo);
  Diagnostics d(diags.file());
  const PathReport pr = verify_path(kept, on.path, m, vo, d);
  if (pr.problems == 0) return 0;
  size_t added = 0;
  const std::vector<Diagnostic> off = diags.kept();
  for (const Diagnostic& e : d.kept()) {
    if (e.severity != Severity::kError) continue;
    const bool known = std::any_of(off.begin(), off.end(), [&](const Diagnostic& o) {
      return o.loc.line == e.loc.line && o.message == e.message;
    });
    if (known) continue;
    diags.error(e.loc, e.line_text, e.message + " (block delete on)");
    ++added;
  }
  return added;
}

}  // namespace

VerifyOutcome verify_program(reader::LineSource& src, const std::string& program_name,
                             const std::vector<ThreadPlan>& plans, const ClExpected* cl,
                             const std::string& plan_name, const Machine& m, double tolerance) {
  VerifyOutcome out;
  Diagnostics diags(program_name);
  Simulation sim;
  SimOptions so;
  so.keep_moves = cl != nullptr && !cl->path.motions.empty();
  so.block_delete_too = so.keep_moves;
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
      size_t on = 0;
      for (const Simulation& s : sim.with_block_delete)
        on += verify_block_delete(cl->path, s, m, vo, diags);
      out.ok = out.ok && hr.problems == 0 && pr.problems == 0 && on == 0;
      out.report += hr.text + pr.text;
      if (on > 0)
        out.report += fmt::format("block delete on: {} difference{} (see the errors)\n", on,
                                  on == 1 ? "" : "s");
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

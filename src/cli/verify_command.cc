#include "cli/verify_command.h"

#include <fmt/format.h>

#include <cerrno>
#include <cstdio>
#include <cstring>

#include "cli/post_file.h"
#include "simulator/control_sim.h"
#include "support/input_file.h"
#include "verify/hole_verify.h"
#include "verify/plan_json.h"
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

namespace {

bool plans_from_json(const std::string& path, const Machine& m, std::vector<ThreadPlan>& plans,
                     VerifyOutcome& out) {
  InputFile f;
  std::string error;
  if (!f.open(path, error)) {
    out.errors = 1;
    out.diagnostics = fmt::format("{}: error: {}\n", path, error);
    return false;
  }
  Diagnostics d(path);
  if (read_plan_json(f.read_all(), m, plans, d)) return true;
  out.errors = d.error_count();
  out.diagnostics = d.render_all();
  return false;
}

}  // namespace

VerifyOutcome verify_files(const std::string& program, const std::string& cl,
                           const std::string& plan_json, const Machine& m, double tolerance) {
  std::vector<ThreadPlan> plans;
  ClExpected expected;
  if (cl.empty()) {
    VerifyOutcome out;
    if (!plans_from_json(plan_json, m, plans, out)) return out;
  } else {
    PostOutcome posted = plans_of(cl, m, plans);
    expected.holes = std::move(posted.holes);
    expected.path = std::move(posted.path);
    if (!posted.ok) {
      VerifyOutcome out;
      out.errors = posted.errors;
      out.diagnostics = posted.diagnostics +
                        fmt::format("clpost: error: cannot verify against '{}': it has errors\n",
                                    display_name(cl));
      return out;
    }
  }
  InputFile f;
  std::string error;
  if (!f.open(program, error)) {
    VerifyOutcome out;
    out.errors = 1;
    out.diagnostics = fmt::format("{}: error: {}\n", program, error);
    return out;
  }
  reader::LineSource src(f.get());
  VerifyOutcome out =
      verify_program(src, display_name(program), plans, cl.empty() ? nullptr : &expected,
                     cl.empty() ? plan_json : display_name(cl), m, tolerance);
  // The CL file's own notes and warnings were shown when it was posted; verify is about the
  // program.
  return out;
}

}  // namespace clpost

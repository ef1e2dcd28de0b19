#include "cli/verify_command.h"

#include <fmt/format.h>

#include <cerrno>
#include <cstdio>
#include <cstring>

#include "cli/post_file.h"
#include "simulator/control_sim.h"
#include "verify/verify.h"

namespace clpost {

VerifyOutcome verify_program(reader::LineSource& src, const std::string& program_name,
                             const std::vector<ThreadPlan>& plans, const std::string& plan_name,
                             const Machine& m, double tolerance) {
  VerifyOutcome out;
  Diagnostics diags(program_name);
  Simulation sim;
  SimOptions so;
  so.keep_moves = false;
  if (simulate_nc(src, m, diags, sim, so)) {
    VerifyOptions vo;
    vo.tolerance = tolerance;
    vo.plan_name = plan_name;
    VerifyReport report;
    out.ok = verify_cuts(plans, sim, m, vo, diags, report);
    out.report = verify_report_text(report, plans, program_name, m, vo);
  } else {
    out.report =
        fmt::format("verify {}: the program cannot be read (see the errors)\n", program_name);
  }
  out.errors = diags.error_count();
  out.diagnostics = diags.render_all();
  return out;
}

VerifyOutcome verify_files(const std::string& program, const std::string& cl, const Machine& m,
                           double tolerance) {
  std::vector<ThreadPlan> plans;
  PostRequest req{cl, "", &m, PostOptions{}, [&](const ThreadPlan& p) { plans.push_back(p); }};
  PostOutcome posted = post_file(req);
  if (!posted.ok) {
    VerifyOutcome out;
    out.errors = posted.errors;
    out.diagnostics =
        posted.diagnostics +
        fmt::format("clpost: error: cannot verify against '{}': it has errors\n", display_name(cl));
    return out;
  }
  std::FILE* f = program == "-" ? stdin : std::fopen(program.c_str(), "rb");
  if (f == nullptr) {
    VerifyOutcome out;
    out.errors = 1;
    out.diagnostics = fmt::format("{}: error: cannot open: {}\n", program, std::strerror(errno));
    return out;
  }
  reader::LineSource src(f);
  VerifyOutcome out =
      verify_program(src, display_name(program), plans, display_name(cl), m, tolerance);
  // The CL file's own notes and warnings were shown when it was posted; verify is about the
  // program.
  if (f != stdin) std::fclose(f);
  return out;
}

}  // namespace clpost

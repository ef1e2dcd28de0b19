#include "cli/verify_command.h"

#include <fmt/format.h>

#include <cerrno>
#include <cstdio>
#include <cstring>

#include "cli/post_file.h"
#include "support/input_file.h"
#include "verify/plan_json.h"
#include "verify/program_verify.h"

namespace clpost {

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

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

// The program `program` could not be opened (`error`).
VerifyOutcome not_opened(const std::string& program, const std::string& error) {
  VerifyOutcome out;
  out.errors = 1;
  out.diagnostics = fmt::format("{}: error: {}\n", program, error);
  return out;
}

// `clpost verify --cl`: the CL posted into a ProgramStream (its motions and thread plans as
// they come, spilled beyond its window), then the program read into it a line at a time, as
// `clpost --verify` compares a program behind its header: memory does not grow with either.
VerifyOutcome verify_against_cl(const std::string& program, const std::string& cl, const Machine& m,
                                double tolerance) {
  ProgramStream stream(display_name(program), display_name(cl), m, tolerance);
  PostOptions options;
  options.keep_motions = true;  // verify compares them
  options.on_motion = [&stream](const ClMotion& c, const CutStateAt& state) {
    stream.cl_motion(c, state);
  };
  options.on_mill = [&stream](const MillSegment& g) { stream.mill_segment(g); };
  const PostRequest req{cl, "", &m, options, [&stream](const ThreadPlan& p) { stream.plan(p); }};
  const PostOutcome posted = post_file(req);
  if (!posted.ok) {
    VerifyOutcome out;
    out.errors = posted.errors;
    out.diagnostics =
        posted.diagnostics +
        fmt::format("clpost: error: cannot verify against '{}': it has errors\n", display_name(cl));
    return out;
  }
  InputFile f;
  std::string error;
  if (!f.open(program, error)) return not_opened(program, error);
  reader::LineSource src(f.get());
  stream.cl_ended();
  stream.program_lines(src);
  // The CL file's own notes and warnings were shown when it was posted; verify is about the
  // program.
  return stream.finish(posted.holes, posted.mill, posted.path.state_count);
}

}  // namespace

VerifyOutcome verify_files(const std::string& program, const std::string& cl,
                           const std::string& plan_json, const Machine& m, double tolerance) {
  if (!cl.empty()) return verify_against_cl(program, cl, m, tolerance);
  std::vector<ThreadPlan> plans;
  VerifyOutcome out;
  if (!plans_from_json(plan_json, m, plans, out)) return out;
  InputFile f;
  std::string error;
  if (!f.open(program, error)) return not_opened(program, error);
  reader::LineSource src(f.get());
  return verify_program(src, display_name(program), plans, nullptr, plan_json, m, tolerance);
}

}  // namespace clpost

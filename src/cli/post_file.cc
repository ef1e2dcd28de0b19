#include "cli/post_file.h"

#include <fmt/format.h>

#include <cerrno>
#include <cstdio>
#include <cstring>
#include <memory>

#include "cli/verify_command.h"
#include "reader/cl_reader.h"
#include "support/input_file.h"
#include "support/output_file.h"
#include "verify/program_verify.h"
#include "writer/nc_program.h"

namespace clpost {

namespace {
class NullSink : public Sink {
 public:
  size_t bytes = 0;

 private:
  void overflow(std::string_view text) override { bytes += text.size(); }
};
// Hands the program as it is written to --verify (`verify`), and keeps a copy when asked
// (`copy`, PostRequest::program).
class TeeSink : public Sink {
 public:
  TeeSink(Sink& to, std::string* copy, ProgramStream* verify)
      : to_(to), copy_(copy), verify_(verify) {}

 private:
  void overflow(std::string_view text) override {
    to_.write(text);
    if (copy_ != nullptr) copy_->append(text);
    if (verify_ != nullptr) verify_->program_text(text);
  }

  Sink& to_;
  std::string* copy_;
  ProgramStream* verify_;
};

// A file not posted: its input or its output could not be opened (the error is in `diags`).
PostOutcome not_opened(const Diagnostics& diags) {
  PostOutcome out;
  out.errors = diags.error_count();
  out.diagnostics = diags.render_all();
  out.kept = diags.kept();
  return out;
}

// Reads, interprets and writes the program to `sink`: what the post found goes into `out`.
// With --verify (`verify`), the CL's motions and thread plans go to it as they are posted.
void post_to(const PostRequest& req, std::FILE* input, Sink& sink, Diagnostics& diags,
             ProgramStream* verify, PostOutcome& out) {
  auto on_thread = [&](const ThreadPlan& p) {
    if (req.on_thread) req.on_thread(p);
    if (verify != nullptr) verify->plan(p);
  };
  ClReader reader(input, diags);
  PostOptions options = req.options;
  options.keep_motions = options.keep_motions || req.verify;
  // The body waits for its header beside the output file (same file system, no name), else in
  // the system's temporary directory.
  if (!req.output.empty()) options.spool_dir = OutputFile::directory_beside(req.output);
  if (verify != nullptr) {
    options.on_motion = [verify](const ClMotion& c, const CutStateAt& state) {
      verify->cl_motion(c, state);
    };
    options.on_mill = [verify](const MillSegment& g) { verify->mill_segment(g); };
  }
  PostSummary summary = post(reader, *req.machine, sink, diags, options, on_thread);
  if (verify != nullptr) verify->cl_ended();
  out.holes = std::move(summary.holes);
  out.mill = std::move(summary.mill);
  out.outputs = std::move(summary.outputs);
  out.partno = std::move(summary.partno);
  out.path = std::move(summary.path);
  out.cycle_time = std::move(summary.cycle_time);
  out.stats = summary.stats;
  out.units = summary.units;
  out.bytes_in = summary.bytes_in;
}

// --verify: the program as written, read back through the control and compared with the plans
// while it was written (`verify`), finished. The report goes into `out`, the program's
// diagnostics into `verify_diagnostics`. False when the program does not cut the plan (one
// error on the CL file says so).
bool verify_posted(ProgramStream& verify, Diagnostics& diags, PostOutcome& out,
                   std::string& verify_diagnostics) {
  VerifyOutcome v = verify.finish(out.holes, out.mill, out.path.state_count);
  out.verify_report = std::move(v.report);
  out.path = {};  // compared: a batch keeps every outcome
  verify_diagnostics = std::move(v.diagnostics);
  out.errors += v.errors;
  // One line on the CL file too (a batch shows each file's first error).
  if (!v.ok) diags.error({}, {}, "--verify: the program does not cut the plan: " + v.first_error);
  return v.ok;
}

// The written program: dropped when `failed`, else committed, or finished and handed to
// publish_later (a batch).
void finish_output(const PostRequest& req, std::unique_ptr<OutputFile>& file, bool failed,
                   Diagnostics& diags, PostOutcome& out) {
  if (failed) {
    file->abort();
    return;
  }
  std::string err;
  out.bytes_out = file->bytes();
  if (!req.publish_later) {
    if (!file->commit(err)) diags.error({}, {}, err);
  } else if (file->finish(err)) {
    req.publish_later(std::move(file));
  } else {
    diags.error({}, {}, err);
  }
}

}  // namespace

std::string display_name(const std::string& input) {
  return input == "-" ? "<stdin>" : input;
}

PostOutcome post_file(const PostRequest& req) {
  Diagnostics diags(display_name(req.input));
  InputFile input;
  std::string open_error;
  if (!input.open(req.input, open_error)) {
    diags.error({}, {}, open_error);
    return not_opened(diags);
  }
  auto file = std::make_unique<OutputFile>();
  NullSink null_sink;
  Sink* sink = &null_sink;
  bool writing = !req.output.empty();
  if (writing) {
    std::string err;
    if (!file->open(req.output, err)) {
      diags.error({}, {}, err);
      return not_opened(diags);
    }
    sink = file.get();
  }
  PostOutcome out;
  std::unique_ptr<ProgramStream> verify;
  if (req.verify)
    verify = std::make_unique<ProgramStream>(
        req.output.empty() || req.output == "-" ? "<program>" : req.output, display_name(req.input),
        *req.machine, req.verify_tolerance);
  TeeSink tee(*sink, req.program, verify.get());
  if (req.verify || req.program != nullptr) sink = &tee;
  if (req.program_sink != nullptr && !req.verify && req.program == nullptr && !writing)
    sink = req.program_sink;
  post_to(req, input.get(), *sink, diags, verify.get(), out);
  std::string verify_diagnostics;
  const bool verify_failed =
      req.verify && !diags.has_errors() && !verify_posted(*verify, diags, out, verify_diagnostics);
  if (writing) {
    finish_output(req, file, diags.has_errors() || verify_failed, diags, out);
  } else {
    out.bytes_out = null_sink.bytes;
  }
  out.errors += diags.error_count();
  out.warnings = diags.warning_count();
  out.ok = !diags.has_errors() && !verify_failed;
  out.diagnostics = diags.render_all() + verify_diagnostics;
  out.kept = diags.kept();
  return out;
}

PostOutcome plans_of(const std::string& cl, const Machine& m, std::vector<ThreadPlan>& plans,
                     std::string* program) {
  PostOptions options;
  options.keep_motions = true;  // verify compares them
  PostRequest req{cl, "", &m, options, [&](const ThreadPlan& p) { plans.push_back(p); }};
  req.program = program;
  return post_file(req);
}

}  // namespace clpost

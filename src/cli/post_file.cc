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
#include "writer/nc_program.h"

namespace clpost {

namespace {
class NullSink : public Sink {
 public:
  size_t bytes = 0;

 private:
  void overflow(std::string_view text) override { bytes += text.size(); }
};
// Keeps a copy of the program for --verify.
class TeeSink : public Sink {
 public:
  TeeSink(Sink& to, std::string& copy) : to_(to), copy_(copy) {}

 private:
  void overflow(std::string_view text) override {
    to_.write(text);
    copy_.append(text);
  }

  Sink& to_;
  std::string& copy_;
};
}  // namespace

std::string display_name(const std::string& input) {
  return input == "-" ? "<stdin>" : input;
}

PostOutcome post_file(const PostRequest& req) {
  PostOutcome out;
  Diagnostics diags(display_name(req.input));
  InputFile input;
  std::string open_error;
  if (!input.open(req.input, open_error)) {
    diags.error({}, {}, open_error);
    out.errors = 1;
    out.diagnostics = diags.render_all();
    out.kept = diags.kept();
    return out;
  }
  auto file = std::make_unique<OutputFile>();
  NullSink null_sink;
  Sink* sink = &null_sink;
  bool writing = !req.output.empty();
  if (writing) {
    std::string err;
    if (!file->open(req.output, err)) {
      diags.error({}, {}, err);
      out.errors = diags.error_count();
      out.diagnostics = diags.render_all();
      out.kept = diags.kept();
      return out;
    }
    sink = file.get();
  }
  std::string own_copy;  // --verify: the program as written
  std::string& program = req.program != nullptr ? *req.program : own_copy;
  std::vector<ThreadPlan> plans;
  TeeSink tee(*sink, program);
  if (req.verify || req.program != nullptr) sink = &tee;
  {
    auto on_thread = [&](const ThreadPlan& p) {
      if (req.on_thread) req.on_thread(p);
      if (req.verify) plans.push_back(p);
    };
    ClReader reader(input.get(), diags);
    PostOptions options = req.options;
    options.keep_motions = options.keep_motions || req.verify;
    PostSummary summary = post(reader, *req.machine, *sink, diags, options, on_thread);
    out.holes = std::move(summary.holes);
    out.path = std::move(summary.path);
    out.cycle_time = std::move(summary.cycle_time);
    out.stats = summary.stats;
    out.units = summary.units;
    out.bytes_in = summary.bytes_in;
  }
  std::string verify_diagnostics;
  bool verify_failed = false;
  if (req.verify && !diags.has_errors()) {
    reader::LineSource src{std::string_view(program)};
    const std::string name = req.output.empty() || req.output == "-" ? "<program>" : req.output;
    const ClExpected expected{out.holes, out.path};
    VerifyOutcome v = verify_program(src, name, plans, &expected, display_name(req.input),
                                     *req.machine, req.verify_tolerance);
    out.verify_report = std::move(v.report);
    out.path = {};  // compared: a batch keeps every outcome
    verify_diagnostics = std::move(v.diagnostics);
    verify_failed = !v.ok;
    out.errors += v.errors;
    // One line on the CL file too (a batch shows each file's first error).
    if (verify_failed)
      diags.error({}, {}, "--verify: the program does not cut the plan: " + v.first_error);
  }
  if (writing) {
    if (diags.has_errors() || verify_failed) {
      file->abort();
    } else {
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

#include "verify/program_verify.h"

#include <fmt/format.h>

#include <algorithm>

#include "simulator/control_sim.h"
#include "verify/hole_verify.h"
#include "verify/mill_verify.h"
#include "verify/verify.h"

namespace clpost {

namespace {

// The errors of the comparison with block delete on (`on`) that the run with block delete off
// has not: into `diags`, marked; the count of those.
size_t keep_block_delete(const Diagnostics& on, Diagnostics& diags) {
  size_t added = 0;
  const std::vector<Diagnostic> off = diags.kept();
  for (const Diagnostic& e : on.kept()) {
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
  return pr.problems == 0 ? 0 : keep_block_delete(d, diags);
}

// A program with optional blocks ('/') where its CL has no OPSKIP range: the CL says to do
// every block, whether block delete is on or off. An error at the first one.
void optional_without_opskip(const Simulation& sim, Diagnostics& diags, VerifyOutcome& out) {
  if (sim.deleted_blocks == 0) return;
  diags.error(SourceLoc{sim.first_optional.first, 1}, sim.first_optional.second,
              "an optional block ('/'), where the CL has no OPSKIP range");
  out.ok = false;
}

// The report's line for differences found only with block delete on.
void report_block_delete(size_t on, VerifyOutcome& out) {
  if (on == 0) return;
  out.ok = false;
  out.report +=
      fmt::format("block delete on: {} difference{} (see the errors)\n", on, on == 1 ? "" : "s");
}

// The program, read: its thread cuts against the plans by `threads(report)` (true: as
// planned); with `holes` (the CL's), its holes, its milling by `mill()`, then its path by
// `path()` (its problems last).
template <typename Threads, typename Mill, typename Path>
void compare(const Simulation& sim, const std::vector<Hole>* holes, const Machine& m,
             const VerifyOptions& vo, Diagnostics& diags, VerifyOutcome& out, Threads&& threads,
             Mill&& mill, Path&& path) {
  out.ok = threads(out.report);
  if (holes != nullptr) {
    const HoleReport hr = verify_holes(*holes, sim.holes, m, vo, diags);
    const MillReport mr = mill();
    const PathReport pr = path();
    out.ok = out.ok && hr.problems == 0 && mr.problems == 0 && pr.problems == 0;
    out.report += hr.text + mr.text + pr.text;
  }
}

void cannot_read(const std::string& program_name, VerifyOutcome& out) {
  out.report =
      fmt::format("verify {}: the program cannot be read (see the errors)\n", program_name);
}

// The diagnostics into `out`: counted, rendered, the first error for one-line summaries.
void diagnose(const Diagnostics& diags, const std::string& program_name, VerifyOutcome& out) {
  out.errors = diags.error_count();
  out.diagnostics = diags.render_all();
  for (const Diagnostic& d : diags.kept())
    if (d.severity == Severity::kError) {
      out.first_error = fmt::format("{}:{}: {}", program_name, d.loc.line, d.message);
      break;
    }
}

VerifyOptions verify_options(const std::string& plan_name, double tolerance) {
  VerifyOptions vo;
  vo.tolerance = tolerance;
  vo.plan_name = plan_name;
  return vo;
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
    const VerifyOptions vo = verify_options(plan_name, tolerance);
    const auto threads = [&](std::string& text) {
      VerifyReport report;
      const bool ok = verify_cuts(plans, sim, m, vo, diags, report);
      text = verify_report_text(report, plans, program_name, m, vo);
      return ok;
    };
    compare(
        sim, cl ? &cl->holes : nullptr, m, vo, diags, out, threads,
        [&] { return verify_milling(cl->mill, sim.mill_moves, sim.mill_move_count, m, vo, diags); },
        [&] { return verify_path(cl->path, sim.path, m, vo, diags); });
    if (cl != nullptr && std::none_of(cl->path.motions.begin(), cl->path.motions.end(),
                                      [](const ClMotion& c) { return c.optional; }))
      optional_without_opskip(sim, diags, out);
    if (cl != nullptr) {
      size_t on = 0;
      for (const Simulation& s : sim.with_block_delete)
        on += verify_block_delete(cl->path, s, m, vo, diags);
      report_block_delete(on, out);
    }
  } else {
    cannot_read(program_name, out);
  }
  diagnose(diags, program_name, out);
  return out;
}

ProgramStream::ProgramStream(const std::string& program_name, const std::string& plan_name,
                             const Machine& m, double tolerance)
    : name_(program_name),
      m_(m),
      vo_(verify_options(plan_name, tolerance)),
      diags_(program_name),
      sim_(m, diags_, out_, options()),
      path_(m, vo_, sim_.readback(), out_.units, kWindow),
      path_on_(m, vo_, sim_.readback(), sim_.block_delete_units(), kWindow),
      threads_(m, vo_),
      mill_(m, vo_) {}

ProgramStream::~ProgramStream() = default;

const SimOptions& ProgramStream::options() {
  so_.keep_moves = false;
  so_.on_move = [this](const Move& mv, const CutState& state) { path_.program_move(mv, &state); };
  so_.block_delete_too = true;
  so_.on_block_delete_move = [this](const Move& mv, const CutState& state) {
    if (!on_follows_) path_on_.program_move(mv, &state);
  };
  so_.on_first_optional = [this] { part_on(); };
  so_.on_mill_move = [this](const SimMillMove& mv) { mill_.program_move(mv); };
  return so_;
}

void ProgramStream::part_on() {
  if (!on_follows_) return;
  on_follows_ = false;
  path_on_.take_over(path_);
}

void ProgramStream::program_text(std::string_view text) {
  read_lines(text);
  threads_.poll(out_.cuts);
}

namespace {

// Where the first line of `text` ends ("\n" or "\r"), or npos: a plain loop, since
// find_first_of calls memchr on its set for every character.
size_t line_end(std::string_view text) {
  for (size_t i = 0; i < text.size(); ++i)
    if (text[i] == '\n' || text[i] == '\r') return i;
  return std::string_view::npos;
}

}  // namespace

void ProgramStream::read_lines(std::string_view text) {
  // Lines end at "\n", "\r" or "\r\n", as reader::LineSource reads them. Text without a "\r"
  // (a search of the whole chunk at once) is cut at its "\n"s by memchr.
  const bool cr = text.find('\r') != std::string_view::npos;
  while (!text.empty()) {
    if (after_cr_ && text.front() == '\n') text.remove_prefix(1);
    after_cr_ = false;
    const size_t end = cr ? line_end(text) : text.find('\n');
    if (end == std::string_view::npos) {
      partial_.append(text);
      return;
    }
    after_cr_ = text[end] == '\r';
    if (partial_.empty()) {
      line(++number_, text.substr(0, end));
    } else {
      partial_.append(text.substr(0, end));
      line(++number_, partial_);
      partial_.clear();
    }
    text.remove_prefix(end + 1);
  }
}

void ProgramStream::line(uint32_t number, std::string_view text) {
  // Behind a header the whole CL is posted before the program's first line: without an OPSKIP
  // range in it, the run with block delete on is not needed.
  if (number == 1 && writes_program_header(m_) && !optional_motions_) sim_.no_optional_blocks();
  if (!stopped_) stopped_ = !sim_.line(number, text);
}

void ProgramStream::program_lines(reader::LineSource& src) {
  const bool read = read_nc_lines(
      src, diags_,
      [this](uint32_t number, std::string_view text) {
        line(number, text);
        threads_.poll(out_.cuts);
        return !stopped_;
      },
      [this] { sim_.unreadable(); });
  stopped_ = stopped_ || !read;
}

void ProgramStream::cl_motion(const ClMotion& c, const CutStateAt& state) {
  ++motions_;
  optional_motions_ = optional_motions_ || c.optional;
  if (c.optional) part_on();
  path_.cl_motion(c, &state);
  if (!c.optional && !on_follows_) path_on_.cl_motion(c, &state);
}

void ProgramStream::mill_segment(const MillSegment& g) {
  mill_.cl_segment(g);
}

void ProgramStream::cl_ended() {
  mill_.cl_ended();
}

void ProgramStream::plan(const ThreadPlan& p) {
  threads_.plan(p, out_.cuts);
}

VerifyOutcome ProgramStream::finish(const std::vector<Hole>& holes,
                                    const std::vector<MillSegment>& mill, size_t cl_states) {
  if (!partial_.empty()) line(++number_, partial_);
  VerifyOutcome out;
  if (!stopped_ && sim_.finish()) {
    for (const MillSegment& g : mill) mill_.cl_segment(g);
    compare(
        out_, &holes, m_, vo_, diags_, out,
        [&](std::string& text) { return threads_.finish(out_.cuts, name_, diags_, text); },
        [&] { return mill_.finish(out_.mill_move_count, diags_); },
        [&] { return motions_ == 0 ? PathReport{} : path_.finish(cl_states, diags_); });
    if (motions_ > 0 && !optional_motions_) optional_without_opskip(out_, diags_, out);
    if (motions_ > 0 && !out_.with_block_delete.empty()) {
      Diagnostics on(name_);
      if (path_on_.finish(cl_states, on).problems > 0)
        report_block_delete(keep_block_delete(on, diags_), out);
    }
  } else {
    cannot_read(name_, out);
  }
  diagnose(diags_, name_, out);
  return out;
}

}  // namespace clpost

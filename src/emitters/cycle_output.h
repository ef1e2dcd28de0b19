#pragma once
// "Exact or fall back" (controllers.md), one interface for every family of cycles: a thread
// (emitter.h), a hole (hole_output.h), an undercut (undercut_output.h), and mill-turn's cycles
// next. A job is written by the first of its machine's outputs that cuts exactly what the CL says
// — a control's cycle when its law, after our rounding, gives the CL's cuts; a generic output
// (moves) otherwise — and a comment in the program says why the first was not used.
#include <span>
#include <string>
#include <string_view>
#include <vector>

#include "machine/machine.h"
#include "reader/statement.h"
#include "support/diagnostics.h"
#include "writer/nc_program.h"

namespace clpost {

// An output that was not used, and why.
struct Unfit {
  std::string name;
  std::string reason;
  SourceLoc where;
};

// Which output wrote a job (at `loc`, its CL statement), and the ones tried before it: what the
// program's fallback comment says, as data (clpost sheet).
struct OutputUsed {
  SourceLoc loc;
  std::string name;                // "G76", "moves", …
  std::vector<Unfit> unfit;        // tried first, did not cut the job exactly
  std::vector<std::string> notes;  // accepted differences
};

struct EmitContext {
  Diagnostics& diags;
  const SavedLines& lines;  // the job's CL statement, for diagnostics
  double rpm = 0;           // spindle speed during the job
  double feed = 0;          // feed in force (for linear pull-outs), output units
  FeedMode feed_mode = FeedMode::kPerMinute;
  SourceLoc loc = {};  // where the diagnostics point (a thread's: its plan's loc)
  std::vector<OutputUsed>* used = nullptr;  // when set, gets the output each job is written by
};

// Whether an output cuts a job exactly: a cycle is written only when what the control will cut
// from the words we would write — its own law, its rounding — is what the CL says.
struct Fit {
  std::string mismatch;            // empty: exact; else why not, one line with the numbers
  std::vector<std::string> notes;  // accepted differences, written as NC comments before it
  SourceLoc where;                 // the CL word the mismatch is about (0: the job's statement)
  bool exact() const { return mismatch.empty(); }
};

template <class Job>
class CycleOutput {
 public:
  virtual ~CycleOutput() = default;
  // What the NC comments and diagnostics call it: "CYCLE99", "G76", "moves", ...
  virtual std::string_view name() const = 0;
  // Would this output cut `job` exactly on machine `m`?
  virtual Fit fit(const Job& job, const Machine& m) const = 0;
  // Writes a job that fits. Returns false (with a diagnostic) when it cannot.
  virtual bool emit(const Job& job, NcProgram& prog, const EmitContext& ctx) = 0;
};

// "G76 not used: <why>. G92 instead".
std::string fallback_comment(const Unfit& first, std::string_view used);
// Every unfit output's reason, outputs with one reason named together: "A, B not used: why; C
// not used: other".
std::string unfit_reasons(const std::vector<Unfit>& unfit);

// The first output of `order` that fits `job` on `m` (its fit in `fit`), or null; `unfit` gets
// the outputs tried before it. With `stop_at_unfit` the search ends at the first that does not
// fit (a machine whose fallback is an error).
template <class Job>
CycleOutput<Job>* first_exact(std::span<CycleOutput<Job>* const> order, const Job& job,
                              const Machine& m, bool stop_at_unfit, Fit& fit,
                              std::vector<Unfit>& unfit) {
  for (CycleOutput<Job>* o : order) {
    fit = o->fit(job, m);
    if (fit.exact()) return o;
    unfit.push_back({std::string(o->name()), fit.mismatch, fit.where});
    if (stop_at_unfit) return nullptr;
  }
  return nullptr;
}

// Writes `job` with `used` after the comments a fallback owes the reader: "<first> not used:
// <why>. <used> instead" when an output before it did not fit, and the fit's accepted
// differences.
template <class Job>
bool emit_after_fallback(CycleOutput<Job>& used, const Fit& fit, const std::vector<Unfit>& unfit,
                         const Job& job, NcProgram& prog, const EmitContext& ctx) {
  if (!unfit.empty()) prog.comment(fallback_comment(unfit.front(), used.name()));
  for (const std::string& n : fit.notes) prog.comment(n);
  if (ctx.used) ctx.used->push_back({ctx.loc, std::string(used.name()), unfit, fit.notes});
  return used.emit(job, prog, ctx);
}

}  // namespace clpost

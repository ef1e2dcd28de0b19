#pragma once
// The interpreter: CL statements in, NC program out. It keeps the CL's modal state (PostState),
// hands each statement to its handler by major word (statement_table.h), and says how the input
// ends. One Interpreter per file; no shared state. post() (post.h) drives it from a reader.
#include <functional>
#include <memory>

#include "interpreter/post_state.h"
#include "machine/machine.h"
#include "planner/thread_plan.h"
#include "reader/statement.h"
#include "support/diagnostics.h"
#include "writer/nc_program.h"

namespace clpost {

class Interpreter {
 public:
  Interpreter(const Machine& m, NcProgram& prog, Diagnostics& diags, const PostOptions& opts);
  ~Interpreter();

  void statement(const Statement& st);
  // End of input: closes the program and reports unterminated sequences.
  void finish();
  // The input is exhausted: like finish(), with a warning when FINI was missing.
  void end_of_input(uint32_t last_line);

  // Called with every thread plan (clpost plan).
  void on_thread(std::function<void(const ThreadPlan&)> cb) { state_->on_thread = std::move(cb); }
  const PostStats& stats() const { return state_->stats; }
  LengthUnit units() const { return state_->units; }
  // The holes written (CYCLE/DRILL …), for verify; moved out.
  std::vector<Hole> take_holes() { return std::move(state_->holes); }
  // The milling written (milling_motion.cc), for verify; moved out.
  std::vector<MillSegment> take_mill();
  std::vector<OutputUsed> take_outputs() { return std::move(state_->outputs); }
  const std::string& partno() const;
  const CycleTime& cycle_time() const { return state_->clock; }
  // With PostOptions::on_motion, the last motion is handed over first.
  ClPath take_path();

 private:
  std::unique_ptr<PostState> state_;
};

}  // namespace clpost

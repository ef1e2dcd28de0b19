#pragma once
// One interface for every threading output style: plain G1/G33 emulation, G33 loops, and the
// controls' cycles (CYCLE99, G76, G92, G31 …). The machine file picks the implementation.
#include <memory>
#include <string_view>

#include "machine/machine.h"
#include "planner/thread_plan.h"
#include "reader/statement.h"
#include "support/diagnostics.h"
#include "writer/nc_program.h"

namespace clpost {

struct EmitContext {
  Diagnostics& diags;
  const SavedLines& lines;  // the thread's CL statement, for diagnostics
  double rpm = 0;           // spindle speed during the thread
  double feed = 0;          // feed in force (for linear pull-outs), output units
  FeedMode feed_mode = FeedMode::kPerMinute;
};

class Emitter {
 public:
  virtual ~Emitter() = default;
  virtual std::string_view name() const = 0;
  // Writes a multi-pass thread. Returns false (with a diagnostic) when it cannot.
  virtual bool emit(const ThreadPlan& plan, NcProgram& prog, const EmitContext& ctx) = 0;
};

std::unique_ptr<Emitter> make_emitter(const Machine& m);

}  // namespace clpost

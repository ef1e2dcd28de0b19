#pragma once
// Test helpers for the cycle emitters: a pass plan from one THREAD/ON line and its GOTOs (through
// the planner, with the machine's defaults), and what an emitter writes for it.
#include <gtest/gtest.h>

#include <memory>
#include <string>
#include <vector>

#include "emitters/emitter.h"
#include "emitters/planner_settings.h"
#include "machine/machine_loader.h"
#include "machine/machine_test_util.h"
#include "planner/planner_test_util.h"
#include "support/sink.h"

namespace clpost::testing {

inline Machine shipped_machine(const std::string& name, std::vector<std::string> sets = {}) {
  Machine m;
  std::string errors;
  EXPECT_TRUE(load_machine(name, {CLPOST_SOURCE_DIR}, sets, shipped_controls(), m, errors))
      << errors;
  return m;
}

// THREAD/ON `on` (line 2) with the tool at `p0` and the GOTOs `gotos`, planned for `m`. The
// approach is fed (the CL had a feed in force), as in the shipped samples; the spindle turns at
// `rpm` (0: not known, no run-in or run-out).
inline ThreadPlan plan_for(const Machine& m, const std::string& on, Vec2 p0,
                           const std::vector<Vec2>& gotos, bool feed_approach = true,
                           LengthUnit units = LengthUnit::kMm, double rpm = 0) {
  TestStatement st(on, 2);
  Diagnostics d("t.cl");
  MultiCase c = make_multi(st, units, p0, gotos, d);
  EXPECT_TRUE(c.parsed) << d.render_all();
  c.in.feed_approach = feed_approach;
  c.in.rpm = rpm;
  PlannerSettings s = planner_settings(m);
  ThreadPlan plan;
  const bool ok = c.in.words.chain.set ? plan_chain_thread(c.in, s, plan, d)
                                       : plan_multi_thread(c.in, s, plan, d);
  EXPECT_TRUE(ok) << d.render_all();
  plan.loc = {2, 1};
  return plan;
}

struct Emitted {
  bool ok = false;
  std::string nc;
  std::string diags;
};

// What `e` writes for `plan` (the thread statement is "THREAD/ON..." at line 2).
inline Emitted emit_with(Emitter& e, const Machine& m, const ThreadPlan& plan) {
  Emitted out;
  StringSink sink;
  NcProgram prog(m, sink);
  prog.set_feed(0.2, FeedMode::kPerRev);  // FEDRAT/0.2,MMPR before the thread
  Diagnostics d("t.cl");
  SavedLines lines;
  lines.first_line = 2;
  lines.lines.push_back("THREAD/ON");
  EmitContext ctx{d, lines, 500, 0.2, FeedMode::kPerRev};
  out.ok = e.emit(plan, prog, ctx);
  out.nc = sink.out;
  out.diags = d.render_all();
  return out;
}

// What the machine's thread output (strategy, fallback) writes for `plan`.
inline Emitted emit_on(const Machine& m, const ThreadPlan& plan) {
  std::unique_ptr<Emitter> e = make_emitter(m);
  return emit_with(*e, m, plan);
}

}  // namespace clpost::testing

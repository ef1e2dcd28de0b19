#pragma once
// Test helpers for the Fanuc / Haas emitters: a machine loaded from machines/, a thread planned
// from one THREAD/ON line, and what make_emitter(m) writes for it.
#include <gtest/gtest.h>

#include <string>
#include <vector>

#include "controls/registry.h"
#include "emitters/emitter.h"
#include "emitters/planner_settings.h"
#include "machine/machine_loader.h"
#include "planner/planner_test_util.h"

namespace clpost::testing {

inline Machine load(const std::string& name, std::vector<std::string> sets = {}) {
  Machine m;
  std::string errors;
  sets.push_back("block_numbers.enabled=false");
  EXPECT_TRUE(load_machine(name, {CLPOST_SOURCE_DIR}, sets, shipped_controls(), m, errors))
      << errors;
  return m;
}

struct Threaded {
  std::string nc;     // the thread's blocks (the tool starts at P0, known to the program)
  std::string diags;  // rendered diagnostics
  bool ok = false;    // emit() returned true
  ThreadPlan plan;
};

// `on` is the THREAD/ON line (line 2 of the CL); P0 then the GOTOs.
inline Threaded thread_on(const Machine& m, const std::string& on, Vec2 p0,
                          const std::vector<Vec2>& gotos, LengthUnit units = LengthUnit::kMm) {
  Threaded t;
  Diagnostics d("t.cl");
  TestStatement st(on, 2);
  MultiCase c = make_multi(st, units, p0, gotos, d);
  EXPECT_TRUE(c.parsed) << d.render_all();
  PlannerSettings ps = planner_settings(m);
  EXPECT_TRUE(plan_multi_thread(c.in, ps, t.plan, d)) << d.render_all();
  StringSink sink;
  NcProgram prog(m, sink);
  prog.cycle_ended_at(LathePoint{p0.x, p0.z});
  SavedLines lines = st.saved();
  EmitContext ctx{d, lines, 800, 0.2, FeedMode::kPerRev};
  t.ok = make_emitter(m)->emit(t.plan, prog, ctx);
  t.nc = sink.out;
  t.diags = d.render_all();
  return t;
}

}  // namespace clpost::testing

// Issue 14: a cycle template that cannot be written stops the thread with an error at its CL
// statement naming the machine and the template, never a thread left out. One case per cycle
// template, on every shipped machine that has the template: the machine's line is replaced by one
// fmt cannot write ('d' is not for text; the loader refuses it, so this can only come from a
// Machine built in code).
#include <fmt/format.h>
#include <gtest/gtest.h>

#include <functional>

#include "controls/fanuc/fanuc_emitter.h"
#include "controls/haas/haas_emitter.h"
#include "controls/heidenhain/heidenhain_emitter.h"
#include "controls/linuxcnc/linuxcnc_emitter.h"
#include "controls/sinumerik/cycle98_emitter.h"
#include "controls/sinumerik/cycle99_emitter.h"
#include "emitters/emitter_test_util.h"
#include "machine/machine_test_util.h"

namespace clpost {
namespace {

using testing::emit_with;
using testing::plan_for;
using testing::shipped_machine;

struct Case {
  const char* tmpl;
  std::function<std::unique_ptr<Emitter>()> emitter;
  const char* on;
  const char* field;  // one the template declares
};

const Case kCases[] = {
    {"fanuc_g76", [] { return std::make_unique<FanucG76Emitter>(); },
     "THREAD/ON,MMPR,1.5,DEPTH,0.92,CUTS,6,OPTION,1", "x"},
    {"g92", [] { return std::make_unique<G92Emitter>(); },
     "THREAD/ON,MMPR,1.5,DEPTH,0.92,CUTS,4,OPTION,3", "x"},
    {"g92_next", [] { return std::make_unique<G92Emitter>(); },
     "THREAD/ON,MMPR,1.5,DEPTH,0.92,CUTS,4,OPTION,0", "x"},
    {"haas_g76", [] { return std::make_unique<HaasG76Emitter>(); },
     "THREAD/ON,MMPR,1.5,DEPTH,0.92,CUTS,6,OPTION,1", "x"},
    {"linuxcnc_g76", [] { return std::make_unique<LinuxcncG76Emitter>(); },
     "THREAD/ON,MMPR,1.5,DEPTH,0.92,CUTS,4,OPTION,1,FINCUT,1", "z"},
    {"linuxcnc_g76_taper", [] { return std::make_unique<LinuxcncG76Emitter>(); },
     "THREAD/ON,MMPR,1.5,DEPTH,0.92,CUTS,5,OPTION,1,CHAMFR,0.92", "z"},
    {"heidenhain_g31", [] { return std::make_unique<HeidenhainG31Emitter>(); },
     "THREAD/ON,MMPR,1.5,DEPTH,0.92,CUTS,5,OPTION,1,FINCUT,2", "x1"},
    {"cycle99", [] { return std::make_unique<Cycle99Emitter>(); },
     "THREAD/ON,MMPR,1.5,DEPTH,0.92,CUTS,4,OPTION,1", "spl"},
    {"cycle98", [] { return std::make_unique<Cycle98Emitter>(); },
     "THREAD/ON,MMPR,1.5,DEPTH,0.92,CUTS,4,OPTION,1,CHAIN", "po1"},
};

TEST(TemplateFailure, EveryCycleTemplateThatCannotBeWrittenIsAnErrorAtTheThread) {
  std::vector<Machine> machines;
  for (const std::string& name : testing::shipped_machine_names())
    machines.push_back(shipped_machine(name, {"block_numbers.enabled=false"}));
  for (const Case& c : kCases) {
    int tested = 0;
    for (Machine m : machines) {
      if (m.templates.count(c.tmpl) == 0) continue;
      SCOPED_TRACE(m.name);
      ++tested;
      const ThreadPlan plan = plan_for(m, c.on, {10, 5}, {{8, 2}, {8, -20}});
      std::unique_ptr<Emitter> e = c.emitter();
      // The template as shipped writes the thread ...
      testing::Emitted good = emit_with(*e, m, plan);
      ASSERT_TRUE(good.ok) << c.tmpl << "\n" << good.diags;
      // ... and this case reaches it.
      m.templates[c.tmpl] = {fmt::format("X{{{}:d}}", c.field)};
      testing::Emitted bad = emit_with(*e, m, plan);
      EXPECT_FALSE(bad.ok) << c.tmpl << "\n" << bad.nc;
      EXPECT_EQ(bad.diags, fmt::format("t.cl:2:1: error: machine '{}': template '{}' cannot be "
                                       "written: invalid type specifier\n"
                                       "  THREAD/ON\n"
                                       "  ^\n",
                                       m.name, c.tmpl));
    }
    EXPECT_GT(tested, 0) << "no shipped machine has template " << c.tmpl;
  }
}

}  // namespace
}  // namespace clpost

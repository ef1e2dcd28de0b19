// libFuzzer target: arbitrary bytes as an NC program, through the NC lexer and the control
// simulation of every shipped machine's dialect (cycles expanded with their laws), then verified
// against a fixed plan (an M16x1.5 thread posted on that machine) and its CL path (end points,
// tool, feed and spindle), as `clpost verify --cl` does.
#include <cstddef>
#include <cstdint>
#include <memory>
#include <vector>

#include "fuzz_post.h"
#include "simulator/control_sim.h"
#include "verify/path_verify.h"
#include "verify/verify.h"

namespace {

constexpr const char* kPlan =
    "UNITS/MM\nLOADTL/1\nSPINDL/600,RPM,CLW\nFEDRAT/0.2,MMPR\nRAPID\nGOTO/10,0,5\n"
    "THREAD/ON,MMPR,1.5,DEPTH,0.92,CUTS,6,OPTION,1\nGOTO/8,0,2\nGOTO/8,0,-20\nTHREAD/OFF\n"
    "RAPID\nGOTO/10,0,5\nFINI\n";

struct Target {
  clpost::Machine machine;
  std::vector<clpost::ThreadPlan> plans;
  clpost::ClPath path;
};
std::vector<std::unique_ptr<Target>>* g_targets = nullptr;

}  // namespace

extern "C" int LLVMFuzzerInitialize(int*, char***) {
  g_targets = new std::vector<std::unique_ptr<Target>>();
  for (clpost::Machine& m : clpost::fuzz::shipped_machines()) {
    auto t = std::make_unique<Target>();
    t->machine = std::move(m);
    clpost::PostOptions opts;
    opts.keep_motions = true;
    clpost::PostedText posted = clpost::post_text(kPlan, t->machine, "plan.cl", opts);
    t->plans = std::move(posted.plans);
    t->path = std::move(posted.summary.path);
    g_targets->push_back(std::move(t));
  }
  return 0;
}

extern "C" int LLVMFuzzerTestOneInput(const uint8_t* data, size_t size) {
  using namespace clpost;
  const std::string_view text(reinterpret_cast<const char*>(data), size);
  // The first byte picks the shipped machine (the text still starts at byte 0).
  const Target& t = *(*g_targets)[size > 0 ? data[0] % g_targets->size() : 0];
  Diagnostics diags("fuzz.nc");
  reader::LineSource src(text);
  Simulation sim;
  if (simulate_nc(src, t.machine, diags, sim)) {
    VerifyOptions vo;
    vo.plan_name = "plan.cl";
    VerifyReport report;
    verify_cuts(t.plans, sim, t.machine, vo, diags, report);
    (void)verify_report_text(report, t.plans, "fuzz.nc", t.machine, vo);
    (void)verify_path(t.path, sim.path, t.machine, vo, diags);
  }
  (void)diags.render_all();
  return 0;
}

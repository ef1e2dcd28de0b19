// SINUMERIK: CYCLE99 threads, CYCLE98 chains, CYCLE96 undercuts (cycle9*_emitter.h, their laws)
// and their read-back.
#include "controls/control.h"
#include "controls/sinumerik/cycle96_emitter.h"
#include "controls/sinumerik/cycle98_emitter.h"
#include "controls/sinumerik/cycle99_emitter.h"
#include "controls/sinumerik/sinumerik_readback.h"
#include "controls/sinumerik/sinumerik_templates.h"

namespace clpost {

extern const Control kSinumerikControl{
    .name = "sinumerik",
    .cycle = "cycle99",
    .cycle_emitter = []() -> std::unique_ptr<Emitter> {
      return std::make_unique<Cycle99Emitter>();
    },
    .chain_emitter = [](const Machine& m) -> std::unique_ptr<Emitter> {
      if (!m.templates.count(std::string(tmpl::kCycle98.name))) return nullptr;
      return std::make_unique<Cycle98Emitter>();
    },
    .undercut_cycle = [](const Machine& m) -> std::unique_ptr<CycleOutput<Undercut>> {
      if (!m.templates.count(std::string(tmpl::kCycle96.name))) return nullptr;
      return std::make_unique<Cycle96Emitter>();
    },
    .readback = &sim::kSinumerikReadback};

}  // namespace clpost

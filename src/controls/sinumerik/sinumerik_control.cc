// SINUMERIK: CYCLE99 threads, CYCLE98 chains, CYCLE96 undercuts (cycle9*_emitter.h, their laws)
// and their read-back.
#include "controls/control.h"
#include "controls/sinumerik/cycle96_emitter.h"
#include "controls/sinumerik/cycle98_emitter.h"
#include "controls/sinumerik/cycle99_emitter.h"
#include "controls/sinumerik/sinumerik_readback.h"
#include "controls/sinumerik/sinumerik_templates.h"

namespace clpost {

namespace {

// SINUMERIK 840D sl Programming Manual Fundamentals: G70/G71 inch/metric, G33 thread cutting,
// G34/G35 increasing/decreasing lead, G94/G95 feed per minute / per revolution.
constexpr FixedCode kSinumerikCodes[] = {
    {"metric", "G71", "selects millimetres"},
    {"inch", "G70", "selects inches"},
    {"thread", "G33", "is a thread cut"},
    {"thread_increasing", "G34", "is a thread with increasing lead"},
    {"thread_decreasing", "G35", "is a thread with decreasing lead"},
    {"feed_per_min", "G94", "is feed per minute"},
    {"feed_per_rev", "G95", "is feed per revolution"},
};

}  // namespace

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
    .readback = &sim::kSinumerikReadback,
    .fixed_codes = kSinumerikCodes,
    // 0.0001 in in an inch program (G70/G700): issue 24; no public SINUMERIK source found
    // (docs/cl-meaning.md, inch output).
    .inch_length_increment = 0.0001};

}  // namespace clpost

// SINUMERIK: CYCLE99 threads, CYCLE98 chains, CYCLE96 undercuts (cycle9*_emitter.h, their laws)
// and their read-back.
#include "controls/sinumerik/cycle96_emitter.h"
#include "controls/sinumerik/cycle98_emitter.h"
#include "controls/sinumerik/cycle99_emitter.h"
#include "controls/sinumerik/sinumerik_readback.h"
#include "controls/sinumerik/sinumerik_templates.h"
#include "machine/control.h"

namespace clpost {

namespace {

// SINUMERIK 840D sl Programming Manual Fundamentals: G700/G710 inch/metric for lengths and feeds
// (G70/G71 leave F in the basic system of units, machine data MD10240: "Feedrate functions are not
// affected by G70/G71. With G700/G710, feedrate values F are interpreted as geometrical
// parameters in the measuring system set by G function", 840Di sl Programming Manual 11/2006
// §7.1; 802D sl Programming 06/2006 §8.2.3), G33 thread cutting, G34/G35 increasing/decreasing
// lead, G94/G95 feed per minute / per revolution.
constexpr FixedCode kSinumerikCodes[] = {
    {"metric", "G710", "selects millimetres, feeds too"},
    {"inch", "G700", "selects inches, feeds too"},
    {"thread", "G33", "is a thread cut"},
    {"thread_increasing", "G34", "is a thread with increasing lead"},
    {"thread_decreasing", "G35", "is a thread with decreasing lead"},
    {"feed_per_min", "G94", "is feed per minute"},
    {"feed_per_rev", "G95", "is feed per revolution"},
};

constexpr const TemplateSpec* kSinumerikTemplates[] = {&tmpl::kCycle99, &tmpl::kCycle98,
                                                       &tmpl::kCycle96};

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
    .inch_length_increment = 0.0001,
    // Group 15 (SINUMERIK 840D sl / ONE Programming Manual Fundamentals, "Constant cutting speed
    // (G96/G961/G962, G97/G971/G972/G973, LIMS, SCC)": G96 "revolutional feedrate (as for G95)
    // and constant cutting speed", G961 "linear feedrate (as for G94) and constant cutting speed",
    // G97 "revolutional feedrate and constant spindle speed"; 840D Programming Manual 10/2004
    // §7.13: "The G96/G961 function can also be deactivated with G94 or G95"; Function Manual
    // Feeds (V1) 08/2005 §2.1: "The programmed F value is deleted when the system switches between
    // the feedrate types").
    .css_feed_per_min = "G961",
    .css_feed_per_rev = "G96",
    .templates = kSinumerikTemplates};

}  // namespace clpost

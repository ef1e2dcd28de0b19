// Fanuc (system A lathe): the two-block G76 and the G92 loop block (fanuc_emitter.h,
// fanuc_law.h) and their read-back.
#include "controls/fanuc/fanuc_codes.h"
#include "controls/fanuc/fanuc_emitter.h"
#include "controls/fanuc/fanuc_readback.h"
#include "controls/fanuc/fanuc_templates.h"
#include "machine/control.h"

namespace clpost {

namespace {

constexpr const TemplateSpec* kFanucTemplates[] = {&tmpl::kFanucG76, &tmpl::kG92, &tmpl::kG92Next};

// G92, the box cycle one block a pass (Haas's machines take it too: threading.loop g92).
constexpr LoopBlock kFanucLoops[] = {
    {"g92", []() -> std::unique_ptr<Emitter> { return std::make_unique<G92Emitter>(); },
     sim::g92_cycle}};

}  // namespace

extern const Control kFanucControl{
    .name = "fanuc",
    .cycle = "fanuc_g76",
    .cycle_emitter = []() -> std::unique_ptr<Emitter> {
      return std::make_unique<FanucG76Emitter>();
    },
    .readback = &sim::kFanucReadback,
    .fixed_codes = kFanucCodes,
    // "%" ends the program text on the control (the end-of-record mark of its tape format).
    .comment_control = "%",
    // Increment system IS-B: least input increment 0.001 mm, 0.0001 in (Fanuc's increment
    // systems, as M. Lynch lists them: mmsonline.com, "Juggling Mismatches in Resolution and
    // Least Input Increment"; docs/cl-meaning.md, inch output).
    .inch_length_increment = 0.0001,
    .templates = kFanucTemplates,
    .loops = kFanucLoops,
    .readback_state = sim::fanuc_readback_state};

}  // namespace clpost

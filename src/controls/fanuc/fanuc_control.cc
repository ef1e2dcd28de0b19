// Fanuc (system A lathe): the two-block G76 (fanuc_emitter.h, fanuc_law.h) and its read-back.
#include "controls/control.h"
#include "controls/fanuc/fanuc_emitter.h"
#include "controls/fanuc/fanuc_readback.h"

namespace clpost {

namespace {

// Fanuc 0i-TF Operator's Manual (B-64604EN), G-code system A: G20/G21 units, G32 thread cutting,
// G98/G99 feed per minute / per revolution.
constexpr FixedCode kFanucCodes[] = {
    {"metric", "G21", "selects millimetres"},
    {"inch", "G20", "selects inches"},
    {"thread", "G32", "is a thread cut"},
    {"feed_per_min", "G98", "is feed per minute"},
    {"feed_per_rev", "G99", "is feed per revolution"},
};

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
    .comment_control = "%"};

}  // namespace clpost

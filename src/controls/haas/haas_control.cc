// Haas lathe: the one-block G76 (haas_emitter.h, haas_law.h) and its read-back; its G92 is
// Fanuc's (threading.loop: g92).
#include "controls/control.h"
#include "controls/haas/haas_emitter.h"
#include "controls/haas/haas_readback.h"

namespace clpost {

namespace {

// Haas Lathe Operator's Manual, G-code list: G20/G21, G32 thread cutting, G98/G99.
constexpr FixedCode kHaasCodes[] = {
    {"metric", "G21", "selects millimetres"},
    {"inch", "G20", "selects inches"},
    {"thread", "G32", "is a thread cut"},
    {"feed_per_min", "G98", "is feed per minute"},
    {"feed_per_rev", "G99", "is feed per revolution"},
};

}  // namespace

extern const Control kHaasControl{
    .name = "haas",
    .cycle = "haas_g76",
    .cycle_emitter = []() -> std::unique_ptr<Emitter> {
      return std::make_unique<HaasG76Emitter>();
    },
    .readback = &sim::kHaasReadback,
    .fixed_codes = kHaasCodes,
    // "%" ends the program text on the control (the end-of-record mark of its tape format).
    .comment_control = "%"};

}  // namespace clpost

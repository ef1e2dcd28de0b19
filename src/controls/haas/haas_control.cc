// Haas lathe: the one-block G76 (haas_emitter.h, haas_law.h) and its read-back; its G92 is
// Fanuc's (threading.loop: g92).
#include "controls/fanuc/fanuc_codes.h"
#include "controls/haas/haas_emitter.h"
#include "controls/haas/haas_keys.h"
#include "controls/haas/haas_readback.h"
#include "controls/haas/haas_templates.h"
#include "machine/control.h"

namespace clpost {

namespace {

constexpr const TemplateSpec* kHaasTemplates[] = {&tmpl::kHaasG76};

}  // namespace

extern const Control kHaasControl{
    .name = "haas",
    .cycle = "haas_g76",
    .cycle_emitter = []() -> std::unique_ptr<Emitter> {
      return std::make_unique<HaasG76Emitter>();
    },
    .readback = &sim::kHaasReadback,
    .fixed_codes = kFanucCodes,
    // "%" ends the program text on the control (the end-of-record mark of its tape format).
    .comment_control = "%",
    // 0.0001 in: Setting 77 reads an F without a point in the inch default of .0001 (Haas,
    // "Help with the Decimal Points", haas.co.uk); lengths are given to the same place (issue
    // 24; docs/cl-meaning.md, inch output).
    .inch_length_increment = 0.0001,
    .keys = kHaasKeys,
    .templates = kHaasTemplates};

}  // namespace clpost

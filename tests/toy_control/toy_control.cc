#include "toy_control/toy_control.h"

#include "toy_control/toy_emitter.h"
#include "toy_control/toy_keys.h"
#include "toy_control/toy_readback.h"
#include "toy_control/toy_templates.h"

namespace clpost::toy {

namespace {

// Its code: the name a machine file gives it by, and its meaning, which no machine file changes.
constexpr NameSpec kCodes[] = {
    {"toy_cycle_end", "the toy's M178, after a thread's last G177 or G178 block"}};
constexpr FixedCode kFixedCodes[] = {
    {"toy_cycle_end", "M178", "ends a run of G177 or G178 blocks"}};

constexpr const TemplateSpec* kTemplates[] = {&kG177, &kG178};

constexpr LoopBlock kLoops[] = {
    {"toy_g178", []() -> std::unique_ptr<Emitter> { return std::make_unique<G178Emitter>(); },
     g178}};

}  // namespace

const Control kControl{
    .name = "toy",
    .cycle = "toy_g177",
    .cycle_emitter = []() -> std::unique_ptr<Emitter> { return std::make_unique<G177Emitter>(); },
    .readback = &kReadback,
    .fixed_codes = kFixedCodes,
    .keys = kKeys,
    .codes = kCodes,
    .templates = kTemplates,
    .loops = kLoops,
    .readback_state = readback_state};

}  // namespace clpost::toy

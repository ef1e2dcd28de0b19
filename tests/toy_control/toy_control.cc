#include "toy_control/toy_control.h"

#include "toy_control/toy_emitter.h"
#include "toy_control/toy_readback.h"

namespace clpost::toy {

const Control kControl{
    .name = "toy",
    .cycle = "toy_g177",
    .cycle_emitter = []() -> std::unique_ptr<Emitter> { return std::make_unique<G177Emitter>(); },
    .readback = &kReadback};

}  // namespace clpost::toy

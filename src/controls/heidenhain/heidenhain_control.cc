// HEIDENHAIN DIN (CNC PILOT): G31 on its contour … G80 (heidenhain_emitter.h, heidenhain_law.h)
// and its read-back.
#include "controls/control.h"
#include "controls/heidenhain/heidenhain_emitter.h"
#include "controls/heidenhain/heidenhain_readback.h"

namespace clpost {

extern const Control kHeidenhainControl{.name = "heidenhain",
                                        .cycle = "heidenhain_g31",
                                        .cycle_emitter = []() -> std::unique_ptr<Emitter> {
                                          return std::make_unique<HeidenhainG31Emitter>();
                                        },
                                        .readback = &sim::kHeidenhainReadback};

}  // namespace clpost

// The registry's loop emitters (threading.loop): the G33 loop any control writes, and Fanuc's
// G92, which Haas's machines use too. Compiled into the emitters stage.
#include "controls/fanuc/fanuc_emitter.h"
#include "emitters/emitter.h"
#include "emitters/emulation_emitter.h"

namespace clpost {

std::unique_ptr<Emitter> make_loop_emitter(ThreadLoop l) {
  switch (l) {
    case ThreadLoop::kG33:
      return std::make_unique<EmulationEmitter>("G33 loop");
    case ThreadLoop::kG92:
      return std::make_unique<G92Emitter>();
  }
  return nullptr;
}

}  // namespace clpost

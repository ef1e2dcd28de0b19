// The registry's read-back of the loop blocks (threading.loop): Fanuc's G92, which Haas's
// machines use too. Compiled into the simulator stage.
#include "controls/fanuc/fanuc_readback.h"
#include "simulator/control_readback.h"

namespace clpost::sim {

CycleReader loop_reader(ThreadLoop l) {
  switch (l) {
    case ThreadLoop::kG33:
      return nullptr;
    case ThreadLoop::kG92:
      return g92_cycle;  // Fanuc's, Haas's too
  }
  return nullptr;
}

}  // namespace clpost::sim

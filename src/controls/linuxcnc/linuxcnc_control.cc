// LinuxCNC: G76 (linuxcnc_emitter.h, linuxcnc_law.h, checked against its own rs274) and its
// read-back.
#include "controls/control.h"
#include "controls/linuxcnc/linuxcnc_emitter.h"
#include "controls/linuxcnc/linuxcnc_readback.h"

namespace clpost {

extern const Control kLinuxcncControl{
    .name = "linuxcnc",
    .cycle = "linuxcnc_g76",
    .cycle_emitter = []() -> std::unique_ptr<Emitter> {
      return std::make_unique<LinuxcncG76Emitter>();
    },
    .readback = &sim::kLinuxcncReadback,
    // M6 stops the spindle: rs274 -g writes STOP_SPINDLE_TURNING between START_CHANGE and
    // CHANGE_TOOL (LinuxCNC 2.9, tests/rs274_test.cc).
    .tool_change_stops_spindle = true};

}  // namespace clpost

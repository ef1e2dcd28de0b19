// LinuxCNC: G76 (linuxcnc_emitter.h, linuxcnc_law.h, checked against its own rs274) and its
// read-back.
#include "controls/linuxcnc/linuxcnc_emitter.h"
#include "controls/linuxcnc/linuxcnc_readback.h"
#include "controls/linuxcnc/linuxcnc_templates.h"
#include "machine/control.h"

namespace clpost {

namespace {

// LinuxCNC G-code reference (lathe): G20/G21, G33 spindle-synchronized motion, G94/G95.
constexpr FixedCode kLinuxcncCodes[] = {
    {"metric", "G21", "selects millimetres"},
    {"inch", "G20", "selects inches"},
    {"thread", "G33", "is a spindle-synchronized move"},
    {"feed_per_min", "G94", "is feed per minute"},
    {"feed_per_rev", "G95", "is feed per revolution"},
    // M-codes page, M3/M4/M5 with `$n`, the spindle number (docs/millturn.md): the live tool is
    // a spindle like the main one, addressed by the live_spindle_rpm template's `$1`.
    {"live_spindle_cw", "M3", "starts a spindle clockwise (the live tool's with `$1`)"},
    {"live_spindle_ccw", "M4", "starts a spindle counter-clockwise (the live tool's with `$1`)"},
};

constexpr const TemplateSpec* kLinuxcncTemplates[] = {&tmpl::kLinuxcncG76,
                                                      &tmpl::kLinuxcncG76Taper};

}  // namespace

extern const Control kLinuxcncControl{
    .name = "linuxcnc",
    .cycle = "linuxcnc_g76",
    .cycle_emitter = []() -> std::unique_ptr<Emitter> {
      return std::make_unique<LinuxcncG76Emitter>();
    },
    .readback = &sim::kLinuxcncReadback,
    // M6 stops the spindle: rs274 -g writes STOP_SPINDLE_TURNING between START_CHANGE and
    // CHANGE_TOOL (LinuxCNC 2.9, tests/rs274_test.cc).
    .tool_change_stops_spindle = true,
    .fixed_codes = kLinuxcncCodes,
    .templates = kLinuxcncTemplates};

}  // namespace clpost

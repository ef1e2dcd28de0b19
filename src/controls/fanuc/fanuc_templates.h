#pragma once
// Fanuc's templates: the two-block G76 and the G92 box cycle (Haas's G92 too), declared
// with their fields (machine/machine_schema.h: a field name a template does not declare does not
// compile). Listed in the schema by its Control (Control::templates).
#include "machine/machine_schema.h"

namespace clpost::tmpl {

using enum FieldKind;
using enum Need;

inline constexpr TemplateField kFanucG76Fields[] = {
    {"m", kText, "finishing passes, two digits"},
    {"chamfer", kText, "chamfer in 0.1 leads, two digits"},
    {"angle", kText, "tool angle, two digits"},
    {"min_cut", kText, "minimum cut, format g76_depth (g76_depth_in in inches)"},
    {"allowance", kText, "finishing allowance, format g76_allowance"},
    {"x", kText, "thread end X"},
    {"z", kText, "thread end Z"},
    {"taper", kText, "' R' and the taper, or empty"},
    {"height", kText, "thread height, format g76_depth"},
    {"first_cut", kText, "first cut depth, format g76_depth"},
    {"lead", kText, "lead, format F"}};
inline constexpr TemplateField kG92Fields[] = {
    {"x", kText, "pass X"},
    {"z", kText, "thread end Z (g92_next: ' Z' and Z when it changed, else empty)"},
    {"taper", kText, "' R' and the taper, or empty"},
    {"lead", kText, "lead, format F (empty in g92_next)"},
    {"start_angle", kText, "' Q' and the start angle (format thread_angle), or empty"}};
inline constexpr TemplateSpec kFanucG76{"fanuc_g76",           kFanucG76Fields,   kSetting,
                                        "Fanuc two-block G76", "threading.cycle", "fanuc_g76"};
inline constexpr TemplateSpec kG92{
    "g92", kG92Fields, kSetting, "first G92 block of a thread", "threading.loop", "g92"};
inline constexpr TemplateSpec kG92Next{
    "g92_next", kG92Fields, kSetting, "next passes while G92 is modal", "threading.loop", "g92"};

}  // namespace clpost::tmpl

#pragma once
// Haas's template: the one-block G76, declared
// with their fields (machine/machine_schema.h: a field name a template does not declare does not
// compile). Listed in the schema by its Control (Control::templates).
#include "machine/machine_schema.h"

namespace clpost::tmpl {

using enum FieldKind;
using enum Need;

inline constexpr TemplateField kHaasG76Fields[] = {
    {"x", kText, "thread end X"},
    {"z", kText, "thread end Z"},
    {"taper", kText, "' I' and the taper, or empty"},
    {"height", kText, "thread height, format K"},
    {"first_cut", kText, "first cut depth, format D"},
    {"angle", kText, "tool angle"},
    {"mode", kText, "infeed mode P"},
    {"start_angle", kText, "' Q' and the start angle (format thread_angle), or empty"},
    {"lead", kText, "lead, format F"}};
inline constexpr TemplateSpec kHaasG76{"haas_g76",           kHaasG76Fields,    kSetting,
                                       "Haas one-block G76", "threading.cycle", "haas_g76"};

}  // namespace clpost::tmpl

#pragma once
// LinuxCNC's templates: G76, and G76 with an exit taper, declared
// with their fields (machine/machine_schema.h: a field name a template does not declare does not
// compile). Listed in the schema by its Control (Control::templates).
#include "machine/machine_schema.h"

namespace clpost::tmpl {

using enum FieldKind;
using enum Need;

inline constexpr TemplateField kLinuxcncG76Fields[] = {
    {"p", kText, "lead, format g76_lead"},
    {"z", kText, "thread end Z"},
    {"i", kText, "thread peak offset, format g76_depth"},
    {"j", kText, "first cut depth, format g76_depth"},
    {"k", kText, "full thread depth, format g76_depth"},
    {"r", kText, "depth degression"},
    {"q", kText, "compound angle, format g76_angle"},
    {"h", kText, "spring passes"},
    {"e", kText, "taper length, format g76_taper"},
    {"l", kText, "taper ends (0 none, 2 exit)"}};
inline constexpr TemplateSpec kLinuxcncG76{"linuxcnc_g76", kLinuxcncG76Fields, kSetting,
                                           "LinuxCNC G76", "threading.cycle",  "linuxcnc_g76"};
inline constexpr TemplateSpec kLinuxcncG76Taper{
    "linuxcnc_g76_taper", kLinuxcncG76Fields, kSetting, "LinuxCNC G76 with an exit taper (E, L)",
    "threading.cycle",    "linuxcnc_g76"};

}  // namespace clpost::tmpl

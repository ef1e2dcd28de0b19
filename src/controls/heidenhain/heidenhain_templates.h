#pragma once
// HEIDENHAIN DIN's template: G31 with its contour and G80, declared
// with their fields (machine/machine_schema.h: a field name a template does not declare does not
// compile). Listed in the schema by its Control (Control::templates).
#include "machine/machine_schema.h"

namespace clpost::tmpl {

using enum FieldKind;
using enum Need;

inline constexpr TemplateField kHeidenhainG31Fields[] = {
    {"f", kText, "lead, format F"},
    {"u", kText, "thread depth, format U"},
    {"ic", kText, "number of cuts"},
    {"v", kText, "infeed type"},
    {"h", kText, "flank offset type (codes g31_h_*)"},
    {"a", kText, "infeed angle, format A"},
    {"d", kText, "number of starts"},
    {"q", kText, "idle (spring) passes"},
    {"c", kText, "start angle, format C"},
    {"bd", kText, "run-in/run-out direction"},
    {"b", kText, "run-in length (threading.run_in, or δ1 with auto), format B"},
    {"p", kText, "run-out length (δ2 with threading.run_in auto, else 0), format P"},
    {"k", kText, "thread run-out, format K"},
    {"x1", kText, "contour start X"},
    {"z1", kText, "contour start Z"},
    {"x2", kText, "contour end X"},
    {"z2", kText, "contour end Z"}};
inline constexpr TemplateSpec kHeidenhainG31{
    "heidenhain_g31",  kHeidenhainG31Fields, kSetting, "HEIDENHAIN G31 with its contour and G80",
    "threading.cycle", "heidenhain_g31"};

}  // namespace clpost::tmpl

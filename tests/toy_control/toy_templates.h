#pragma once
// The toy control's templates: its cycle G177 and its loop block G178, declared with their fields
// (machine/machine_schema.h: a field name a template does not declare does not compile) and
// listed in the schema by its Control (Control::templates). A machine file gives their lines.
#include "machine/machine_schema.h"

namespace clpost::toy {

using enum FieldKind;
using enum Need;

inline constexpr TemplateField kG177Fields[] = {{"x", kText, "the pass's X, format X"},
                                                {"z", kText, "where the cut ends, format Z"},
                                                {"k", kText, "where the cut starts, format K"},
                                                {"f", kText, "lead, format F"}};
inline constexpr TemplateSpec kG177{"toy_g177",       kG177Fields,       kSetting,
                                    "the toy's G177", "threading.cycle", "toy_g177"};

inline constexpr TemplateField kG178Fields[] = {
    {"x", kText, "the pass's X, format X"},
    {"z", kText, "where the cut ends, format Z"},
    {"f", kText, "' F' and the lead (format F) in a thread's first block, else empty"}};
inline constexpr TemplateSpec kG178{
    "toy_g178", kG178Fields, kSetting, "the toy's G178 loop block", "threading.loop", "toy_g178"};

}  // namespace clpost::toy

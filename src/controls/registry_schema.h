#pragma once
// The registry's schema side: the templates, keys and codes the shipped controls declare, in the
// order the schema lists them (machine_schema.cc: the loader, `clpost schema`,
// docs/machines.md).
#include "controls/fanuc/fanuc_templates.h"
#include "controls/haas/haas_keys.h"
#include "controls/haas/haas_templates.h"
#include "controls/heidenhain/heidenhain_codes.h"
#include "controls/heidenhain/heidenhain_templates.h"
#include "controls/linuxcnc/linuxcnc_templates.h"
#include "controls/sinumerik/sinumerik_templates.h"

namespace clpost::tmpl {

inline constexpr const TemplateSpec* kControlTemplates[] = {
    &kCycle99, &kCycle98, &kCycle96,     &kFanucG76,         &kHaasG76,
    &kG92,     &kG92Next, &kLinuxcncG76, &kLinuxcncG76Taper, &kHeidenhainG31};

}  // namespace clpost::tmpl

namespace clpost {

// The keys and the codes the controls declare (one control each, today).
inline constexpr auto& kControlKeys = kHaasKeys;
inline constexpr auto& kControlCodes = kHeidenhainCodes;

}  // namespace clpost

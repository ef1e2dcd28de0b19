#pragma once
// The controls' own settings a machine file sets (each declared by its control's folder), as one
// base of Machine: part of the registry.
#include "controls/haas/haas_settings.h"

namespace clpost {

struct ControlSettings : HaasMachineSettings {};

}  // namespace clpost

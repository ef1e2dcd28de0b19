#pragma once
// The Haas control's settings its G76 law reads (haas_law.h: haas_settings), kept on the machine
// as the keys threading.haas_* (haas_keys.h). Machine has them through ControlSettings
// (controls/control_settings.h).

namespace clpost {

struct HaasMachineSettings {
  double haas_finish_allowance = 0;  // Haas setting 86, machine units
  double haas_min_cut = 0;           // Haas setting 99, machine units
  double haas_chamfer = 0;           // Haas setting 95, in leads
};

}  // namespace clpost

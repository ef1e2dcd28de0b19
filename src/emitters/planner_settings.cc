#include "emitters/planner_settings.h"

namespace clpost {

PlannerSettings planner_settings(const Machine& m) {
  PlannerSettings s;
  s.default_option = m.default_option;
  s.default_tool_angle = m.default_tool_angle;
  s.start_angle_word = m.start_angle_word;
  s.variable_lead = m.variable_lead;
  s.lead_law = {m.servo_time_constant, m.lead_error};
  s.add_run_in = m.run_in.automatic;
  s.machine_name = m.name;
  return s;
}

}  // namespace clpost

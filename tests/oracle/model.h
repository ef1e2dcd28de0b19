#pragma once
// The oracle's model of what a CL program means, written from docs/cl-meaning.md: a CL text in,
// its events out (every motion with the state it is made with, every dwell), in mm. Deliberately
// small, and sharing no code with src/: a misunderstanding of the CL in the post is not repeated
// here.
#include <string>
#include <string_view>
#include <vector>

#include "events.h"

namespace oracle {

// What the model needs to know of the machine: the CL units before any UNITS/ and the CSS limit
// before any MAXRPM (the machine's limits.max_rpm).
struct ModelOptions {
  bool inch = false;
  double max_rpm = 3000;
  // GOHOME/x,y,z is the machine's home return (its `home` template: Fanuc, Haas `G28 U0.`,
  // `G28 W0.`; docs/machines.md), not a rapid to the point.
  bool home_is_reference = false;
};

struct ModelResult {
  std::vector<Event> events;
  std::string error;  // "CL line N: …" when the model cannot say what a statement means
};

ModelResult model_events(std::string_view cl, const ModelOptions& opts = {});

}  // namespace oracle

#pragma once
// A small reader of a Fanuc 0i-T lathe program (G-code system A), and of a Haas or an NCT lathe
// program where Haas or NCT documents another meaning: the program text in, the oracle's events
// out (events.h: mm, X a radius), as the control runs it with block delete off or on. Written from
// the controls' documentation (docs/cl-meaning.md, "How the oracle reads a Fanuc or Haas
// program", "How the oracle reads an NCT program", each meaning's source beside its code); it
// shares no code with src/ (not the NC reader, not the laws, not the simulator): the post's
// misreading of a control is not repeated here.
#include <string>
#include <string_view>
#include <vector>

#include "events.h"

namespace oracle {

enum class Dialect { kFanuc, kHaas, kNct };

struct ControlRun {
  std::vector<Event> events;
  std::string error;   // why the control stops (an alarm, or a word the reader cannot say)
  int error_line = 0;  // its line in the program, from 1
};

ControlRun fanuc_events(std::string_view program, Dialect dialect, bool block_delete);

}  // namespace oracle

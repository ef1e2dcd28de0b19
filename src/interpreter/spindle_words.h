#pragma once
// SPINDL/ as read (spindle_feed.cc), for the path that turns the spindle it names
// (ToolPath::spindle): the main spindle on the turning path, the live tool's on a live path.
#include <optional>

#include "interpreter/post_state.h"

namespace clpost {

// SPINDL/'s words, in any order.
struct SpindleWords {
  std::optional<double> value, max_rpm;
  SourceLoc value_loc;
  bool css = false, off = false, on = false;
  const Arg* surface_word = nullptr;  // SFM or SMM
  std::optional<SpindleDir> dir;
};

// A speed the S format rounds to nothing would be written as S0: a turning spindle that stands
// still on the machine (CATIA writes its tools' SPINDL/0.398,RPM defaults). False: reported.
bool speed_written(PostState& s, const Statement& st, const SpindleWords& w);
// SPINDL/ for the main spindle (the turning path): its speed, surface speed and direction, or
// OFF (templates spindle_rpm, spindle_css, spindle_stop).
void main_spindl(PostState& s, const Statement& st, SpindleWords w);

}  // namespace clpost

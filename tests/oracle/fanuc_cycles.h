#pragma once
// The threading cycles of the Fanuc/Haas reader (fanuc_reader.cc) expanded into their passes,
// from the controls' documented meaning (../shared/reference/controllers.md, "Fanuc (system A
// lathe)", "Haas lathe", "What public sources confirm"). Plain geometry, no program text.
#include <vector>

#include "events.h"

namespace oracle {

struct CyclePoint {
  double x = 0, z = 0;  // mm, X a radius
};

// One pass of a threading cycle from its start point `s`: a rapid to the cut's start `cut`, the
// thread cut at `lead` to `end`, a rapid out to s.x, a rapid back to s. Moves of no length are
// left out. The events have no state (the reader adds it).
void thread_pass(CyclePoint s, CyclePoint cut, CyclePoint end, double lead,
                 std::vector<Event>& out);

// Fanuc G76's depths from the crest (radius, mm), pass by pass: Δd·√n, an increment below
// Δdmin raised to it (and every later one), roughing up to k − d, then m passes at k.
std::vector<double> fanuc_g76_depths(double k, double first, double min_cut, double allowance,
                                     int finish_passes);

// Haas G76's depths: D·√N (P1, P2) or N·D (P3, P4) while below K, then one pass at K.
std::vector<double> haas_g76_depths(double k, double d, bool constant_depth);

}  // namespace oracle

#pragma once
// The model's events against rs274's, in order: the first difference, within what the program can
// say (docs/cl-meaning.md, "How the oracle reads rs274"), and the class it is counted under.
#include <string>
#include <vector>

#include "events.h"

namespace oracle {

constexpr double kPointTolerance = 1e-4;  // mm: end points, centres, leads

// The least increment a program writes X, Z, I, K and R in (0: LinuxCNC's doubles, compared to
// kPointTolerance). An end point is within half of it of the model's, a centre (a start point and
// I, K, each rounded) within one.
struct Resolution {
  double mm = 0;    // in a G21 program, mm
  double inch = 0;  // in a G20 program, in
};

struct Difference {
  bool found = false;
  size_t index = 0;    // in the run's event lists
  std::string field;   // what differs: "feed", "spindle speed", "end point", …
  std::string klass;   // field and the context it happens in (the model's provenance)
  std::string detail;  // "model …, rs274 …"
  bool have_model = false, have_rs274 = false;
  Event model, rs274;
};

// One difference of one event.
struct Found {
  Difference d;       // d.klass: its class in this run
  std::string plain;  // its class in a run with block delete off
};

struct Comparison {
  Difference first;          // the first difference, the one a report shows
  std::vector<Found> found;  // every difference, event by event
  size_t lined_up = 0;       // events that line up: up to the first difference in the motions
};

// `model`: the model's events that the run should do (without the OPSKIP ranges' when block
// delete is on). The state of every motion is compared up to the first difference in the motions
// themselves (after which the events no longer line up). `block_delete`: the run skips the
// ranges, so "first after an OPSKIP range" is a context worth naming.
Comparison compare_events(const std::vector<Event>& model, const std::vector<Event>& rs274,
                          bool block_delete = false, const Resolution& resolution = {});

// The class a difference in `field` at the model's event `m` is counted under: the field and the
// cause the model's provenance points at ("feed [after UNITS]"). With block delete on, the cause
// is the OPSKIP range (a difference the run with block delete off does not show).
std::string class_of(const std::string& field, const Event& m, bool block_delete);

// `text` with its digits taken out: messages that differ only in their numbers are one class.
std::string without_numbers(const std::string& text);

}  // namespace oracle

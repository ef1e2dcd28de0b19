#pragma once
// One hole on the spindle axis (CYCLE/DRILL … and its GOTO at radial 0) written for a control:
// its own canned cycle through a `hole_*` template when the machine has one and the cycle's words
// say exactly what the CL says, else plain G0/G1/G4 moves with the pecks expanded (the reason in
// a comment) — "exact or fall back", as threads are written.
#include <cstddef>
#include <cstdint>
#include <string>
#include <string_view>
#include <vector>

#include "laws/hole_law.h"
#include "writer/nc_program.h"

namespace clpost {

// The template that writes `h` on its machine (hole_drill, hole_peck, …).
const TemplateSpec& hole_template(const Machine& m, const Hole& h);

// Why the template cannot write `h` exactly, or "" when it can (the machine has it, and its one
// peck word, dwell or retract say what the CL says).
std::string hole_misfit(const Machine& m, const Hole& h);

// Writes `h`: the template when it fits, else moves (with a comment saying why). A template that
// cannot be written is returned (an error at the hole's CL line); the moves always are.
[[nodiscard]] TemplateWrite write_hole(NcProgram& prog, const Hole& h);

// The hole as G0/G1/G4 moves, pecks expanded (a tap: G1 at its lead per revolution in, the
// spindle reversed, G1 out). Returns the dwell's write (kWritten when there is none).
[[nodiscard]] TemplateWrite expand_hole(NcProgram& prog, const Hole& h);

}  // namespace clpost

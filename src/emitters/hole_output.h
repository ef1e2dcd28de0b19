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

#include "emitters/cycle_output.h"
#include "laws/hole_law.h"
#include "writer/nc_program.h"

namespace clpost {

// The template that writes `h` on its machine (hole_drill, hole_peck, …).
const TemplateSpec& hole_template(const Machine& m, const Hole& h);

// The output of the holes written as G0/G1/G4 moves (OutputUsed::name).
inline constexpr std::string_view kHoleMoves = "moves";

// What wrote `h` as its reader calls it, from the name of its output (OutputUsed::name: the
// hole's template, or kHoleMoves): the cycle and the code its template writes ("peck drilling
// (G83)", "drilling (CYCLE81)"), or the machine's moves ("G0/G1 moves").
std::string hole_output_text(const Machine& m, const Hole& h, std::string_view output);

// Why the template cannot write `h` exactly, or "" when it can (the machine has it, and its one
// peck word, dwell or retract say what the CL says).
std::string hole_misfit(const Machine& m, const Hole& h);

// Writes `h` with the first of its outputs that fits: the machine's cycle (its hole_* template),
// else moves, a comment saying why. False, with an error at ctx.loc, when a template cannot be
// written.
bool write_hole(NcProgram& prog, const Hole& h, const EmitContext& ctx);

// The hole as G0/G1/G4 moves, pecks expanded (a tap: G1 at its lead per revolution in, the
// spindle reversed, G1 out). Returns the dwell's write (kWritten when there is none).
[[nodiscard]] TemplateWrite expand_hole(NcProgram& prog, const Hole& h);

}  // namespace clpost

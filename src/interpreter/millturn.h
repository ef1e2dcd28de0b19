#pragma once
// Mill-turn in the interpreter (millturn.cc, docs/millturn.md): the main spindle as the C axis
// around tool changes, spindle starts and motions, and C positioning. A live tool's own work is
// its path's (live_path.h); which tools mill, tool_kind.h.
#include <optional>
#include <vector>

#include "interpreter/post_state.h"

namespace clpost {

// The main spindle stops for milling or C positioning: written when the CL left it turning (it
// turns again, as the CL left it, before the next turning motion: restart_stopped_spindle).
void hold_main_spindle(PostState& s, const Statement& st);
// The main spindle becomes the C axis (codes.c_engage), once, until it turns again: for a
// milling tool (ToolPath::begin) and for ROTABL/.
void engage_c(PostState& s, const Statement& st);
// Before the main spindle turns, and at the program end: C is unclamped and disengaged. Across a
// tool change C stays engaged for a next milling tool.
void release_c(PostState& s);
// C is at the C index (the last ROTABL's angle, whole turns aside), or either is not known.
bool c_at_index(const PostState& s);
// The C words that take C from `from` (unknown: none) to `angle` (incremental: by `angle`),
// turning `sign` (+1 increasing, -1 decreasing, none: the shortest way), as machine `m` takes
// them (millturn.c_rotation); empty when C is there already.
std::vector<double> c_steps(const Machine& m, std::optional<double> from, double angle,
                            bool incremental, std::optional<int> sign);
// Writes C words `steps` (c_steps), unclamping before and clamping after as the machine does;
// C is then at the last. False (reported at `st`) when the c_index template cannot be written.
bool write_c_steps(PostState& s, const Statement& st, const std::vector<double>& steps);
// CLAMP/ON|OFF|AUTO,CAXIS (ICAM) and CLAMP/CAXIS,ON|OFF (NX-to-APT): the CL's own C clamp.
void clamp_c_stmt(PostState& s, const Statement& st);
// CLAMP/TABLE,ALL,ON|OFF|AUTO (Fusion): every rotary axis, C on a lathe; a note without C.
void clamp_table_stmt(PostState& s, const Statement& st);

}  // namespace clpost

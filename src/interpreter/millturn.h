#pragma once
// Mill-turn in the interpreter (millturn.cc, docs/millturn.md): milling tools, the live spindle
// and the C axis around tool changes, spindle starts and motions.
#include <optional>
#include <vector>

#include "interpreter/post_state.h"

namespace clpost {

// The kind of the tool LOADTL-like statement `st` loads (its tool number is argument `first`):
// a MILL or TURN word of its own (`at` set to it), else the tool data before it (TDATA/MILL,
// TOOLNO/…,MILL), else the CL's mode (APPLY/MILL); none: a turning tool.
std::optional<ToolKindWord> loadtl_kind(const PostState& s, const Statement& st, size_t first,
                                        SourceLoc& at);
// Before tool `tool` of `kind` is loaded: the live tool of the one leaving stops, the main
// spindle stops for a milling tool. False (an error at `at`): a milling tool on a machine
// without live tools.
bool millturn_tool_change(PostState& s, const Statement& st, int tool,
                          const std::optional<ToolKindWord>& kind, SourceLoc at);
// The end of a live tool's work, the same before a tool change and at the program end: cutter
// compensation off, Y back to 0 (a rapid from where the CL left the tool) and the lathe plane
// (end_milling), the live tool stopped. With `release` (the program end) C is unclamped and
// disengaged too, whatever the tool; across a tool change C stays engaged for a next milling
// tool, until the main spindle turns again (release_c).
void end_milling_section(PostState& s, const Statement& st, bool release);
// After the tool change block: a milling tool engages C.
void millturn_after_tool_change(PostState& s, const Statement& st);
// Before the main spindle turns: C is unclamped and disengaged.
void release_c(PostState& s);
// A GOTO of a milling tool to `p` that is an XZ move at the C index, written as a lathe's move:
// Y 0, the tool axis along Z, C indexed (or X 0), a rapid or a feed per minute.
bool live_xz_move(const PostState& s, Point3 p);
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

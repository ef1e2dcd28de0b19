#pragma once
// Statement handlers by major word. Each family lives in its own file: motion.cc (GOTO, FROM,
// GODLTA, CIRCLE, RAPID, HELICAL), spindle_feed.cc (FEDRAT, SPINDL, DELAY), tool.cc (LOADTL,
// LOAD/TOOL, TURRET), program_words.cc (UNITS, COOLNT, CUTCOM, STOP, FINI, … and the words
// skipped), text_words.cc (PARTNO, PPRINT, INSERT, TOOL PATH, unknown words), thread_statements.cc
// (PITCH, THREAD, OP/THREAD, COUPLE), cycles.cc (CYCLE/), cam_words.cc (SYN, DNTCUT/CUT, TOOLNO,
// TPRINT, CUTTER, SWITCH), geometric_motion.cc (INDIRV, PSIS, GOFWD …; its geometry in
// lathe_geometry.cc). A new CL word is one entry in statement_table.cc and one handler. What a
// statement does for one kind of tool is its motion path's (tool_path.h): the handler reads the
// statement and calls the path in force.
#include <span>
#include <string_view>

#include "interpreter/clock.h"
#include "interpreter/post_state.h"

namespace clpost {

using StatementHandler = void (*)(PostState&, const Statement&);

struct StatementEntry {
  std::string_view major;
  StatementHandler handler;
};

// The handler of major word `major` (upper case), or nullptr when the word is unknown.
const StatementEntry* find_statement(std::string_view major);
// Every entry, sorted by major word (tests).
std::span<const StatementEntry> statement_table();

// Handlers (declared here so that the table can name them).
void goto_stmt(PostState& s, const Statement& st);
void from_stmt(PostState& s, const Statement& st);
void godlta_stmt(PostState& s, const Statement& st);
void circle_stmt(PostState& s, const Statement& st);
void rapid_stmt(PostState& s, const Statement& st);
void movarc_stmt(PostState& s, const Statement& st);
// HELICAL/ (CATIA): an arc or a helix of a milling tool; the comment an unknown statement is for
// a turning tool.
void helical_stmt(PostState& s, const Statement& st);
void fedrat_stmt(PostState& s, const Statement& st);
void spindl_stmt(PostState& s, const Statement& st);
void delay_stmt(PostState& s, const Statement& st);
void loadtl_stmt(PostState& s, const Statement& st);
void load_stmt(PostState& s, const Statement& st);
void units_stmt(PostState& s, const Statement& st);
void coolnt_stmt(PostState& s, const Statement& st);
void cutcom_stmt(PostState& s, const Statement& st);
void stop_stmt(PostState& s, const Statement& st);
void end_stmt(PostState& s, const Statement& st);
void fini_stmt(PostState& s, const Statement& st);
void gohome_stmt(PostState& s, const Statement& st);  // positions.cc
// Before a tool change: the machine's tool_change_position, when it has one (positions.cc).
void tool_change_position(PostState& s, const Statement& st);
// Pass-through words (machine_words.cc).
void auxfun_stmt(PostState& s, const Statement& st);
void prefun_stmt(PostState& s, const Statement& st);
void selctl_stmt(PostState& s, const Statement& st);
void clamp_stmt(PostState& s, const Statement& st);
void opskip_stmt(PostState& s, const Statement& st);
void multax_stmt(PostState& s, const Statement& st);
void spline_stmt(PostState& s, const Statement& st);
void skipped_stmt(PostState& s, const Statement& st);
void partno_stmt(PostState& s, const Statement& st);
void pprint_stmt(PostState& s, const Statement& st);
void insert_stmt(PostState& s, const Statement& st);
void tool_path_stmt(PostState& s, const Statement& st);
void pitch_stmt(PostState& s, const Statement& st);
void thread_stmt(PostState& s, const Statement& st);
void op_stmt(PostState& s, const Statement& st);
void couple_stmt(PostState& s, const Statement& st);
void cycle_stmt(PostState& s, const Statement& st);
void undercut_stmt(PostState& s, const Statement& st);       // CYCLE/UNDCUT (undercut.cc)
void lathe_thread_cycle(PostState& s, const Statement& st);  // CYCLE/LATHTHRD (its own file)

// CAM words (cam_words.cc) and APT geometric motion (geometric_motion.cc).
void syn_stmt(PostState& s, const Statement& st);
void ppfun_stmt(PostState& s, const Statement& st);
void dntcut_stmt(PostState& s, const Statement& st);
void cut_stmt(PostState& s, const Statement& st);
void toolno_stmt(PostState& s, const Statement& st);
void tprint_stmt(PostState& s, const Statement& st);
void cutter_stmt(PostState& s, const Statement& st);
// A cutter diameter the CL gave (CUTTER/, TLDATA/): the tool loaded when it has not moved yet,
// else the next tool (tool data before the change it describes, as CATIA and SolidWorks write
// it). Its holes carry it (Hole::tool_diameter).
void describe_diameter(PostState& s, double d);
void switch_stmt(PostState& s, const Statement& st);
void indirv_stmt(PostState& s, const Statement& st);
void psis_stmt(PostState& s, const Statement& st);
void go_stmt(PostState& s, const Statement& st);  // GOFWD, GOLFT, GORGT, GOBACK
// The turning path's geometric motion and PSIS/ (geometric_motion.cc): in the lathe plane.
void lathe_go(PostState& s, const Statement& st);
void lathe_part_surface(PostState& s, const Statement& st);
// The replacement SYN/ gave major word `major` (empty: ignored), or nullptr.
const std::string* synonym_of(const PostState& s, std::string_view major);
// GOFWD, GOLFT, GORGT, GOBACK: the words whose modifiers (TLON, TLLFT, TLRGT) go_stmt reads.
inline bool is_motion_word(std::string_view w) {
  return w == "GOFWD" || w == "GOLFT" || w == "GORGT" || w == "GOBACK";
}
// Hole-making cycles (hole_cycles.cc): CYCLE/DRILL, DEEP, … and CYCLE/INIT; the GOTO of a
// turning tool's hole while one is in force (hole_goto.cc).
bool is_hole_cycle(std::string_view word);
void hole_cycle_stmt(PostState& s, const Statement& st);
void lathe_hole(PostState& s, const Statement& st, Point3 p);

// Mill-turn (millturn.cc): TDATA/TLDATA, APPLY/SET/MODE, ROTABL/ROTATE, SYNC.
void tdata_stmt(PostState& s, const Statement& st);
void apply_stmt(PostState& s, const Statement& st);
void rotabl_stmt(PostState& s, const Statement& st);
void sync_stmt(PostState& s, const Statement& st);
void channel_stmt(PostState& s, const Statement& st);

// A statement no handler knows: a warning and an NC comment, or an error with --strict.
void unknown_stmt(PostState& s, const Statement& st);
// A statement the reader could not read (Statement::problem) or with words before its major word
// (APT's `TLON,GOFWD/…`): an error for a `known` word or a modifier, else unknown_stmt.
void odd_statement(PostState& s, const Statement& st, bool known);

// Thread sequences (thread_statements.cc). A GOTO's point while a sequence is open.
void thread_goto(PostState& s, const Statement& st, const Point3& p);
// Whether statement `st` may stand inside the open sequence; false: reported, skip it. A
// single-pass thread ends at the first statement that is not a GOTO: it is cut here.
bool sequence_accepts(PostState& s, const Statement& st);
// The input ends: a single-pass thread is cut, an open THREAD/ON or COUPLE/ON is an error.
void end_sequences(PostState& s);

// FINI or the end of input (`at`: the FINI, or an empty statement at the file's last line): a
// single-pass thread is cut, open sequences reported, a live tool's milling ended
// (ToolPath::leave), the program end written (once).
void finish_program(PostState& s, const Statement& at);

// The ordinary move to `p` (motion.cc): rapid, feed or the arc of a CIRCLE/ before it.
void move_to(PostState& s, const Statement& st, const Point3& p);
// A GOTO in the lathe plane (the turning path's, a radial live tool's approach): on the frame's
// plane, a thread sequence's point while one is open, else the ordinary move.
inline void lathe_goto(PostState& s, const Statement& st, const Point3& p) {
  if (!frame_point(s, st, p)) return;
  if (s.thread.kind != ThreadSequence::Kind::kNone) return thread_goto(s, st, p);
  move_to(s, st, p);
}
// Verify's record of a motion to `to` (PostOptions::keep_motions): its end point and, when it
// changed, the state it is made with (motion.cc). `from_pos`: the motion starts where s.pos
// is (a GOTO), so it stays put when `to` is there; false for a hole's retract, which follows the
// hole's own moves.
void record_motion(PostState& s, const Statement& st, Vec2 to, bool rapid, bool from_pos = true);
// The last motion recorded, finished, to PostOptions::on_motion (when set), no longer kept.
void hand_over_motion(PostState& s);
// Verify's record of where a cycle of CL line `line` (a hole, a thread, an undercut) leaves the
// tool (ClMotion::exit), when PostOptions::keep_motions asks.
void record_exit(PostState& s, uint32_t line, Vec2 at, std::optional<double> hole_bottom = {},
                 uint32_t thread_cuts = 0);

}  // namespace clpost

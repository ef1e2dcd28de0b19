#pragma once
// The thread planner: pure functions from a thread description to a pass plan. No I/O.
#include <optional>
#include <string>
#include <string_view>
#include <vector>

#include "planner/run_in.h"
#include "planner/thread_plan.h"
#include "planner/thread_words.h"
#include "reader/statement.h"
#include "support/diagnostics.h"

namespace clpost {

// What the machine contributes to a plan.
struct PlannerSettings {
  int default_option = 0;          // OPTION when the CL gives none
  double default_tool_angle = 60;  // TLANGL when the CL gives none
  bool start_angle_word = false;   // multi-start by spindle start angle instead of offset
  bool variable_lead = false;      // the control can cut INCR/DECR (G34/G35)
  LeadLaw lead_law;                // threading.servo_time_constant, threading.lead_error
  bool add_run_in = false;         // threading.run_in auto: passes begin the run-in before P1
  std::string machine_name;        // for diagnostics
};

struct ThreadGoto {
  Vec2 point;
  SourceLoc loc;
  SavedLines lines;
};

// A THREAD/ON ... THREAD/OFF (or OP/THREAD ... OP/THREAD,NOMORE) sequence as read.
struct MultiThreadInput {
  ThreadWords words;      // parsed THREAD/ON parameters
  SavedLines on_lines;    // THREAD/ON statement, for diagnostics on its words
  SourceLoc on_loc;       // THREAD/ON major word
  PitchSpec modal_pitch;  // PITCH/ in force at THREAD/ON
  LengthUnit units = LengthUnit::kMm;
  Vec2 p0;  // tool position before THREAD/ON
  bool feed_approach = false;
  double rpm = 0;  // the spindle speed the thread is cut at (0: not known), for run_in.h
  std::vector<ThreadGoto> gotos;  // as read (2 or 3 is valid)
  SourceLoc off_loc;
  // How the statements are named in messages (the Pro/E form: "OP/THREAD", "OP/THREAD,NOMORE").
  std::string on_word = "THREAD/ON";
  std::string off_word = "THREAD/OFF";
};

// Plans a multi-pass thread (threading.md sections 4-8). Returns false (with diagnostics) on any
// error; `out` is then unspecified.
bool plan_multi_thread(const MultiThreadInput& in, const PlannerSettings& settings, ThreadPlan& out,
                       Diagnostics& diags);

// Most GOTOs of a chained thread (THREAD/ON,...,CHAIN): 20 segments.
inline constexpr size_t kMaxChainGotos = 21;

// Plans a chained multi-pass thread (threading.md section 11): `in.gotos` is the contour P1 ...
// Pk (2 to kMaxChainGotos; the interpreter keeps one more for the error). Form "chain", every
// pass the contour translated along the infeed, with its `path`. Returns false (with
// diagnostics) on any error.
bool plan_chain_thread(const MultiThreadInput& in, const PlannerSettings& settings, ThreadPlan& out,
                       Diagnostics& diags);

// A single-pass thread: THREAD/TURN|FACE|TAPER[,pitch couplets] and the GOTOs up to the next
// statement that is not a GOTO (exactly 2 are valid). Same as GOTO/start, COUPLE/ON, GOTO/end,
// COUPLE/OFF.
struct SingleThreadInput {
  SourceLoc loc;                     // THREAD major word
  SavedLines lines;                  // the THREAD/<kind> statement
  std::string word = "THREAD/TURN";  // for messages
  PitchSpec pitch;                   // in force: the modal PITCH/ with the statement's couplets
  LengthUnit units = LengthUnit::kMm;
  Vec2 p0;                        // tool position before the statement
  std::vector<ThreadGoto> gotos;  // as read
};

// Plans a single-pass thread: form "single", path {start, end}, one pass. Returns false (with
// diagnostics) on any error.
bool plan_single_thread(const SingleThreadInput& in, const PlannerSettings& settings,
                        ThreadPlan& out, Diagnostics& diags);

// A coupled sequence: COUPLE/ON[,pitch couplets] ... COUPLE/OFF (or the two GOTOs of a
// single-pass thread).
struct CoupleInput {
  SourceLoc loc;                   // COUPLE major word
  SavedLines lines;                // the COUPLE/ON statement
  std::string word = "COUPLE/ON";  // for messages
  std::string off_word = "COUPLE/OFF";
  PitchSpec pitch;  // in force: the modal PITCH/ with the statement's couplets
  LengthUnit units = LengthUnit::kMm;
  Vec2 start;                     // tool position at COUPLE/ON: where the first move starts
  std::vector<ThreadGoto> gotos;  // the synchronized moves, in order
};

// Plans a coupled sequence: form "couple", `path` = start and every GOTO, one pass per
// synchronized segment (a GOTO that does not move the tool is skipped with a warning). Returns
// false (with diagnostics) on any error. The same as CouplePlanner over `in.gotos`.
bool plan_couple(const CoupleInput& in, const PlannerSettings& settings, ThreadPlan& out,
                 Diagnostics& diags);

// A coupled sequence planned while it is read, so that memory stays flat however many GOTOs it
// has: begin() at COUPLE/ON, add() at every GOTO (the synchronized move to cut now), finish() at
// COUPLE/OFF. Single-pass threads are planned through it too.
class CouplePlanner {
 public:
  // The passes kept in the plan (for clpost plan and verify); the moves after them are cut and
  // counted (ThreadPlan::passes_not_kept) but not kept.
  static constexpr size_t kMaxKeptPasses = 10000;

  // `in` without its GOTOs: checks the pitch in force. False (reported): nothing can be cut.
  bool begin(const CoupleInput& in, const PlannerSettings& settings, Diagnostics& diags);
  // The synchronized move to `point` (a GOTO at `loc`, on line text `line`), or nullptr when it
  // does not move the tool (warned). The pointer is valid until the next call.
  const ThreadPass* add(Vec2 point, SourceLoc loc, std::string_view line, Diagnostics& diags);
  // The plan of the whole sequence. False (reported) when it had no synchronized move.
  bool finish(ThreadPlan& out, Diagnostics& diags);
  // The plan so far: pitch, lead and units from begin(), the path up to the last add().
  const ThreadPlan& plan() const { return plan_; }

 private:
  ThreadPlan plan_;
  SavedLines lines_;
  SourceLoc loc_;
  std::string word_;
  ThreadPass last_;
  Vec2 at_;
  size_t count_ = 0;
};

}  // namespace clpost

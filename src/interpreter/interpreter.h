#pragma once
// The interpreter: CL statements in, NC program out. It keeps the CL's modal state (units, feed,
// spindle, RAPID, CIRCLE, PITCH, thread sequences), maps the CL frame onto the lathe, and drives
// NcProgram and the machine's thread emitter. One Interpreter per file; no shared state.
#include <cmath>
#include <functional>
#include <memory>
#include <optional>
#include <string>
#include <vector>

#include "emitters/emitter.h"
#include "machine/machine.h"
#include "planner/planner.h"
#include "reader/statement.h"
#include "support/diagnostics.h"
#include "writer/nc_program.h"

namespace clpost {

struct PostOptions {
  bool strict = false;  // unknown statements are errors, not warnings
};

struct PostStats {
  size_t statements = 0;
  size_t motions = 0;
  size_t threads = 0;
  size_t passes = 0;
};

class Interpreter {
 public:
  Interpreter(const Machine& m, NcProgram& prog, Diagnostics& diags, const PostOptions& opts);
  ~Interpreter();

  void statement(const Statement& st);
  // End of input: closes the program, reports unterminated sequences and a missing FINI.
  void finish(uint32_t last_line);
  // The input is exhausted: like finish(), with a warning when FINI was missing.
  void end_of_input(uint32_t last_line);

  // Called with every thread plan (clpost plan).
  void on_thread(std::function<void(const ThreadPlan&)> cb) { on_thread_ = std::move(cb); }
  const PostStats& stats() const { return stats_; }
  LengthUnit units() const { return units_; }

 private:
  struct Circle {
    double cx, cy, cz, ax, ay, az, radius;
    SourceLoc loc;
  };
  struct Point3 {
    double x = 0, y = 0, z = 0;
  };
  enum class Seq { kNone, kMulti, kSingle, kCouple };

  // Statement handlers
  void units_stmt(const Statement& st);
  void goto_stmt(const Statement& st);
  void from_stmt(const Statement& st);
  void godlta_stmt(const Statement& st);
  void circle_stmt(const Statement& st);
  void fedrat_stmt(const Statement& st);
  void spindl_stmt(const Statement& st);
  void loadtl_stmt(const Statement& st, size_t first);
  void coolnt_stmt(const Statement& st);
  void cutcom_stmt(const Statement& st);
  void delay_stmt(const Statement& st);
  void pitch_stmt(const Statement& st);
  void thread_stmt(const Statement& st, size_t first);
  void couple_stmt(const Statement& st);
  void op_stmt(const Statement& st);
  void cycle_stmt(const Statement& st);
  void undercut_stmt(const Statement& st);  // CYCLE/UNDCUT (undercut.cc)
  void skipped(const Statement& st, std::string_view why);
  void unknown(const Statement& st);

  // Motion
  void move_to(const Statement& st, Point3 p);
  void thread_goto(const Statement& st, Point3 p);
  LathePoint lathe(Point3 p) const;
  Vec2 cl2(Point3 p) const;  // lathe frame in CL units: x radius, z axial
  void ensure_started();
  void end_sequence_errors(uint32_t line);
  void emit_thread(ThreadPlan& plan, const SavedLines& lines);
  bool check_pitch(const Statement& st, const PitchSpec& p);
  void single_pass_plan(ThreadPlan& plan);
  bool begin_thread_spindle(const ThreadPlan& plan, const SavedLines& lines);
  void end_thread_spindle();

  // Diagnostics helpers
  void error(const Statement& st, SourceLoc loc, std::string msg);
  void warning(const Statement& st, SourceLoc loc, std::string msg);
  void note_once(const Statement& st, std::string_view key, std::string msg);
  // Argument i as a number within ±kMaxValue: inline for the common case (every GOTO coordinate
  // comes here), the diagnostics out of line.
  bool number_arg(const Statement& st, size_t i, std::string_view what, double& out) {
    if (i < st.args.size() && st.args[i].is_number() && within_limits(st.args[i].number)) {
      out = st.args[i].number;
      return true;
    }
    return bad_number_arg(st, i, what);
  }
  bool bad_number_arg(const Statement& st, size_t i, std::string_view what);
  bool in_range(const Statement& st, const Arg& a, std::string_view what);
  static bool within_limits(double v) { return std::abs(v) <= kMaxValue; }  // NaN is not

 public:
  // The largest CL value (coordinate, feed, speed, time) that becomes an NC word: anything
  // larger is a units mistake or garbage, and would not fit an NC address anyway.
  static constexpr double kMaxValue = 1e6;

 private:
  const Machine& m_;
  NcProgram& prog_;
  Diagnostics& diags_;
  PostOptions opts_;
  PostStats stats_;
  std::unique_ptr<Emitter> emitter_;
  std::function<void(const ThreadPlan&)> on_thread_;

  LengthUnit units_;
  bool units_given_ = false;
  bool started_ = false;
  bool ended_ = false;  // FINI seen
  bool end_seen_ = false;
  std::string partno_;
  std::optional<Point3> pos_;
  bool rapid_next_ = false;
  std::optional<Circle> circle_;
  bool feed_given_ = false;
  FeedMode feed_mode_ = FeedMode::kPerMinute;
  double feed_ = 0;
  // Spindle as last programmed
  bool spindle_on_ = false;
  bool css_ = false;
  double spindle_value_ = 0;  // rpm or surface speed
  double css_max_rpm_ = 0;
  SpindleDir spindle_dir_ = SpindleDir::kCw;
  std::vector<std::string> noted_;  // words already noted once
  size_t y_warnings_ = 0;
  bool in_cycle_ = false;  // between an unsupported CYCLE/ and CYCLE/OFF
  int tool_offset_ = -1;   // offset of the last LOADTL (-1: no tool loaded yet)
  size_t axis_notes_ = 0;

  // Threading
  PitchSpec pitch_;
  Seq seq_ = Seq::kNone;
  SavedLines seq_lines_;
  SourceLoc seq_loc_;
  MultiThreadInput multi_;
  ThreadWords single_words_;
  std::vector<ThreadGoto> single_gotos_;
  ThreadPlan couple_;
  PlannerSettings planner_settings_;
  bool couple_started_ = false;
  bool multi_failed_ = false;  // THREAD/ON had an error: its sequence is read but not planned
  bool forced_rpm_ = false;    // CSS turned into G97 for the thread in progress
  double thread_rpm_ = 0;
  static constexpr size_t kMaxKeptPath = 10000;  // coupled moves kept for `clpost plan`
};

}  // namespace clpost

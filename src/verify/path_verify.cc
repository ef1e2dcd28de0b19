#include "verify/path_verify.h"

#include <fmt/format.h>

#include <array>
#include <cmath>
#include <cstdint>
#include <cstdio>
#include <type_traits>

#include "laws/cut_pass.h"
#include "laws/written_value.h"
#include "support/ring.h"

namespace clpost {

namespace {

bool near(Vec2 a, Vec2 b, double tol) {
  return std::fabs(a.x - b.x) <= tol && std::fabs(a.z - b.z) <= tol;
}

bool same_kind(const ClMotion& c, const Move& mv) {
  return c.rapid ? mv.kind == MoveKind::kRapid
                 : mv.kind == MoveKind::kFeed || mv.kind == MoveKind::kArcCw ||
                       mv.kind == MoveKind::kArcCcw;
}

// The program's moves in a window of the stream: moves[i] is move number `base + i`.
struct MoveWindow {
  Ring<PathStream::ProgramMove> moves;
  size_t base = 0;
  size_t size() const { return base + moves.size(); }  // one past the last move received
  const Move& operator[](size_t i) const { return moves[i - base].move; }
  const PathStream::ProgramMove& at(size_t i) const { return moves[i - base]; }
};

// The first move from `from` that ends at `c` (of its kind when `kind`), or moves.size().
size_t find_move(const MoveWindow& moves, size_t from, const ClMotion& c, double tol, bool kind) {
  for (size_t j = from; j < moves.size(); ++j)
    if (near(moves[j].to, c.to, tol) && (!kind || same_kind(c, moves[j]))) return j;
  return moves.size();
}

}  // namespace

// What the comparison needs and what it found.
struct PathStream::Check {
  Check(const Machine& machine, const VerifyOptions& o, const StateReadback& r, const LengthUnit& u,
        double tolerance)
      : m(machine),
        options(o),
        readback(r),
        units(&u),
        diags(o.plan_name),
        tol(tolerance),
        xs(diameter_factor(machine)) {}
  const Machine& m;
  VerifyOptions options;
  StateReadback readback;
  const LengthUnit* units;  // the program's, as read so far
  Diagnostics diags;        // the problems, handed to the program's at the end
  MoveWindow moves;
  size_t next = 0;  // the move the next CL motion is looked for from
  size_t motions = 0;
  double tol;
  double xs;  // X as the program writes it (2: diameters)
  size_t problems = 0;
  size_t arcs = 0;
  std::string first;
  // Each kind of state difference (tool, feed, spindle) as last reported, CL and program: a
  // difference is reported once, where it begins.
  std::pair<std::string, std::string> reported[3];
  // The last states compared (check_state) and whether tool, feed and spindle differ in them.
  bool compared = false;
  LengthUnit compared_units = LengthUnit::kMm;
  CutState cl_state, program_state;
  std::array<bool, 3> differs{};

  std::string at(const ClMotion& c) const {
    return fmt::format("{}:{}", options.plan_name, c.line);
  }
  std::string point(Vec2 p) const { return fmt::format("X{:.4f} Z{:.4f}", p.x * xs, p.z); }
  void problem(const Move* mv, const std::string& why) {
    if (problems++ == 0) first = why;
    diags.error(SourceLoc{mv ? static_cast<uint32_t>(mv->line) : 0, 1}, {}, why);
  }
};

namespace {

using Check = PathStream::Check;

std::string arc_name(const Machine& m, MoveKind k) {
  if (k == MoveKind::kArcCw) return fmt::format("a clockwise arc ({})", m.code("arc_cw"));
  if (k == MoveKind::kArcCcw) return fmt::format("a counter-clockwise arc ({})", m.code("arc_ccw"));
  return fmt::format("a straight line ({})", m.code("linear"));
}

// The arc (or straight feed) of CL motion `c` against the program's move `mv`.
void check_arc(Check& k, const ClMotion& c, const Move& mv) {
  if (c.rapid) return;
  const MoveKind want = c.arc == ArcSense::kCw    ? MoveKind::kArcCw
                        : c.arc == ArcSense::kCcw ? MoveKind::kArcCcw
                                                  : MoveKind::kFeed;
  if (want != MoveKind::kFeed) ++k.arcs;
  if (mv.kind != want)
    return k.problem(&mv, fmt::format("motion at {}: the CL cuts {} to {}, the program {}", k.at(c),
                                      arc_name(k.m, want), k.point(c.to), arc_name(k.m, mv.kind)));
  if (want != MoveKind::kFeed && !near(mv.center, c.center, k.tol))
    k.problem(&mv, fmt::format("arc at {}: the CL turns around {}, the program around {}", k.at(c),
                               k.point(c.center), k.point(mv.center)));
}

// `cl` as format `format` writes it in the program's units (`inch`) is `program`.
bool same_as_written(const Machine& m, std::string_view format, double cl, double program,
                     bool inch) {
  const NumberFormat f = m.format_for(format).in_units(inch);
  return std::fabs(as_read(f, cl) - program) <= least_increment(f) / 2 + 1e-9;
}

std::string tool_text(const CutState& s, const StateReadback& r) {
  if (s.tool < 0) return "no tool";
  return s.offset < 0 || !r.offset ? fmt::format("tool {}", s.tool)
                                   : fmt::format("tool {} offset {}", s.tool, s.offset);
}

std::string feed_text(const CutState& s, LengthUnit u) {
  const char* unit = u == LengthUnit::kInch ? "in" : "mm";
  if (s.feed <= 0) return "no feed";
  if (s.per_rev < 0) return fmt::format("{:g} with no feed mode", s.feed);
  return fmt::format("{:g} {}/{}", s.feed, unit, s.per_rev ? "rev" : "min");
}

std::string spindle_text(const CutState& s, LengthUnit u) {
  if (s.spindle == SpindleRun::kOff) return "stopped";
  const char* dir = s.spindle == SpindleRun::kCw ? "CW" : "CCW";
  if (!s.css) return fmt::format("{} at {:g} rpm", dir, s.speed);
  const std::string limit = s.max_rpm > 0 ? fmt::format(", limit {:g} rpm", s.max_rpm) : "";
  return fmt::format("{} at {:g} {}/min CSS{}", dir, s.speed, u == LengthUnit::kInch ? "ft" : "m",
                     limit);
}

bool same_tool(const StateReadback& r, const CutState& a, const CutState& b) {
  if (!r.tool || a.tool < 0) return true;
  return a.tool == b.tool && (!r.offset || a.offset < 0 || a.offset == b.offset);
}

bool same_feed(const Machine& m, const StateReadback& r, const CutState& a, const CutState& b,
               bool inch) {
  if (a.feed <= 0) return true;
  return same_as_written(m, "F", a.feed, b.feed, inch) &&
         (!r.feed_mode || a.per_rev < 0 || a.per_rev == b.per_rev);
}

bool same_spindle(const Machine& m, const StateReadback& r, const CutState& a, const CutState& b) {
  if (!r.spindle) return true;
  if (a.spindle != b.spindle) return false;
  if (a.spindle == SpindleRun::kOff) return true;
  if (r.css && a.css != b.css) return false;
  if (!same_as_written(m, "S", a.speed, b.speed, false)) return false;
  return !a.css || !r.max_rpm || a.max_rpm <= 0 ||
         same_as_written(m, "S", a.max_rpm, b.max_rpm, false);
}

// Feed, spindle and tool of CL motion `c` against the program's state at move `j`.
void check_state(Check& k, const PathStream::ClStep& c, size_t j) {
  const PathStream::ProgramMove& mv = k.moves.at(j);
  if (!c.known || !mv.known) return;
  const CutState& a = c.state.state;
  const CutState& b = mv.state;
  const StateReadback& r = k.readback;
  const LengthUnit u = *k.units;
  // The states change seldom: the comparison of the last pair is kept.
  if (!k.compared || k.compared_units != u || !(k.cl_state == a) || !(k.program_state == b)) {
    k.differs = {!same_tool(r, a, b), !same_feed(k.m, r, a, b, u == LengthUnit::kInch),
                 !same_spindle(k.m, r, a, b)};
    k.compared = true;
    k.compared_units = u;
    k.cl_state = a;
    k.program_state = b;
  }
  const std::array<bool, 3>& differs = k.differs;
  static constexpr const char* kWhat[3] = {"tool", "feed", "spindle"};
  const bool compared[3] = {true, !c.motion.rapid,
                            !c.motion.rapid};  // feed and spindle: where it cuts
  for (int i = 0; i < 3; ++i) {
    if (!compared[i]) continue;
    if (!differs[i]) {
      k.reported[i].first.clear();
      k.reported[i].second.clear();
      continue;
    }
    std::pair<std::string, std::string> texts =
        i == 0   ? std::pair{tool_text(a, r), tool_text(b, r)}
        : i == 1 ? std::pair{feed_text(a, u), feed_text(b, u)}
                 : std::pair{spindle_text(a, u), spindle_text(b, u)};
    if (k.reported[i] == texts) continue;
    const CutStateAt& at = c.state;
    const uint32_t set = i == 0 ? at.tool_line : i == 1 ? at.feed_line : at.spindle_line;
    k.problem(&mv.move, fmt::format("{} at {}: CL {} ({} at CL line {}), program {}", kWhat[i],
                                    k.at(c.motion), texts.first, set ? "set" : "in force",
                                    set ? set : at.line, texts.second));
    k.reported[i] = std::move(texts);
  }
}

// The end point of CL motion `c` from move `next` on: the matching move's index, or
// moves.size() (reported).
size_t check_end_point(Check& k, const MoveWindow& moves, size_t next, const ClMotion& c) {
  if (c.thread_cuts > 0) {
    // After the thread's synchronized cuts (a run of synchronized moves each): a cycle returns
    // to its exit point after every pass.
    uint32_t runs = 0;
    for (size_t i = next; i < moves.size() && runs < c.thread_cuts; ++i)
      if (moves[i].kind == MoveKind::kThread &&
          (i + 1 == moves.size() || moves[i + 1].kind != MoveKind::kThread) &&
          ++runs == c.thread_cuts)
        next = i + 1;
  }
  if (c.hole_bottom) {
    // After the feed that reaches the hole's bottom: the hole's own moves pass its exit point
    // on the way in (its R plane may be there).
    ClMotion bottom = c;
    bottom.to = {0, *c.hole_bottom};
    bottom.rapid = false;
    const size_t b = find_move(moves, next, bottom, k.tol, true);
    if (b < moves.size()) next = b + 1;
  }
  const size_t j = find_move(moves, next, c, k.tol, !c.exit);
  if (j < moves.size()) return j;
  const size_t other = find_move(moves, next, c, k.tol, false);
  // Where the program goes elsewhere: its next move (else its last).
  const Move* mv = other < moves.size()  ? &moves[other]
                   : next < moves.size() ? &moves[next]
                   : next > 0            ? &moves[next - 1]
                                         : nullptr;
  if (other < moves.size()) {
    k.problem(mv,
              fmt::format("motion at {}: {} is reached by a {} move, the CL {} there", k.at(c),
                          k.point(c.to), moves[other].kind == MoveKind::kRapid ? "rapid" : "feed",
                          c.rapid ? "rapids" : "cuts"));
  } else {
    k.problem(mv, fmt::format("motion at {}: {} is not reached by the program in order", k.at(c),
                              k.point(c.to)));
  }
  return other;
}

// What the program's words do not let verify compare, said in the report.
std::string not_compared(const StateReadback& r) {
  std::string out;
  const auto add = [&out](bool readable, std::string_view what) {
    if (!readable) out += fmt::format("{}{}", out.empty() ? "; not compared: " : ", ", what);
  };
  add(r.tool, "the tool (template tool_change has no {tool} word to read)");
  add(!r.tool || r.offset, "the offset (template tool_change has no {offset})");
  add(r.feed_mode, "the feed mode (codes feed_per_min, feed_per_rev)");
  add(r.spindle, "the spindle (codes spindle_cw/ccw, templates spindle_rpm, spindle_stop)");
  add(!r.spindle || r.css, "RPM or CSS (template spindle_css's speed line has no code)");
  add(!r.css || r.max_rpm, "the CSS limit");
  return out;
}

// CL motion `c` against the program's moves from k.next on.
void check_motion(Check& k, const PathStream::ClStep& step) {
  const ClMotion& c = step.motion;
  const MoveWindow& moves = k.moves;
  ++k.motions;
  // A motion to where the tool already is moves nothing, and a program need not write it (a
  // full circle does move): it is the program's next move only when that one ends there.
  if (c.stays && c.arc == ArcSense::kNone) {
    if (k.next < moves.size() && near(moves[k.next].to, c.to, k.tol) && same_kind(c, moves[k.next]))
      check_state(k, step, k.next++);
    return;
  }
  const size_t j = check_end_point(k, moves, k.next, c);
  if (j >= moves.size()) return;
  k.next = j + 1;
  if (!c.exit && same_kind(c, moves[j])) check_arc(k, c, moves[j]);
  check_state(k, step, j);
}

}  // namespace

PathStream::PathStream(const Machine& m, const VerifyOptions& options,
                       const StateReadback& readback, const LengthUnit& units, size_t window)
    : window_(window) {
  shown_ = options.tolerance > 0 ? options.tolerance : cut_tolerance(m);
  k_ = std::make_unique<Check>(m, options, readback, units, shown_ + 1e-9);
  if (window == SIZE_MAX) return;
  // A window of CL motions; the moves from the one before the next motion's to a window past
  // it, and the one just come.
  cl_ = Ring<ClStep>(window);
  k_->moves.moves = Ring<ProgramMove>(window + 2);
}

PathStream::~PathStream() {
  if (spill_ != nullptr) std::fclose(spill_);
}

static_assert(std::is_trivially_copyable_v<PathStream::ClStep>, "spilled as bytes");

namespace {

// Spilled CL motions from number `at` on: `batch` (its size) read from `f`, or written to it.
bool read_spill(std::FILE* f, size_t at, std::vector<PathStream::ClStep>& batch) {
  using Step = PathStream::ClStep;
  return std::fseek(f, static_cast<long>(at * sizeof(Step)), SEEK_SET) == 0 &&
         std::fread(batch.data(), sizeof(Step), batch.size(), f) == batch.size();
}
bool write_spill(std::FILE* f, size_t at, const std::vector<PathStream::ClStep>& batch) {
  using Step = PathStream::ClStep;
  return std::fseek(f, static_cast<long>(at * sizeof(Step)), SEEK_SET) == 0 &&
         std::fwrite(batch.data(), sizeof(Step), batch.size(), f) == batch.size();
}

}  // namespace

// A CL motion in order: in memory while the window has room and nothing waits on disk, else
// on disk (a program that is written after the whole post, behind its header, comes after
// every CL motion).
void PathStream::queue(const ClStep& step) {
  if (window_ == SIZE_MAX ||
      (cl_.size() < window_ && spill_read_ == spill_written_ && spill_buffer_.empty())) {
    cl_.push_back(step);
    return;
  }
  spill_buffer_.push_back(step);
  if (spill_buffer_.size() < kSpillBatch) return;
  if (spill_ == nullptr) spill_ = std::tmpfile();
  if (spill_ == nullptr) return;  // no temporary file: they wait in memory
  if (!write_spill(spill_, spill_written_, spill_buffer_)) return;  // they wait in memory
  spill_written_ += spill_buffer_.size();
  spill_buffer_.clear();
}

// The CL motions waiting on disk, then in the buffer, back in order.
void PathStream::refill() {
  if (spill_read_ < spill_written_) {
    std::vector<ClStep> batch(std::min(kSpillBatch, spill_written_ - spill_read_));
    if (read_spill(spill_, spill_read_, batch)) {
      spill_read_ += batch.size();
      for (const ClStep& step : batch) cl_.push_back(step);
      return;
    }
    spill_read_ = spill_written_;  // unreadable: those motions are lost, not compared
  }
  for (const ClStep& step : spill_buffer_) cl_.push_back(step);
  spill_buffer_.clear();
}

void PathStream::take_over(const PathStream& o) {
  const LengthUnit* units = k_->units;
  k_ = std::make_unique<Check>(*o.k_);
  k_->units = units;
  window_ = o.window_;
  shown_ = o.shown_;
  cl_ = o.cl_;
  if (spill_ != nullptr) std::fclose(spill_);
  spill_ = nullptr;
  spill_read_ = spill_written_ = 0;
  spill_buffer_.clear();
  // o's motions on disk into a file of its own, a batch at a time; what cannot be written
  // waits in memory, in order, before o's buffer.
  std::vector<ClStep> batch;
  for (size_t at = o.spill_read_; at < o.spill_written_; at += batch.size()) {
    batch.resize(std::min(kSpillBatch, o.spill_written_ - at));
    if (!read_spill(o.spill_, at, batch)) break;  // unreadable: lost, as refill() loses them
    if (spill_buffer_.empty() && spill_ == nullptr) spill_ = std::tmpfile();
    if (spill_buffer_.empty() && spill_ != nullptr && write_spill(spill_, spill_written_, batch)) {
      spill_written_ += batch.size();
    } else {
      spill_buffer_.insert(spill_buffer_.end(), batch.begin(), batch.end());
    }
  }
  spill_buffer_.insert(spill_buffer_.end(), o.spill_buffer_.begin(), o.spill_buffer_.end());
}

void PathStream::cl_motion(const ClMotion& c, const CutStateAt* state) {
  queue({c, state ? *state : CutStateAt{}, state != nullptr});
  advance(false);
}

void PathStream::program_move(const Move& mv, const CutState* state) {
  // A live tool's milling is the milling check's (MillStream): it would fill the window between
  // two lathe motions of the CL however long the milling between them is.
  if (mv.mill) return;
  k_->moves.moves.push_back({mv, state ? *state : CutState{}, state != nullptr});
  advance(false);
}

// The CL motions waiting whose window of program moves has come (all of them at the end), and
// the moves no motion can reach any more let go: the one before the next is kept (a problem
// may be reported at it).
void PathStream::advance(bool at_end) {
  MoveWindow& w = k_->moves;
  while (!cl_.empty() && (at_end || w.size() - std::min(w.size(), k_->next) >= window_)) {
    check_motion(*k_, cl_.front());
    cl_.pop_front();
    if (cl_.empty()) refill();
  }
  while (w.base + 1 < k_->next && !w.moves.empty()) {
    w.moves.pop_front();
    ++w.base;
  }
}

PathReport PathStream::finish(size_t cl_states, Diagnostics& nc_diags) {
  advance(true);
  Check& k = *k_;
  // The problems in order, after the ones found before (the threads', the holes').
  for (const Diagnostic& d : k.diags.kept()) nc_diags.add(d.severity, d.loc, {}, d.message);
  for (size_t i = 0; i < k.diags.dropped(); ++i) nc_diags.error({}, {}, {});  // counted only
  PathReport r;
  if (k.motions == 0) return r;
  r.problems = k.problems;
  r.text = k.problems == 0
               ? fmt::format(
                     "motions: {} CL end points, every one reached in order, within {:g}; {} "
                     "arc{} by {} centre; feed, spindle and tool as the CL ({} states){}\n",
                     k.motions, shown_, k.arcs, k.arcs == 1 ? "" : "s",
                     k.arcs == 1 ? "its" : "their", cl_states, not_compared(k.readback))
               : fmt::format("FAILED: {} difference{} over {} CL motions; the first: {}\n",
                             k.problems, k.problems == 1 ? "" : "s", k.motions, k.first);
  return r;
}

PathReport verify_path(const ClPath& cl, const Toolpath& path, const Machine& m,
                       const VerifyOptions& options, Diagnostics& nc_diags) {
  if (cl.motions.empty()) return {};
  PathStream ps(m, options, path.readback, path.units, SIZE_MAX);
  const auto state_of = [&](uint32_t i) {
    return i < path.states.size() ? &path.states[i].state : nullptr;
  };
  size_t e = 0;  // every move in order, the entries from an unknown position among them
  for (size_t i = 0; i <= path.moves.size(); ++i) {
    for (; e < path.entries.size() && path.entries[e].before == i; ++e)
      ps.program_move(path.entries[e].move, state_of(path.entries[e].move.state));
    if (i < path.moves.size()) ps.program_move(path.moves[i], state_of(path.moves[i].state));
  }
  for (const ClMotion& c : cl.motions)
    ps.cl_motion(c, c.state < cl.states.size() ? &cl.states[c.state] : nullptr);
  return ps.finish(cl.states.size(), nc_diags);
}

}  // namespace clpost

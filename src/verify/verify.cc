#include "verify/verify.h"

#include <fmt/format.h>

#include <algorithm>
#include <cmath>
#include <map>

#include "laws/cut_pass.h"
#include "laws/written_value.h"
#include "support/vec2_math.h"
#include "verify/cut_alignment.h"
#include "verify/expected_cuts.h"

namespace clpost {

using namespace vec2_math;

namespace {

// A thread's frame: u along the cut (P1 toward P2), n into the material (depth grows along n).
struct Frame {
  Vec2 u{0, -1};
  Vec2 n{-1, 0};
  double turns = 1;  // revolutions over the thread's length
};

Frame frame_of(const ThreadPlan& plan) {
  Frame f;
  Vec2 d = plan.p2 - plan.p1;
  if (plan.form != ThreadForm::kMulti && plan.path.size() >= 2)
    d = plan.path.back() - plan.path.front();
  const double len = length(d);
  if (len > 0) f.u = (1 / len) * d;
  f.n = {-f.u.z, f.u.x};
  const ThreadPass* deepest = nullptr;
  for (const ThreadPass& p : plan.passes)
    if (deepest == nullptr || p.depth > deepest->depth) deepest = &p;
  if (deepest != nullptr && deepest->depth > 0) {
    if (dot(deepest->to - plan.p1, f.n) < 0) f.n = -f.n;
  } else if ((plan.side == ThreadSide::kExternal) == (f.n.x > 0)) {
    f.n = -f.n;
  }
  f.turns = thread_turns(plan);
  return f;
}

// Consecutive synchronized blocks are one continuous cut on the control (G33 is modal), so a
// coupled or single-pass thread that begins where the one before it ended, with no move
// between, is cut as part of that one. The program's cut is split where such a thread of the
// plan begins, so each is compared with its own.
// `origin` (when given): for each cut returned, the index in `cuts` of the cut it comes from.
std::vector<NcCut> split_at_path_starts(const std::vector<NcCut>& cuts,
                                        const std::vector<ExpectedCut>& expected, double tol,
                                        std::vector<size_t>* origin = nullptr) {
  std::vector<Vec2> starts;  // where the plan's coupled and single-pass threads begin
  for (const ExpectedCut& e : expected)
    if (e.path) starts.push_back(e.from);
  const auto starts_at = [&](Vec2 p) {
    return std::any_of(starts.begin(), starts.end(), [&](Vec2 s) {
      return std::fabs(s.x - p.x) <= tol && std::fabs(s.z - p.z) <= tol;
    });
  };
  std::vector<NcCut> out;
  out.reserve(cuts.size());
  for (const NcCut& c : cuts) {
    // The pieces since the last resize come from the cut before this one.
    if (origin != nullptr && !out.empty())
      origin->resize(out.size(), static_cast<size_t>(&c - cuts.data()) - 1);
    size_t begin = 0;  // the chain index the piece being built starts at
    for (size_t k = 0; c.call < 0 && !starts.empty() && k + 1 < c.chain.size(); ++k) {
      if (!starts_at(c.chain[k])) continue;
      NcCut head = c;
      if (begin > 0) head.from = c.chain[begin - 1];
      head.chain.assign(c.chain.begin() + static_cast<long>(begin),
                        c.chain.begin() + static_cast<long>(k) + 1);
      head.to = head.chain.front();
      head.end = head.chain.back();
      head.linear_pullout.reset();
      out.push_back(std::move(head));
      begin = k + 1;
    }
    if (begin == 0) {
      out.push_back(c);
      continue;
    }
    NcCut rest = c;
    rest.from = c.chain[begin - 1];
    rest.chain.assign(c.chain.begin() + static_cast<long>(begin), c.chain.end());
    rest.to = rest.chain.front();
    out.push_back(std::move(rest));
  }
  if (origin != nullptr) origin->resize(out.size(), cuts.size() - 1);
  return out;
}

// The program's cuts in the plan's order: a cycle that cuts start by start (CYCLE99 with NUMTH,
// Haas G76 once per start) is put back in the plan's order, pass by pass and start by start
// within a pass, so the comparison sees the same sequence.
std::vector<size_t> cutting_order(const std::vector<NcCut>& cuts) {
  struct Group {
    size_t begin, end;  // [begin, end) in cuts
  };
  std::vector<Group> groups;
  for (size_t i = 0; i < cuts.size();) {
    size_t j = i + 1;
    if (cuts[i].call >= 0)
      while (j < cuts.size() && cuts[j].call == cuts[i].call) ++j;
    groups.push_back({i, j});
    i = j;
  }
  auto same_shape = [&](const Group& a, const Group& b) {
    const NcCut& x = cuts[a.begin];
    const NcCut& y = cuts[b.begin];
    return x.call >= 0 && y.call >= 0 && a.end - a.begin == b.end - b.begin &&
           x.source == y.source && x.lead == y.lead && x.start_angle && y.start_angle &&
           *x.start_angle != *y.start_angle && x.from.x == y.from.x;
  };
  std::vector<size_t> order;
  for (size_t g = 0; g < groups.size();) {
    size_t h = g + 1;
    while (h < groups.size() && same_shape(groups[g], groups[h])) ++h;
    // Each cut's rank within its start (its call's start, or its call when one call is one
    // start); a stable sort by rank keeps the starts in the order they were cut.
    struct Key {
      size_t rank;
      size_t index;
    };
    std::vector<Key> keys;
    for (size_t k = g; k < h; ++k) {
      std::map<int, size_t> rank;
      for (size_t i = groups[k].begin; i < groups[k].end; ++i)
        keys.push_back({rank[cuts[i].start]++, i});
    }
    std::stable_sort(keys.begin(), keys.end(),
                     [](const Key& a, const Key& b) { return a.rank < b.rank; });
    for (const Key& k : keys) order.push_back(k.index);
    g = h;
  }
  return order;
}

double angle_diff(double a, double b) {
  double d = std::fmod(std::fabs(a - b), 360.0);
  return std::min(d, 360 - d);
}

struct Compared {
  int cost = 0;         // 0 same, 1 the same cut with different numbers, 2 unrelated
  std::string why;      // cost 1: the first difference, with the numbers
  double accepted = 0;  // a fixed pass end accepted (threading.accept_pass_end): how far
};

// `r` becomes a difference of the same cut (cost 1); `why` formats it, only when `explain`.
template <typename Why>
Compared& differ(Compared& r, bool explain, Why&& why) {
  r.cost = 1;
  if (explain) r.why = why();
  return r;
}

class Comparer {
 public:
  Comparer(const std::vector<ThreadPlan>& plans, const Machine& m, double tol)
      : plans_(plans), m_(m), tol_(tol), limit_(tol + 1e-9) {
    for (const ThreadPlan& p : plans) frames_.push_back(frame_of(p));
  }

  std::string point(Vec2 v) const {
    return fmt::format("X{:.4f} Z{:.4f}", diameter_factor(m_) * v.x, v.z);
  }

  // The cut's depth and shift in the plan's frame, relative to the pass it stands for.
  SectionPass measure(const ExpectedCut& e, const NcCut& c) const {
    const Frame& f = frames_[e.thread];
    SectionPass s;
    s.n = e.pass;
    s.start = e.start;
    s.kind = e.kind;
    s.depth = e.depth + dot(c.to - e.to, f.n);
    s.shift = e.shift + dot(c.from - e.from, f.u);
    return s;
  }

  // `explain`: spell out the difference (the alignment asks only for the cost, once per cell of
  // its band, so it must not format text).
  Compared compare(const ExpectedCut& e, const NcCut& c, bool explain = true) const {
    const ThreadPlan& plan = plans_[e.thread];
    if (plan.lead <= 0 || std::fabs(c.lead - plan.lead) > 0.05 * plan.lead) {
      Compared r;
      r.cost = 2;
      if (explain) r.why = fmt::format("lead {:.6g}, plan {:.6g}", c.lead, plan.lead);
      return r;
    }
    Compared r = compare_lead(e, c, explain);
    if (r.cost != 0) return r;
    if (plan.form != ThreadForm::kMulti) return compare_path(e, c, explain);
    r = compare_pass(e, c, explain);
    if (r.cost != 0) return r;
    return compare_pass_ends(e, c, explain);
  }

 private:
  // The lead over the thread's turns, its change, the start and its angle: every form.
  Compared compare_lead(const ExpectedCut& e, const NcCut& c, bool explain) const {
    const ThreadPlan& plan = plans_[e.thread];
    const Frame& f = frames_[e.thread];
    Compared r;
    if (std::fabs(c.lead - plan.lead) * f.turns > limit_)
      return differ(r, explain, [&] {
        return fmt::format(
            "lead {:.6f}, plan {:.6f}: {:.4f} off over the thread's {:.1f} "
            "turns (tolerance {:g})",
            c.lead, plan.lead, std::fabs(c.lead - plan.lead) * f.turns, f.turns, tol_);
      });
    if (std::fabs(c.lead_change - plan.pitch.lead_change) > 1e-9)
      return differ(r, explain, [&] {
        return fmt::format("lead change {:g} per revolution, plan {:g}", c.lead_change,
                           plan.pitch.lead_change);
      });
    if (plan.pitch.starts > 1 && c.start >= 0 && c.start != e.start)
      return differ(r, explain, [&] {
        return fmt::format("start {}, plan start {}", c.start + 1, e.start + 1);
      });
    if (c.start_angle) {
      const double want = plan.starts_by_angle ? e.start_angle : 0;
      if (angle_diff(*c.start_angle, want) > 0.01)
        return differ(r, explain, [&] {
          return fmt::format("start angle {:g} deg, plan {:g} deg", *c.start_angle, want);
        });
    }
    return r;
  }

  // A thread cut along its path (single-pass, coupled, chained): the path's points one by one,
  // then a chain's linear pull-out.
  Compared compare_path(const ExpectedCut& e, const NcCut& c, bool explain) const {
    const ThreadPlan& plan = plans_[e.thread];
    Compared r;
    if (length(c.from - e.from) > limit_)
      return differ(r, explain, [&] {
        return fmt::format("starts at {}, plan {} (tolerance {:g})", point(c.from), point(e.from),
                           tol_);
      });
    for (size_t i = 0; i < std::min(c.chain.size(), e.chain.size()); ++i)
      if (length(c.chain[i] - e.chain[i]) > limit_)
        return differ(r, explain, [&] {
          return fmt::format("move {} ends at {}, plan {} (tolerance {:g})", i + 1,
                             point(c.chain[i]), point(e.chain[i]), tol_);
        });
    if (c.chain.size() != e.chain.size())
      return differ(r, explain, [&] {
        return fmt::format("{} synchronized moves, plan {}", c.chain.size(), e.chain.size());
      });
    if (plan.form == ThreadForm::kChain && plan.pullout && plan.pullout_linear &&
        (!c.linear_pullout || length(*c.linear_pullout - e.end) > limit_))
      return differ(r, explain, [&] {
        return fmt::format("pull-out ends at {}, plan {} (tolerance {:g})",
                           c.linear_pullout ? point(*c.linear_pullout) : "(none)", point(e.end),
                           tol_);
      });
    return r;
  }

  // One pass of a multi-pass thread: its depth and shift in the plan's frame, where it starts.
  Compared compare_pass(const ExpectedCut& e, const NcCut& c, bool explain) const {
    Compared r;
    const SectionPass at = measure(e, c);
    const double depth = at.depth;
    if (std::fabs(depth - e.depth) > limit_)
      return differ(r, explain, [&] {
        return fmt::format("depth {:.4f}, plan {:.4f} (tolerance {:g})", depth, e.depth, tol_);
      });
    const double shift = at.shift;
    if (std::fabs(shift - e.shift) > limit_)
      return differ(r, explain, [&] {
        return fmt::format("shift {:.4f}, plan {:.4f} (tolerance {:g})", shift, e.shift, tol_);
      });
    if (length(c.from - e.from) > limit_)
      return differ(r, explain, [&] {
        return fmt::format("starts at {}, plan {} (tolerance {:g})", point(c.from), point(e.from),
                           tol_);
      });
    return r;
  }

  // Where a pass of a multi-pass thread ends, and its pull-out. A cycle that ends every pass at
  // a fixed Z is accepted off the plan's end along the thread (threading.accept_pass_end), by
  // how far `accepted` says; the distance is kept when the pull-out then differs.
  Compared compare_pass_ends(const ExpectedCut& e, const NcCut& c, bool explain) const {
    const Frame& f = frames_[e.thread];
    Compared r;
    const bool accept_end = c.fixed_end && m_.accept_pass_end;
    if (length(c.to - e.to) > limit_) {
      if (!accept_end || std::fabs(dot(c.to - e.to, f.n)) > limit_)
        return differ(r, explain, [&] {
          return fmt::format("ends at {}, plan {} (tolerance {:g})", point(c.to), point(e.to),
                             tol_);
        });
      r.accepted = std::max(r.accepted, std::fabs(dot(c.to - e.to, f.u)));
    }
    // A pull-out cut with G1 (chamfer angle outside the G33 range) ends after the cut.
    const bool planned_pullout = length(e.end - e.to) > 0;
    const Vec2 end =
        planned_pullout && c.chain.size() == 1 && c.linear_pullout ? *c.linear_pullout : c.end;
    if (length(end - e.end) > limit_) {
      if (!accept_end || std::fabs(dot(end - e.end, f.n)) > limit_)
        return differ(r, explain, [&] {
          return fmt::format("pull-out ends at {}, plan {} (tolerance {:g})", point(end),
                             point(e.end), tol_);
        });
      r.accepted = std::max(r.accepted, std::fabs(dot(end - e.end, f.u)));
    }
    return r;
  }

  const std::vector<ThreadPlan>& plans_;
  const Machine& m_;
  double tol_;    // as given, for the messages
  double limit_;  // differences up to it are equal: the tolerance, and rounding
  std::vector<Frame> frames_;
};

std::string pass_name(const ThreadPlan& plan, const ExpectedCut& e) {
  if (plan.form != ThreadForm::kMulti && plan.form != ThreadForm::kChain)
    return "its synchronized path";
  return plan.pitch.starts > 1 ? fmt::format("pass {} (start {})", e.pass, e.start + 1)
                               : fmt::format("pass {}", e.pass);
}

// What verify_cuts gathers for one thread while it goes through the alignment.
struct ThreadAccumulator {
  ThreadVerdict verdict;
  uint32_t first_line = 0;  // NC lines of the program cuts matched to the thread (0: none)
  uint32_t last_line = 0;
  std::vector<std::string> sources;  // the blocks that cut it ("G76", "G33"), first seen first
  double accepted = 0;               // the farthest pass end accepted (threading.accept_pass_end)
};

// The alignment of the plan's passes with the program's cuts, gone through pair by pair.
struct Walk {
  const std::vector<ThreadPlan>& plans;
  const std::vector<ExpectedCut>& expected;
  const std::vector<NcCut>& cuts;
  const std::vector<size_t>& order;  // the program's cuts in the plan's order
  const std::vector<AlignedPair>& pairs;
  const Comparer& cmp;
  const VerifyOptions& options;
  Diagnostics& nc_diags;
  std::vector<ThreadAccumulator> threads{};  // one per plan
  size_t problems = 0;
  // The thread an unmatched program cut is reported with: the last thread seen, else the next.
  size_t last_thread = 0;
  const NcCut* last_cut = nullptr;
  // Threads were compared before these (ThreadStream): the pair before the first was a cut.
  bool continued = false;
};

// The program cut at index `b` of the alignment; null for none (-1).
const NcCut* program_cut(const Walk& w, long b) {
  return b >= 0 ? &w.cuts[w.order[static_cast<size_t>(b)]] : nullptr;
}

// A problem of thread `t`, in its verdict and as an error at the NC block `at` (none: null).
void problem(Walk& w, size_t t, const NcCut* at, std::string message) {
  w.threads[t].verdict.problems.push_back(message);
  ++w.problems;
  w.nc_diags.error(
      SourceLoc{at ? at->line : 0, at ? 1u : 0u}, at ? at->line_text : "",
      fmt::format("thread at {}:{}: {}", w.options.plan_name, w.plans[t].loc.line, message));
}

// A pass the program cuts: compared, and counted in its thread's NC lines, blocks and accepted
// pass ends.
void matched_cut(Walk& w, const ExpectedCut& e, const NcCut& c) {
  ThreadAccumulator& a = w.threads[e.thread];
  ++a.verdict.cut;
  a.first_line = a.first_line == 0 ? c.line : std::min(a.first_line, c.line);
  a.last_line = std::max(a.last_line, c.line);
  if (std::find(a.sources.begin(), a.sources.end(), c.source) == a.sources.end())
    a.sources.push_back(c.source);
  const Compared r = w.cmp.compare(e, c);
  if (w.plans[e.thread].form == ThreadForm::kMulti)
    a.verdict.program_passes.push_back(w.cmp.measure(e, c));
  a.accepted = std::max(a.accepted, r.accepted);
  if (r.cost != 0)
    problem(w, e.thread, &c, fmt::format("{}: {}", pass_name(w.plans[e.thread], e), r.why));
}

// A pass the program does not cut (pair `k`): named at the block after which it should have been
// cut.
void missing_cut(Walk& w, size_t k, const ExpectedCut& e) {
  const NcCut* near = w.last_cut;
  for (size_t q = k + 1; near == nullptr && q < w.pairs.size(); ++q)
    near = program_cut(w, w.pairs[q].b);
  problem(w, e.thread, near,
          fmt::format("{} (depth {:.4f}, from {}) is not cut by the program",
                      pass_name(w.plans[e.thread], e), e.depth, w.cmp.point(e.from)));
}

// A program cut the plan does not have (pair `k`): reported with the last thread seen, else the
// next; without a plan, on its own.
void extra_cut(Walk& w, size_t k, const NcCut& c) {
  size_t t = w.last_thread;
  if (k == 0 ? !w.continued : w.pairs[k - 1].a < 0)
    for (size_t q = k + 1; q < w.pairs.size(); ++q)
      if (w.pairs[q].a >= 0) {
        if (w.last_cut == nullptr) t = w.expected[static_cast<size_t>(w.pairs[q].a)].thread;
        break;
      }
  if (w.plans.empty()) {
    ++w.problems;
    w.nc_diags.error(SourceLoc{c.line, 1}, c.line_text,
                     fmt::format("{} cuts a thread (from {} to {}) that the plan does not have",
                                 c.source, w.cmp.point(c.from), w.cmp.point(c.to)));
  } else {
    problem(w, t, &c,
            fmt::format("the program cuts a pass the plan does not have: {} from {} to {}",
                        c.source, w.cmp.point(c.from), w.cmp.point(c.to)));
  }
}

// Pair `k`: a pass the program cuts, a pass it does not cut, or a cut the plan does not have.
void walk_pair(Walk& w, size_t k) {
  const AlignedPair& p = w.pairs[k];
  const ExpectedCut* e = p.a >= 0 ? &w.expected[static_cast<size_t>(p.a)] : nullptr;
  const NcCut* c = program_cut(w, p.b);
  if (e != nullptr) w.last_thread = e->thread;
  if (e != nullptr && c != nullptr) {
    matched_cut(w, *e, *c);
    w.last_cut = c;
  } else if (e != nullptr) {
    missing_cut(w, k, *e);
  } else if (c != nullptr) {
    extra_cut(w, k, *c);
    w.last_cut = c;
  }
}

// The thread's verdict, finished: how the program cuts it, the pass ends accepted.
ThreadVerdict verdict_of(ThreadAccumulator& a) {
  ThreadVerdict& v = a.verdict;
  std::string src;
  for (const std::string& s : a.sources) src += (src.empty() ? "" : ", ") + s;
  if (a.first_line == 0) {
    v.how = "not cut";
  } else if (a.first_line == a.last_line) {
    v.how = fmt::format("{}, NC line {}", src, a.first_line);
  } else {
    v.how = fmt::format("{}, NC lines {}-{}", src, a.first_line, a.last_line);
  }
  if (a.accepted > 0)
    v.notes.push_back(fmt::format(
        "passes end up to {:.4f} from the plan's ends along the thread: the cycle ends every "
        "pass at its Z (threading.accept_pass_end)",
        a.accepted));
  return std::move(v);
}

// The alignment of `plans` (all of them, or ThreadStream's window) with the program's cuts.
struct Window {
  std::vector<ExpectedCut> expected;
  std::vector<size_t> origin;  // for each cut, the index in the program's cuts it comes from
  std::vector<NcCut> cuts;
  std::vector<size_t> order;  // the cuts in the plan's order
  std::vector<AlignedPair> pairs;
};

// `align`: the pairs too (else only the cuts, split and in the plan's order).
void align_window(const std::vector<ThreadPlan>& plans, const std::vector<NcCut>& program,
                  const Comparer& cmp, double tol, Window& w, bool align = true) {
  w.expected = expected_cuts(plans);
  w.cuts = split_at_path_starts(program, w.expected, tol, &w.origin);
  w.order = cutting_order(w.cuts);
  if (!align) return;
  w.pairs = align_sequences(w.expected.size(), w.order.size(), [&](size_t i, size_t j) {
    return cmp.compare(w.expected[i], w.cuts[w.order[j]], false).cost;
  });
}

// Walks pairs [0, end) of the window; the verdicts of its first `threads` threads.
std::vector<ThreadVerdict> walk_window(Walk& w, size_t end, size_t threads) {
  w.threads.resize(threads);
  for (size_t t = 0; t < threads; ++t) w.threads[t].verdict.plan = t;
  for (const ExpectedCut& e : w.expected)
    if (e.thread < threads) ++w.threads[e.thread].verdict.planned;
  for (size_t k = 0; k < end; ++k) walk_pair(w, k);
  std::vector<ThreadVerdict> out;
  for (ThreadAccumulator& a : w.threads) out.push_back(verdict_of(a));
  return out;
}

std::string report_header(const std::string& program_name, const Machine& m,
                          const VerifyOptions& options, size_t threads, size_t planned,
                          size_t cut) {
  return fmt::format("verify {} on {} against {}: {} threads, {} passes planned, {} cut\n",
                     program_name, m.name, options.plan_name, threads, planned, cut);
}

std::string thread_lines(const ThreadVerdict& v, const ThreadPlan& p,
                         const VerifyOptions& options) {
  std::string out =
      fmt::format("  {}:{:<5} {:>3} passes  {:<6} {}\n", options.plan_name, p.loc.line, v.planned,
                  v.problems.empty() ? "ok" : "DIFFERS", v.how);
  for (const std::string& n : v.notes) out += fmt::format("      note: {}\n", n);
  for (const std::string& pr : v.problems) out += fmt::format("      {}\n", pr);
  return out;
}

std::string report_verdict(size_t problems, double tolerance, bool mm) {
  const char* unit = mm ? "mm" : "in";
  if (problems == 0)
    return fmt::format("ok: every pass is cut as planned, within {:g} {}\n", tolerance, unit);
  return fmt::format("FAILED: {} difference{} beyond {:g} {}\n", problems, problems == 1 ? "" : "s",
                     tolerance, unit);
}

}  // namespace

bool verify_cuts(const std::vector<ThreadPlan>& plans, const Simulation& sim, const Machine& m,
                 const VerifyOptions& options, Diagnostics& nc_diags, VerifyReport& report) {
  report = VerifyReport{};
  report.tolerance = options.tolerance > 0 ? options.tolerance : cut_tolerance(m);
  const Comparer cmp(plans, m, report.tolerance);
  Window win;
  align_window(plans, sim.cuts, cmp, report.tolerance, win);
  report.planned_passes = win.expected.size();
  report.program_cuts = win.order.size();
  Walk w{plans, win.expected, win.cuts, win.order, win.pairs, cmp, options, nc_diags};
  report.threads = walk_window(w, win.pairs.size(), plans.size());
  report.problems = w.problems;
  return report.problems == 0;
}

std::string verify_report_text(const VerifyReport& report, const std::vector<ThreadPlan>& plans,
                               const std::string& program_name, const Machine& m,
                               const VerifyOptions& options) {
  std::string out = report_header(program_name, m, options, plans.size(), report.planned_passes,
                                  report.program_cuts);
  for (const ThreadVerdict& v : report.threads) out += thread_lines(v, plans[v.plan], options);
  return out + report_verdict(report.problems, report.tolerance,
                              plans.empty() || plans.front().units == LengthUnit::kMm);
}

ThreadStream::ThreadStream(const Machine& m, const VerifyOptions& options)
    : m_(m),
      options_(options),
      tolerance_(options.tolerance > 0 ? options.tolerance : cut_tolerance(m)) {}

ThreadStream::~ThreadStream() = default;

void ThreadStream::plan(const ThreadPlan& p, std::vector<NcCut>& cuts) {
  if (!mm_) mm_ = p.units == LengthUnit::kMm;
  plans_.push_back(p);
  if (plans_.size() >= attempt_at_) poll(cuts);
}

void ThreadStream::poll(std::vector<NcCut>& cuts) {
  while (plans_.size() >= kWindow && cuts.size() >= retry_at_ && flush(cuts)) {
  }
}

namespace {

// How many leading passes of the window the program cuts as planned, one by one in order: the
// plan's i-th pass is the same cut in the same place as the program's i-th cut.
size_t exact_prefix(const Window& w, const Comparer& cmp) {
  size_t n = 0;
  for (; n < std::min(w.expected.size(), w.order.size()); ++n)
    if (w.order[n] != n || cmp.compare(w.expected[n], w.cuts[n], false).cost != 0) break;
  return n;
}

// The last pair where a thread of the window begins that a flush may end before: `ahead` exact
// pairs after it, `margin` threads after it in the window, not inside one program cut or one
// cycle call, not at the last program cut (the simulation may still add to it); 0: none.
size_t flush_point(const Window& w, size_t exact, size_t ahead, size_t margin, size_t threads,
                   size_t program_cuts) {
  size_t end = 0;
  for (size_t i = 1; i + ahead <= exact; ++i) {
    const size_t t = w.expected[i].thread;
    if (t == w.expected[i - 1].thread || t + margin > threads) continue;
    if (w.origin[i] == w.origin[i - 1] || w.origin[i] + 1 >= program_cuts) continue;
    if (w.cuts[i].call >= 0 && w.cuts[i].call == w.cuts[i - 1].call) continue;
    end = i;
  }
  return end;
}

}  // namespace

bool ThreadStream::flush(std::vector<NcCut>& cuts) {
  // The leading threads, and enough of the program's cuts for their passes.
  const std::vector<ThreadPlan> head(
      plans_.begin(), plans_.begin() + static_cast<long>(std::min(plans_.size(), 2 * kWindow)));
  const Comparer cmp(head, m_, tolerance_);
  Window win;
  const size_t passes = expected_cuts(head).size();
  const std::vector<NcCut> front(
      cuts.begin(), cuts.begin() + static_cast<long>(std::min(cuts.size(), passes + 1)));
  align_window(head, front, cmp, tolerance_, win, false);
  const size_t end =
      flush_point(win, exact_prefix(win, cmp), kAhead, kMargin, head.size(), cuts.size());
  if (end == 0) {  // not now: when twice as many threads wait, or more cuts are read
    attempt_at_ = plans_.size() * 2;
    retry_at_ = cuts.size() + kRetryCuts;
    return false;
  }
  attempt_at_ = kWindow;
  retry_at_ = 0;
  for (size_t i = 0; i < end; ++i)
    win.pairs.push_back({static_cast<long>(i), static_cast<long>(i)});
  const size_t threads = win.expected[end].thread;
  Diagnostics none("");  // an exact prefix has no problems
  Walk w{head, win.expected, win.cuts, win.order, win.pairs, cmp, options_, none};
  for (const ThreadVerdict& v : walk_window(w, end, threads))
    lines_ += thread_lines(v, head[v.plan], options_);
  threads_ += threads;
  planned_ += end;
  cut_ += end;
  last_cut_ = win.cuts[end - 1];
  plans_.erase(plans_.begin(), plans_.begin() + static_cast<long>(threads));
  cuts.erase(cuts.begin(), cuts.begin() + static_cast<long>(win.origin[end]));
  return true;
}

bool ThreadStream::finish(const std::vector<NcCut>& cuts, const std::string& program_name,
                          Diagnostics& nc_diags, std::string& text) {
  const Comparer cmp(plans_, m_, tolerance_);
  Window win;
  align_window(plans_, cuts, cmp, tolerance_, win);
  Walk w{plans_, win.expected, win.cuts, win.order, win.pairs, cmp, options_, nc_diags};
  w.continued = last_cut_.has_value();
  w.last_cut = last_cut_ ? &*last_cut_ : nullptr;
  const std::vector<ThreadVerdict> verdicts = walk_window(w, win.pairs.size(), plans_.size());
  text = report_header(program_name, m_, options_, threads_ + plans_.size(),
                       planned_ + win.expected.size(), cut_ + win.order.size()) +
         lines_;
  for (const ThreadVerdict& v : verdicts) text += thread_lines(v, plans_[v.plan], options_);
  text += report_verdict(w.problems, tolerance_, mm_.value_or(true));
  return w.problems == 0;
}

}  // namespace clpost

// Chained multi-pass threads (threading.md section 11; the decisions are in docs/threading.md):
// THREAD/ON,...,CHAIN with 2 to 21 GOTOs, the thread contour. Built from the multi-pass
// thread's parts: the first segment is the thread line of multi_geometry.cc (lead axis,
// infeed, side), the depth ladder, the flank shifts, and the pull-out of pullout.cc taken on the
// last segment.
#include <fmt/format.h>

#include <algorithm>
#include <cmath>
#include <utility>

#include "planner/depth_ladder.h"
#include "planner/flank_shift.h"
#include "planner/multi_geometry.h"
#include "planner/multi_sites.h"
#include "planner/plan_report.h"
#include "planner/planner.h"
#include "planner/pullout.h"
#include "support/angles.h"
#include "support/number_text.h"
#include "support/vec2_math.h"

namespace clpost {

using namespace vec2_math;
using namespace plan_report;

namespace {

// The radial and lead-axis coordinates of a point of a chain whose lead axis is Z (or X).
double lead_of(Vec2 v, bool along_z) {
  return along_z ? v.z : v.x;
}
double radial_of(Vec2 v, bool along_z) {
  return along_z ? v.x : v.z;
}
const char* lead_axis(bool along_z) {
  return along_z ? "Z" : "X";
}

bool check_chain_count(const MultiThreadInput& in, Reporter& r) {
  const size_t n = in.gotos.size();
  if (n < 2) {
    return r.error(on_site(in), fmt::format("{},CHAIN needs 2 to {} GOTOs before {} (the thread "
                                            "contour); found {}",
                                            in.on_word, kMaxChainGotos, in.off_word, n));
  }
  if (n > kMaxChainGotos) {
    r.error(goto_site(in, kMaxChainGotos),
            fmt::format("{},CHAIN takes at most {} GOTOs before {} (20 segments); this is GOTO {}",
                        in.on_word, kMaxChainGotos, in.off_word, kMaxChainGotos + 1));
    note_sequence_start(in, r);
    return false;
  }
  return true;
}

// Segment j (GOTO j-1 to GOTO j, j >= 1): a length, an advance along the lead axis the same way
// as the first segment, at most 45 degrees off it. Reported at GOTO j.
bool check_segment(const MultiThreadInput& in, size_t j, bool along_z, double sense, Reporter& r) {
  const Vec2 a = in.gotos[j - 1].point, b = in.gotos[j].point;
  const Vec2 d = b - a;
  std::string why;
  if (length(d) <= kLengthEps) {
    why = fmt::format("GOTO {} {} repeats the point before it: a chain segment needs a length",
                      j + 1, pt(b));
  } else if (lead_of(d, along_z) * sense <= kLengthEps) {
    why = fmt::format(
        "the chain segment from {} to {} moves {} along {}; every segment must "
        "advance along {} like the first one ({}{})",
        pt(a), pt(b), num_text(lead_of(d, along_z)), lead_axis(along_z), lead_axis(along_z),
        sense > 0 ? "+" : "-", lead_axis(along_z));
  } else if (std::fabs(radial_of(d, along_z)) > std::fabs(lead_of(d, along_z)) + kLengthEps) {
    const double off =
        degrees(std::atan2(std::fabs(radial_of(d, along_z)), std::fabs(lead_of(d, along_z))));
    why = fmt::format(
        "the chain segment from {} to {} is {}° off the {} axis; a chain segment "
        "may be at most 45° off it",
        pt(a), pt(b), num_text(off), lead_axis(along_z));
  }
  if (why.empty()) return true;
  r.error(goto_site(in, j), why);
  note_sequence_start(in, r);
  return false;
}

// Every segment, then the first one as the thread line (multi_geometry.h): lead axis, direction.
bool chain_geometry(const MultiThreadInput& in, MultiGeometry& g, Reporter& r) {
  const Vec2 d1 = in.gotos[1].point - in.gotos[0].point;
  if (length(d1) <= kLengthEps) return check_segment(in, 1, true, 1, r);  // reports it
  const bool along_z = std::fabs(d1.z) >= std::fabs(d1.x);
  const double sense = lead_of(d1, along_z) > 0 ? 1 : -1;
  for (size_t j = 1; j < in.gotos.size(); ++j) {
    if (!check_segment(in, j, along_z, sense, r)) return false;
  }
  return make_thread_line(in, g, r);
}

// One constant lead: INCR / DECR are refused at their word (or at THREAD/ON when PITCH/ gave
// them).
bool check_constant_lead(const MultiThreadInput& in, const PitchSpec& pitch, Reporter& r) {
  if (pitch.lead_change == 0) return true;
  const Site at = on_statement(in.on_lines, pitch.lead_change_loc)
                      ? word_site(in, pitch.lead_change_loc)
                      : on_site(in);
  return r.error(
      at,
      fmt::format("a chained thread cuts one constant lead: {} {} (CL line {}) "
                  "cannot be used with CHAIN",
                  pitch.lead_change > 0 ? "INCR" : "DECR", num_text(std::fabs(pitch.lead_change)),
                  pitch.lead_change_loc.line != 0 ? pitch.lead_change_loc.line : in.on_loc.line));
}

// The last segment as a thread line with the chain's infeed, for the pull-out (pullout.h).
MultiGeometry last_segment(const MultiThreadInput& in, const MultiGeometry& first) {
  MultiGeometry g = first;
  g.p1 = in.gotos[in.gotos.size() - 2].point;
  g.p2 = in.gotos.back().point;
  g.d12 = g.p2 - g.p1;
  g.length = length(g.d12);
  g.t = (1 / g.length) * g.d12;
  g.n = Vec2{g.t.z, -g.t.x};
  if (dot(g.n, g.u) < 0) g.n = -g.n;
  g.nu = dot(g.n, g.u);
  g.out_dir = -g.n;
  return g;
}

// What every pass of a chain shares.
struct ChainFrame {
  const MultiThreadInput& in;
  const MultiGeometry& first;  // the first segment: infeed u, multi-start run-in direction
  const MultiGeometry& last;   // the last segment: pull-out, where passes end
  Vec2 a;                      // the cutting direction along the lead axis (unit)
  double slide = 0;            // every pass ends this far back along the last segment
  const FlankShifts& shifts;
  const Pullout& pullout;
  double clear = 0;  // the radial coordinate of the clear line
  int starts = 1;
  double pitch = 0;
  bool by_angle = false;
  double run_in = 0;  // every start begins this much earlier along the first segment (auto)
};

// The point on the clear line with the lead-axis coordinate of `p`.
Vec2 on_clear_line(const ChainFrame& f, Vec2 p) {
  return f.first.lead_along_z ? Vec2{f.clear, p.z} : Vec2{p.x, f.clear};
}

ThreadPass chain_pass(const ChainFrame& f, const DepthLadder& ladder, size_t i, int k) {
  const bool along_z = f.first.lead_along_z;
  const double d = ladder.depths[i];
  const Vec2 base = d * f.first.u + f.shifts.sigma[i] * f.a;
  ThreadPass p;
  p.n = static_cast<int>(i) + 1;
  p.start = k;
  p.depth = d;
  p.kind = ladder.kinds[i];
  p.shift = f.shifts.sigma[i];
  const double earlier =
      f.run_in + (f.by_angle ? 0 : k * f.pitch / std::fabs(lead_of(f.first.t, along_z)));
  const std::vector<ThreadGoto>& pts = f.in.gotos;
  p.path.reserve(pts.size());
  p.path.push_back(pts.front().point + base - earlier * f.first.t);
  for (size_t j = 1; j + 1 < pts.size(); ++j) p.path.push_back(pts[j].point + base);
  p.path.push_back(pts.back().point + base - f.slide * f.last.t);
  p.from = p.path.front();
  p.to = p.path.back();
  p.pullout_end = f.pullout.delta ? p.to + *f.pullout.delta : p.to;
  p.clear = on_clear_line(f, p.pullout_end);
  // Along CUTANG back from the pass start to the clear line.
  const double s = (radial_of(p.from, along_z) - f.clear) / radial_of(f.first.u, along_z);
  p.approach = p.from - s * f.first.u;
  p.start_angle = f.by_angle ? k * 360.0 / f.starts : 0;
  return p;
}

// How far every pass ends back along the last segment: the largest flank shift (measured along
// the lead axis) and a negative CHAMFR. False, reported, when that leaves the last segment.
bool end_slide(const MultiThreadInput& in, const MultiGeometry& last, Vec2 a,
               const FlankShifts& shifts, const Pullout& pullout, double& out, Reporter& r) {
  out = shifts.max / dot(last.t, a) + pullout.shorten;
  if (out < last.length - kLengthEps) return true;
  return r.error(on_site(in),
                 fmt::format("the passes end {} back along the last chain segment (largest flank "
                             "shift {}, negative CHAMFR {}), which is only {} long",
                             num_text(out), num_text(shifts.max), num_text(pullout.shorten),
                             num_text(last.length)));
}

// The radial coordinate of the clear line, outside every point of the contour: RETURN,h is h
// outside its outermost point; otherwise the initial point's, which must be outside it. A
// pull-out that ends further out raises it (warned).
bool clear_line(const MultiThreadInput& in, const MultiGeometry& g, const MultiGeometry& last,
                const ChainFrame& f, double shallowest, double& out, Reporter& r) {
  const Pullout& pullout = f.pullout;
  const bool along_z = g.lead_along_z;
  const double sign = radial_of(g.u, along_z) < 0 ? 1 : -1;  // outward
  size_t far = 0;                                            // the outermost point of the contour
  for (size_t j = 1; j < in.gotos.size(); ++j)
    if (sign * radial_of(in.gotos[j].point, along_z) >
        sign * radial_of(in.gotos[far].point, along_z))
      far = j;
  const double top = radial_of(in.gotos[far].point, along_z);
  const Site site = in.words.ret.set ? word_site(in, in.words.ret.loc) : on_site(in);
  if (in.words.ret.height_given) {
    out = top + sign * in.words.ret.height;
  } else {
    out = radial_of(g.p0, along_z);
    if (sign * (out - top) <= kLengthEps) {
      return r.error(
          site, fmt::format("the tool returns to the initial point's {} {}, which is "
                            "not outside the chain contour: GOTO {} {} reaches {} {}; "
                            "start from outside the contour or give RETURN,h",
                            along_z ? "X" : "Z", num_text(out), far + 1, pt(in.gotos[far].point),
                            along_z ? "X" : "Z", num_text(top)));
    }
  }
  if (pullout.delta) {
    const double end = radial_of(
        in.gotos.back().point + shallowest * g.u - f.slide * last.t + *pullout.delta, along_z);
    if (sign * (end - out) > kLengthEps) {
      r.warning(site, fmt::format("the clear line {} {} is inside the pull-out end: the tool "
                                  "clears to {}",
                                  along_z ? "X" : "Z", num_text(out), num_text(end)));
      out = end;
    }
  }
  return true;
}

// The multi-pass header (multi_geometry.h) with what a chain says otherwise: its form, its
// last point as P2, its contour, and its kind from the lead axis alone.
ThreadPlan chain_header(const MultiThreadInput& in, const PlannerSettings& settings,
                        const PitchSpec& pitch, const MultiGeometry& g) {
  ThreadPlan plan = plan_header(in, settings, pitch, g);
  plan.form = ThreadForm::kChain;
  plan.p2 = in.gotos.back().point;
  for (const ThreadGoto& p : in.gotos) plan.points.push_back(p.point);
  plan.kind = g.lead_along_z ? ThreadKind::kTurn : ThreadKind::kFace;
  return plan;
}

// The infeed must cross the lead axis so that every pass can be reached from the clear line.
bool check_infeed_crosses(const MultiThreadInput& in, const MultiGeometry& g, Reporter& r) {
  if (std::fabs(radial_of(g.u, g.lead_along_z)) >= std::sin(radians(10)) - kAngleEps) return true;
  return r.error(in.words.cutang.set ? word_site(in, in.words.cutang.loc) : on_site(in),
                 fmt::format("CUTANG {} is within 10° of the chain's lead axis {}: the infeed "
                             "must cross it",
                             num_text(g.cutang), lead_axis(g.lead_along_z)));
}

}  // namespace

bool plan_chain_thread(const MultiThreadInput& in, const PlannerSettings& settings, ThreadPlan& out,
                       Diagnostics& diags) {
  Reporter r(diags);
  MultiGeometry g;
  if (!check_chain_count(in, r) || !chain_geometry(in, g, r)) return false;
  PitchSpec pitch = in.modal_pitch;
  in.words.pitch.apply_to(pitch);
  if (!check_pitch(pitch, on_site(in), in.on_word, settings, r) ||
      !check_constant_lead(in, pitch, r) || !make_infeed_direction(in, g, r) ||
      !check_infeed_crosses(in, g, r))
    return false;
  ThreadPlan plan = chain_header(in, settings, pitch, g);
  plan_run_in_out(plan, in.rpm, settings.lead_law, settings.add_run_in);
  DepthLadder ladder;
  if (!make_depth_ladder(in.words, plan.option, in.on_lines, in.on_loc, in.on_word, ladder, diags))
    return false;
  plan.depth = ladder.depth;
  const FlankShifts shifts = flank_shifts(ladder.depths, plan.option, g.cutang, plan.tool_angle);
  // The pull-out as that of a two-GOTO thread along the last segment.
  MultiThreadInput last_in = in;
  last_in.gotos.erase(last_in.gotos.begin(), last_in.gotos.end() - 2);
  const MultiGeometry last = last_segment(in, g);
  Pullout pullout;
  if (!make_pullout(last_in, last, pitch.pitch, pullout, r)) return false;
  plan.pullout = pullout.delta;
  plan.pullout_linear = pullout.linear;
  const Vec2 a = g.lead_along_z ? Vec2{0, g.t.z > 0 ? 1.0 : -1.0} : Vec2{g.t.x > 0 ? 1.0 : -1.0, 0};
  ChainFrame f{.in = in, .first = g, .last = last, .a = a, .shifts = shifts, .pullout = pullout};
  const double shallowest = *std::min_element(ladder.depths.begin(), ladder.depths.end());
  if (!end_slide(in, last, a, shifts, pullout, f.slide, r) ||
      !clear_line(in, g, last, f, shallowest, f.clear, r))
    return false;
  f.starts = std::clamp(pitch.starts, 1, kMaxStarts);
  f.pitch = pitch.pitch;
  f.by_angle = plan.starts_by_angle = f.starts > 1 && settings.start_angle_word;
  f.run_in = added_run_in_along(plan);
  for (size_t i = 0; i < ladder.depths.size(); ++i)
    for (int k = 0; k < f.starts; ++k) plan.passes.push_back(chain_pass(f, ladder, i, k));
  plan.end_position = on_clear_line(f, plan.p1);
  plan.clearance = std::fabs(f.clear - radial_of(plan.p1, g.lead_along_z));
  out = std::move(plan);
  return true;
}

}  // namespace clpost

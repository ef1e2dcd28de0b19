// Multi-pass thread planning (threading.md sections 4-8; the decisions taken where it is silent
// are in docs/threading.md): the GOTOs, then each phase in its own file (multi_geometry.cc,
// depth_ladder.cc, flank_shift.cc, pullout.cc), then the passes. Single-pass and coupled
// threads: path_threads.cc.
#include "planner/planner.h"

#include <fmt/format.h>

#include <algorithm>
#include <cmath>
#include <utility>

#include "planner/depth_ladder.h"
#include "planner/flank_shift.h"
#include "planner/multi_geometry.h"
#include "planner/multi_sites.h"
#include "planner/plan_report.h"
#include "planner/pullout.h"
#include "support/number_text.h"
#include "support/vec2_math.h"

namespace clpost {

using namespace vec2_math;
using namespace plan_report;

namespace {

// 2 or 3 GOTOs: thread start, thread end, optional chamfer end.
bool check_goto_count(const MultiThreadInput& in, Reporter& r) {
  const size_t ngoto = in.gotos.size();
  if (ngoto < 2) {
    return r.error(on_site(in),
                   fmt::format("{} needs 2 or 3 GOTOs before {} (thread start, thread end, "
                               "optional chamfer end); found {}",
                               in.on_word, in.off_word, ngoto));
  }
  if (ngoto > 3) {
    r.error(goto_site(in, 3), fmt::format("{} takes at most 3 GOTOs before {} (thread start, "
                                          "thread end, chamfer end); this is GOTO 4 of {}",
                                          in.on_word, in.off_word, ngoto));
    note_sequence_start(in, r);
    return false;
  }
  return true;
}

// What every pass of the thread shares.
struct PassFrame {
  const MultiGeometry& g;
  const FlankShifts& shifts;
  const Pullout& pullout;
  double clearance;  // the height of the clearance line above the thread line
  int starts;        // MULTRD, 1 to kMaxStarts
  double pitch;      // start k begins k pitches earlier, measured along the lead axis ...
  double t_lead;     // ... along which t has this length: k * pitch / t_lead along t
  double run_in;     // and every start this much earlier along t (threading.run_in auto)
};

// Pass `i` of the depth ladder for start `k`: the cut, its pull-out, the clear position and the
// approach along CUTANG from the clearance line.
ThreadPass make_pass(const PassFrame& f, const DepthLadder& ladder, size_t i, int k,
                     bool by_angle) {
  const MultiGeometry& g = f.g;
  const double d = ladder.depths[i];
  const double sigma = f.shifts.sigma[i];
  const Vec2 base = (d / g.nu) * g.u + sigma * g.t;
  ThreadPass p;
  p.n = static_cast<int>(i) + 1;
  p.start = k;
  p.depth = d;
  p.kind = ladder.kinds[i];
  p.shift = sigma;
  const double offset = f.run_in + (by_angle ? 0 : k * f.pitch / f.t_lead);
  p.from = g.p1 + base - offset * g.t;
  p.to = g.p2 + base - (f.shifts.max + f.pullout.shorten) * g.t;
  p.pullout_end = f.pullout.delta ? p.to + *f.pullout.delta : p.to;
  const double h_end = dot(p.pullout_end - g.p1, g.out_dir);
  p.clear = p.pullout_end + (f.clearance - h_end) * g.out_dir;
  p.approach = p.from - ((f.clearance + d) / g.nu) * g.u;
  p.start_angle = by_angle ? k * 360.0 / f.starts : 0;
  return p;
}

// Every pass in cutting order: pass 1 of every start, then pass 2 of every start, ... False,
// reported, when the flank shifts and a negative CHAMFR leave the passes no length.
bool make_passes(const MultiThreadInput& in, const PlannerSettings& settings,
                 const DepthLadder& ladder, const PassFrame& f, ThreadPlan& plan, Reporter& r) {
  const MultiGeometry& g = f.g;
  const double cut_len = g.length - f.shifts.max - f.pullout.shorten;
  if (cut_len <= kLengthEps) {
    return r.error(on_site(in), fmt::format("the passes have no length: thread length {} - "
                                            "largest flank shift {} - negative CHAMFR {} = {}",
                                            num_text(g.length), num_text(f.shifts.max),
                                            num_text(f.pullout.shorten), num_text(cut_len)));
  }
  plan.starts_by_angle = f.starts > 1 && settings.start_angle_word;
  const size_t npass = ladder.depths.size();
  plan.passes.reserve(npass * static_cast<size_t>(f.starts));
  for (size_t i = 0; i < npass; ++i) {
    for (int k = 0; k < f.starts; ++k) {
      plan.passes.push_back(make_pass(f, ladder, i, k, plan.starts_by_angle));
    }
  }
  return true;
}

}  // namespace

bool plan_multi_thread(const MultiThreadInput& in, const PlannerSettings& settings, ThreadPlan& out,
                       Diagnostics& diags) {
  Reporter r(diags);
  MultiGeometry g;
  if (!check_goto_count(in, r) || !make_thread_line(in, g, r)) return false;
  PitchSpec pitch = in.modal_pitch;
  in.words.pitch.apply_to(pitch);
  if (!check_pitch(pitch, on_site(in), in.on_word, settings, r)) return false;
  if (!make_infeed_direction(in, g, r)) return false;
  ThreadPlan plan = plan_header(in, settings, pitch, g);
  plan_run_in_out(plan, in.rpm, settings.lead_law, settings.add_run_in);

  DepthLadder ladder;
  if (!make_depth_ladder(in.words, plan.option, in.on_lines, in.on_loc, in.on_word, ladder, diags))
    return false;
  plan.depth = ladder.depth;
  const FlankShifts shifts = flank_shifts(ladder.depths, plan.option, g.cutang, plan.tool_angle);
  Pullout pullout;
  if (!make_pullout(in, g, pitch.pitch, pullout, r)) return false;
  plan.pullout = pullout.delta;
  plan.pullout_linear = pullout.linear;
  const double shallowest = *std::min_element(ladder.depths.begin(), ladder.depths.end());
  if (!clearance_height(in, g, pitch.pitch, pullout, shallowest, plan.clearance, r)) return false;

  // Start k begins k pitches (measured along the lead axis) earlier, and every start the run-in
  // earlier when it is added; the end stays.
  const double t_lead = g.lead_along_z ? std::fabs(g.t.z) : std::fabs(g.t.x);
  const PassFrame frame{.g = g,
                        .shifts = shifts,
                        .pullout = pullout,
                        .clearance = plan.clearance,
                        .starts = std::clamp(pitch.starts, 1, kMaxStarts),
                        .pitch = pitch.pitch,
                        .t_lead = t_lead,
                        .run_in = added_run_in_along(plan)};
  if (!make_passes(in, settings, ladder, frame, plan, r)) return false;
  plan.end_position = g.p1 + plan.clearance * g.out_dir;
  out = std::move(plan);
  return true;
}

}  // namespace clpost

// Multi-pass thread planning (threading.md sections 4-8; the decisions taken where it is silent
// are in docs/threading.md). Single-pass and coupled threads: path_threads.cc.
#include "planner/planner.h"

#include <fmt/format.h>

#include <algorithm>
#include <cmath>
#include <limits>
#include <string>

#include "planner/depth_ladder.h"
#include "planner/flank_shift.h"
#include "planner/multi_geometry.h"
#include "planner/number_text.h"
#include "planner/plan_report.h"
#include "planner/pullout.h"
#include "planner/vec2_math.h"

namespace clpost {

using namespace vec2_math;
using namespace plan_report;

bool plan_multi_thread(const MultiThreadInput& in, const PlannerSettings& settings, ThreadPlan& out,
                       Diagnostics& diags) {
  Reporter r(diags);
  const Site on{in.on_loc, &in.on_lines};
  const ThreadWords& w = in.words;
  auto goto_site = [&](size_t i) { return Site{in.gotos[i].loc, &in.gotos[i].lines}; };
  auto sequence_note = [&] { r.note(on, "the thread sequence starts here"); };

  // --- The GOTOs: 2 or 3. ---
  const size_t ngoto = in.gotos.size();
  if (ngoto < 2) {
    return r.error(on, fmt::format("{} needs 2 or 3 GOTOs before {} (thread start, thread end, "
                                   "optional chamfer end); found {}",
                                   in.on_word, in.off_word, ngoto));
  }
  if (ngoto > 3) {
    r.error(goto_site(3), fmt::format("{} takes at most 3 GOTOs before {} (thread start, thread "
                                      "end, chamfer end); this is GOTO 4 of {}",
                                      in.on_word, in.off_word, ngoto));
    sequence_note();
    return false;
  }
  MultiGeometry g;
  if (!make_thread_line(in, g, r)) return false;
  const Vec2 p0 = g.p0;
  const Vec2 p1 = g.p1;
  const Vec2 p2 = g.p2;
  const double len = g.length;

  // --- Pitch. ---
  PitchSpec pitch = in.modal_pitch;
  w.pitch.apply_to(pitch);
  if (!check_pitch(pitch, on, in.on_word, settings, r)) return false;

  // --- Geometry. ---
  if (!make_infeed_direction(in, g, r)) return false;
  ThreadPlan plan;
  plan.loc = in.on_loc;
  plan.form = ThreadForm::kMulti;
  plan.units = in.units;
  plan.pitch = pitch;
  plan.lead = pitch.starts * pitch.pitch;
  plan.p0 = p0;
  plan.p1 = p1;
  plan.p2 = p2;
  plan.feed_approach = in.feed_approach;
  plan.kind = kind_of(g.d12);
  plan.lead_along_z = g.lead_along_z;
  plan.cutang = g.cutang;
  plan.side = side_of(g);
  const double theta = g.cutang;
  const Vec2 t = g.t;
  const Vec2 u = g.u;
  const double nu = g.nu;
  const Vec2 out_dir = g.out_dir;

  plan.option = w.option.set ? w.option.value : settings.default_option;
  plan.tool_angle = w.tlangl.set ? w.tlangl.value : settings.default_tool_angle;

  // --- Depth ladder. ---
  DepthLadder ladder;
  if (!make_depth_ladder(w, plan.option, in.on_lines, in.on_loc, in.on_word, ladder, diags))
    return false;
  plan.depth = ladder.depth;

  // --- Flank shift. ---
  const size_t npass = ladder.depths.size();
  const FlankShifts shifts = flank_shifts(ladder.depths, plan.option, theta, plan.tool_angle);
  const std::vector<double>& sigma = shifts.sigma;
  const double sigma_max = shifts.max;

  // --- Pull-out. ---
  Pullout pullout;
  if (!make_pullout(in, g, pitch.pitch, pullout, r)) return false;
  const std::optional<Vec2> delta = pullout.delta;
  const double shorten = pullout.shorten;
  plan.pullout = delta;
  plan.pullout_linear = pullout.linear;

  // --- Clearance: the line, parallel to the thread, that the tool returns along. ---
  const double d_min = *std::min_element(ladder.depths.begin(), ladder.depths.end());
  double clear_h = 0;
  if (!clearance_height(in, g, pitch.pitch, pullout, d_min, clear_h, r)) return false;
  plan.clearance = clear_h;

  // --- Passes. ---
  const double cut_len = len - sigma_max - shorten;
  if (cut_len <= kLengthEps) {
    return r.error(
        on, fmt::format("the passes have no length: thread length {} - largest flank "
                        "shift {} - negative CHAMFR {} = {}",
                        num_text(len), num_text(sigma_max), num_text(shorten), num_text(cut_len)));
  }
  const int starts = std::clamp(pitch.starts, 1, kMaxStarts);
  plan.starts_by_angle = starts > 1 && settings.start_angle_word;
  // Start k begins k pitches (measured along the lead axis) earlier; the end stays.
  const double t_lead = plan.lead_along_z ? std::fabs(t.z) : std::fabs(t.x);
  plan.passes.reserve(npass * static_cast<size_t>(starts));
  for (size_t i = 0; i < npass; ++i) {
    const double d = ladder.depths[i];
    const Vec2 base = (d / nu) * u + sigma[i] * t;
    for (int k = 0; k < starts; ++k) {
      ThreadPass p;
      p.n = static_cast<int>(i) + 1;
      p.start = k;
      p.depth = d;
      p.kind = ladder.kinds[i];
      p.shift = sigma[i];
      const double offset = plan.starts_by_angle ? 0 : k * pitch.pitch / t_lead;
      p.from = p1 + base - offset * t;
      p.to = p2 + base - (sigma_max + shorten) * t;
      p.pullout_end = delta ? p.to + *delta : p.to;
      const double h_end = dot(p.pullout_end - p1, out_dir);
      p.clear = p.pullout_end + (clear_h - h_end) * out_dir;
      p.approach = p.from - ((clear_h + d) / nu) * u;
      p.start_angle = plan.starts_by_angle ? k * 360.0 / starts : 0;
      plan.passes.push_back(p);
    }
  }
  plan.end_position = p1 + clear_h * out_dir;
  out = std::move(plan);
  return true;
}

}  // namespace clpost

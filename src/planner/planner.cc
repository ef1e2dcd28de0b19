// Multi-pass thread planning (threading.md sections 4-8; the decisions taken where it is silent
// are in docs/threading.md). Single-pass and coupled threads: path_threads.cc.
#include "planner/planner.h"

#include <fmt/format.h>

#include <algorithm>
#include <cmath>
#include <limits>
#include <string>

#include "planner/depth_ladder.h"
#include "planner/multi_geometry.h"
#include "planner/number_text.h"
#include "planner/plan_report.h"
#include "planner/vec2_math.h"

namespace clpost {

using namespace vec2_math;
using namespace plan_report;

namespace {

// pitch/(2 tan 30): the full depth of a 60 degree thread, the default pull-out and return height.
double default_height(double pitch) {
  return pitch / (2 * std::tan(rad(30)));
}

bool is_axis_angle(double deg_value) {
  const double r = std::fabs(std::fmod(deg_value, 90.0));
  return r < kAngleEps || 90 - r < kAngleEps;
}

// One way to define the pull-out, with where it was given (for the "more than one" error).
struct PulloutSource {
  std::string name;  // "the third GOTO", "ATANGL", "CHAMFR"
  Site site;
};

std::string loc_text(SourceLoc l) {
  return fmt::format("line {}, column {}", l.line, l.col);
}

}  // namespace

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
  std::vector<double> sigma(npass, 0);
  if (plan.option != 0 && is_axis_angle(theta)) {
    const double k = std::tan(rad(plan.tool_angle / 2));
    for (size_t i = 0; i < npass; ++i) {
      const int pass_no = static_cast<int>(i) + 1;
      const bool single_edge = plan.option == 1 || plan.option == 3;
      if (single_edge || pass_no % 2 == 0) sigma[i] = ladder.depths[i] * k;
    }
  }
  const double sigma_max = npass ? *std::max_element(sigma.begin(), sigma.end()) : 0;

  // --- Pull-out. ---
  std::vector<PulloutSource> sources;
  if (w.atangl.set) sources.push_back({"ATANGL", {w.atangl.loc, &in.on_lines}});
  if (w.chamfr.set && w.chamfr.length != 0)
    sources.push_back({"CHAMFR", {w.chamfr.loc, &in.on_lines}});
  if (sources.size() == 2 && (sources[1].site.loc.line < sources[0].site.loc.line ||
                              (sources[1].site.loc.line == sources[0].site.loc.line &&
                               sources[1].site.loc.col < sources[0].site.loc.col)))
    std::swap(sources[0], sources[1]);
  if (ngoto == 3) sources.push_back({"the third GOTO", goto_site(2)});
  if (sources.size() > 1) {
    for (size_t k = 1; k < sources.size(); ++k) {
      r.error(sources[k].site,
              fmt::format("{} defines a second pull-out: {} at {} already defines it; give only "
                          "one of a third GOTO, ATANGL and CHAMFR",
                          sources[k].name, sources[0].name, loc_text(sources[0].site.loc)));
    }
    if (sources.back().name == "the third GOTO") sequence_note();
    return false;
  }
  std::optional<Vec2> delta;
  double shorten = 0;  // negative CHAMFR: every pass ends this much earlier along t
  double chamfer_angle = 0;
  if (ngoto == 3) {
    const Vec2 p3 = in.gotos[2].point;
    const Vec2 d = p3 - p2;
    if (length(d) <= kLengthEps) {
      r.warning(goto_site(2), fmt::format("the third GOTO {} repeats the thread end: no "
                                          "pull-out",
                                          pt(p3)));
    } else if (dot(d, out_dir) < -kLengthEps) {
      r.error(goto_site(2),
              fmt::format("the chamfer end {} is {} on the material side of the thread line: "
                          "the pull-out must move out of the thread",
                          pt(p3), num_text(-dot(d, out_dir))));
      sequence_note();
      return false;
    } else {
      delta = d;
    }
  } else if (w.atangl.set) {
    const double h = w.atangl.height > 0 ? w.atangl.height : default_height(pitch.pitch);
    delta = h * out_dir + (h * std::tan(rad(w.atangl.angle))) * t;
  } else if (w.chamfr.set && w.chamfr.length != 0) {
    const double l = std::fabs(w.chamfr.length);
    delta = l * t + (l * std::tan(rad(w.chamfr.angle))) * out_dir;
    if (w.chamfr.length < 0) shorten = l;
  }
  if (delta) {
    chamfer_angle = deg(std::atan2(dot(*delta, out_dir), dot(*delta, t)));
    plan.pullout = delta;
    plan.pullout_linear = chamfer_angle < 30 - kAngleEps || chamfer_angle > 60 + kAngleEps;
  }

  // --- Clearance: the line, parallel to the thread, that the tool returns along. ---
  // Highest pull-out end over all passes (the shallowest pass), above the thread line.
  const double d_min = *std::min_element(ladder.depths.begin(), ladder.depths.end());
  const double top =
      delta ? dot(*delta, out_dir) - d_min : -std::numeric_limits<double>::infinity();
  double clear_h = 0;
  if (w.ret.set) {
    const Site ret{w.ret.loc, &in.on_lines};
    if (w.ret.height_given) {
      clear_h = w.ret.height;
    } else if (plan.lead_along_z) {
      clear_h = (p0.x - p2.x) / out_dir.x;
      if (clear_h <= kLengthEps) {
        return r.error(ret, fmt::format("RETURN without a height clears to the initial point's "
                                        "X {}, which is not outside the thread end {}; give "
                                        "RETURN,h",
                                        num_text(p0.x), pt(p2)));
      }
    } else {
      clear_h = (p0.z - p2.z) / out_dir.z;
      if (clear_h <= kLengthEps) {
        return r.error(ret, fmt::format("RETURN without a height clears to the initial point's "
                                        "Z {}, which is not outside the thread end {}; give "
                                        "RETURN,h",
                                        num_text(p0.z), pt(p2)));
      }
    }
    if (top > clear_h + kLengthEps) {
      r.warning(ret, fmt::format("the return height {} is below the pull-out end ({} above the "
                                 "thread line): the tool clears to {}",
                                 num_text(clear_h), num_text(top), num_text(top)));
      clear_h = top;
    }
  } else {
    clear_h = std::max(default_height(pitch.pitch), top);
  }
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

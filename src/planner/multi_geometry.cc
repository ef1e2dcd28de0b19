// The geometry of a multi-pass thread: threading.md section 4 (multi_geometry.h).
#include "planner/multi_geometry.h"

#include <fmt/format.h>

#include <algorithm>
#include <cmath>

#include "planner/multi_sites.h"
#include "support/angles.h"
#include "support/number_text.h"
#include "support/vec2_math.h"

namespace clpost {

using namespace vec2_math;
using namespace plan_report;

namespace {

// CUTANG as given: more than 10 degrees off the thread line, else reported at CUTANG.
bool given_cutang(const MultiThreadInput& in, const MultiGeometry& g, Reporter& r) {
  const double theta = in.words.cutang.value;
  const Vec2 u = direction(theta);
  const double off = degrees(std::acos(std::min(1.0, std::fabs(dot(u, g.t)))));
  if (off > 10 + kAngleEps) return true;
  return r.error(
      word_site(in, in.words.cutang.loc),
      fmt::format("CUTANG {} is only {}° off the thread line (direction {}° from "
                  "{} to {}); the infeed must be more than 10° off it",
                  num_text(theta), num_text(off), num_text(angle_of(g.t)), pt(g.p1), pt(g.p2)));
}

// The default CUTANG: along X toward the thread line from the initial point for a turn or
// turn-taper thread, along Z for a face or face-taper thread. False, reported, when the initial
// point is on the thread line.
bool default_cutang(const MultiThreadInput& in, const MultiGeometry& g, double& theta,
                    Reporter& r) {
  const Vec2 p0 = g.p0, p1 = g.p1, d12 = g.d12;
  const double gap = g.lead_along_z ? p1.x + (p0.z - p1.z) * d12.x / d12.z - p0.x
                                    : p1.z + (p0.x - p1.x) * d12.z / d12.x - p0.z;
  if (std::fabs(gap) <= kLengthEps) {
    return r.error(on_site(in), fmt::format("cannot choose the infeed direction: the initial "
                                            "point {} is on the thread line; give CUTANG",
                                            pt(p0)));
  }
  if (g.lead_along_z) {
    theta = gap < 0 ? 180 : 0;
  } else {
    theta = gap < 0 ? 270 : 90;
  }
  return true;
}

}  // namespace

bool make_thread_line(const MultiThreadInput& in, MultiGeometry& g, Reporter& r) {
  g.p0 = in.p0;
  g.p1 = in.gotos[0].point;
  g.p2 = in.gotos[1].point;
  g.d12 = g.p2 - g.p1;
  g.length = length(g.d12);
  if (g.length <= kLengthEps) {
    r.error(goto_site(in, 1), fmt::format("the thread end {} is the thread start: the thread "
                                          "has no length",
                                          pt(g.p2)));
    note_sequence_start(in, r);
    return false;
  }
  g.lead_along_z = std::fabs(g.d12.z) >= std::fabs(g.d12.x);
  g.t = (1 / g.length) * g.d12;
  return true;
}

bool make_infeed_direction(const MultiThreadInput& in, MultiGeometry& g, Reporter& r) {
  double theta = 0;
  if (in.words.cutang.set) {
    if (!given_cutang(in, g, r)) return false;
    theta = in.words.cutang.value;
  } else if (!default_cutang(in, g, theta, r)) {
    return false;
  }
  g.cutang = theta;
  g.u = direction(theta);
  g.n = Vec2{g.t.z, -g.t.x};
  if (dot(g.n, g.u) < 0) g.n = -g.n;
  g.nu = dot(g.n, g.u);
  g.out_dir = -g.n;
  return true;
}

ThreadPlan plan_header(const MultiThreadInput& in, const PlannerSettings& settings,
                       const PitchSpec& pitch, const MultiGeometry& g) {
  ThreadPlan plan;
  plan.loc = in.on_loc;
  plan.form = ThreadForm::kMulti;
  plan.units = in.units;
  plan.pitch = pitch;
  plan.lead = pitch.starts * pitch.pitch;
  plan.p0 = g.p0;
  plan.p1 = g.p1;
  plan.p2 = g.p2;
  plan.feed_approach = in.feed_approach;
  plan.kind = kind_of(g.d12);
  plan.lead_along_z = g.lead_along_z;
  plan.cutang = g.cutang;
  plan.side = side_of(g);
  plan.option = in.words.option.set ? in.words.option.value : settings.default_option;
  plan.tool_angle = in.words.tlangl.set ? in.words.tlangl.value : settings.default_tool_angle;
  return plan;
}

ThreadSide side_of(const MultiGeometry& g) {
  return (!g.lead_along_z || g.n.x < 0) ? ThreadSide::kExternal : ThreadSide::kInternal;
}

}  // namespace clpost

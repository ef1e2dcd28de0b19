#include "plot/thread_section.h"

#include <fmt/format.h>

#include <algorithm>
#include <cmath>
#include <utility>
#include <vector>

#include "support/number_text.h"

namespace clpost {

ThreadSection section_from_plan(const ThreadPlan& plan, std::string title) {
  ThreadSection s;
  if (title.empty()) {
    title = fmt::format("thread at line {} - pitch {}, depth {}", plan.loc.line,
                        num_text(plan.pitch.pitch), num_text(plan.depth));
    if (plan.form == ThreadForm::kMulti || plan.form == ThreadForm::kChain)
      title += fmt::format(", OPTION {}", plan.option);
  }
  s.title = std::move(title);
  s.units = plan.units;
  s.side = plan.side;
  s.pitch = plan.pitch.pitch;
  s.lead = plan.lead;
  s.starts = plan.pitch.starts;
  s.depth = plan.depth;
  s.tool_angle = plan.tool_angle;
  s.passes.reserve(plan.passes.size());
  for (const ThreadPass& p : plan.passes) {
    SectionPass q;
    q.n = p.n;
    q.start = p.start;
    q.depth = p.depth;
    q.shift = p.shift;
    q.kind = p.kind;
    s.passes.push_back(q);
  }
  return s;
}

namespace {

// Segment j (points j-1 to j) of a chain: every pass's depth at right angles to it and its shift
// along it, from the pass's first point (or, for the last segment, its last point) and the
// contour.
ThreadSection segment_section(const ThreadPlan& plan, size_t j) {
  const Vec2 a = plan.points[j - 1], b = plan.points[j];
  const double len = std::hypot(b.x - a.x, b.z - a.z);
  const Vec2 t{(b.x - a.x) / len, (b.z - a.z) / len};
  // Toward the material: the side the passes are on.
  Vec2 n{t.z, -t.x};
  const double inward = plan.side == ThreadSide::kInternal ? 1 : -1;
  if (plan.lead_along_z ? n.x * inward < 0 : n.z > 0) n = {-n.x, -n.z};
  ThreadSection s = section_from_plan(
      plan, fmt::format("thread at line {} - segment {} of {}, (X {}, Z {}) to (X {}, Z {}) - "
                        "pitch {}, OPTION {}",
                        plan.loc.line, j, plan.points.size() - 1, num_text(a.x), num_text(a.z),
                        num_text(b.x), num_text(b.z), num_text(plan.pitch.pitch), plan.option));
  for (size_t i = 0; i < plan.passes.size() && i < s.passes.size(); ++i) {
    const ThreadPass& p = plan.passes[i];
    if (p.path.size() != plan.points.size()) continue;
    // A corner of the pass against the contour's: the first point may be run in earlier (a
    // multi-start offset), so segment 1 is measured at its end when that is a corner.
    const bool at_end = j == 1 && p.path.size() > 2;
    const Vec2 on = at_end ? p.path[1] : p.path[j - 1], ref = at_end ? b : a;
    const Vec2 d{on.x - ref.x, on.z - ref.z};
    s.passes[i].depth = d.x * n.x + d.z * n.z;
    s.passes[i].shift = d.x * t.x + d.z * t.z;
  }
  double deepest = 0;
  for (const SectionPass& q : s.passes) deepest = std::max(deepest, q.depth);
  s.depth = deepest;
  return s;
}

}  // namespace

std::vector<ThreadSection> sections_from_plan(const ThreadPlan& plan) {
  if (plan.form != ThreadForm::kChain || plan.points.size() < 2)
    return {section_from_plan(plan, "")};
  std::vector<ThreadSection> out;
  for (size_t j = 1; j < plan.points.size(); ++j) out.push_back(segment_section(plan, j));
  return out;
}

}  // namespace clpost

#include "plot/thread_section.h"

#include <fmt/format.h>

#include <algorithm>
#include <cmath>
#include <utility>
#include <vector>

#include "planner/run_in.h"
#include "support/number_text.h"

namespace clpost {

namespace {

// The run-in and run-out of `plan` along its lead axis, and what its passes span across it.
SectionLead section_lead(const ThreadPlan& plan) {
  SectionLead l;
  const LeadSpan s = lead_span(plan);
  if (!s.known) return l;
  l.known = true;
  l.along_z = s.along_z;
  l.cut_from = s.cut_from;
  l.cut_to = s.cut_to;
  l.right_from = s.from;
  l.right_to = s.to;
  l.any = s.any;
  l.run_in = plan.run_in;
  l.run_out = plan.run_out;
  l.rpm = plan.rpm;
  bool first = true;
  auto across = [&](Vec2 p) {
    const double v = s.along_z ? p.x : p.z;
    l.across_lo = first ? v : std::min(l.across_lo, v);
    l.across_hi = first ? v : std::max(l.across_hi, v);
    first = false;
  };
  across(plan.p1);
  across(plan.p2);
  for (const Vec2& p : plan.points) across(p);
  for (const Vec2& p : plan.path) across(p);
  for (const ThreadPass& p : plan.passes) {
    across(p.from);
    across(p.to);
  }
  return l;
}

}  // namespace

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
  s.zones = section_lead(plan);
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
    // A run-in clpost added (threading.run_in auto) moves the first point back along segment 1.
    const double run_in = j == 1 && !at_end ? added_run_in_along(plan) : 0;
    const Vec2 d{on.x - ref.x + run_in * t.x, on.z - ref.z + run_in * t.z};
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

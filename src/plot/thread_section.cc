#include "plot/thread_section.h"

#include <fmt/format.h>

#include <algorithm>
#include <cctype>
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

namespace clpost {

namespace {

bool same_pass(const SectionPass& a, const SectionPass& b) {
  return a.n == b.n && a.start == b.start && a.depth == b.depth && a.shift == b.shift &&
         a.kind == b.kind;
}

bool same_lead(const SectionLead& a, const SectionLead& b) {
  return a.known == b.known && a.along_z == b.along_z && a.cut_from == b.cut_from &&
         a.cut_to == b.cut_to && a.right_from == b.right_from && a.right_to == b.right_to &&
         a.any == b.any && a.run_in == b.run_in && a.run_out == b.run_out && a.rpm == b.rpm &&
         a.across_lo == b.across_lo && a.across_hi == b.across_hi;
}

// A title without the line it names ("thread at line 12 - ...", "thread at part.cl:12 as ..."):
// the digits after the first "line " or ':' dropped.
std::string title_key(const std::string& title) {
  size_t at = title.find("line ");
  at = at == std::string::npos ? title.find(':') : at + 4;
  if (at == std::string::npos) return title;
  size_t end = at + 1;
  while (end < title.size() && std::isdigit(static_cast<unsigned char>(title[end]))) ++end;
  return title.substr(0, at + 1) + title.substr(end);
}

}  // namespace

bool same_section(const ThreadSection& a, const ThreadSection& b) {
  return title_key(a.title) == title_key(b.title) && a.units == b.units && a.side == b.side &&
         a.pitch == b.pitch && a.lead == b.lead && a.starts == b.starts && a.depth == b.depth &&
         a.tool_angle == b.tool_angle &&
         std::equal(a.passes.begin(), a.passes.end(), b.passes.begin(), b.passes.end(),
                    same_pass) &&
         same_lead(a.zones, b.zones);
}

void SectionGroups::add(ThreadSection s) {
  ++total_;
  for (auto& [g, n] : groups_) {
    if (!same_section(g, s)) continue;
    ++n;
    return;
  }
  if (groups_.size() >= kMaxDrawnSections) {
    ++left_out_;
    return;
  }
  groups_.emplace_back(std::move(s), 1);
}

std::vector<ThreadSection> SectionGroups::drawn() const {
  std::vector<ThreadSection> out;
  for (const auto& [g, n] : groups_) {
    out.push_back(g);
    if (n > 1) out.back().title += fmt::format(" \u00d7{} ({} identical threads)", n, n);
  }
  return out;
}

}  // namespace clpost

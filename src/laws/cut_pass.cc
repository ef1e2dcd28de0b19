#include "laws/cut_pass.h"

#include <fmt/format.h>

#include "laws/written_value.h"

#include <algorithm>
#include <cmath>

namespace clpost {

std::vector<Cut> plan_cuts(const ThreadPlan& plan) {
  std::vector<Cut> out;
  out.reserve(plan.passes.size());
  for (const ThreadPass& p : plan.passes) {
    out.push_back(Cut{p.start, p.depth, p.from, p.to, p.pullout_end, {}});
    if (p.path.size() > 2) out.back().corners.assign(p.path.begin() + 1, p.path.end() - 1);
  }
  return out;
}

double cut_tolerance(const Machine& m) {
  if (m.thread_tolerance > 0) return m.thread_tolerance;
  return least_increment(m, "Z");
}

namespace {

double dist(Vec2 a, Vec2 b) {
  return std::hypot(a.x - b.x, a.z - b.z);
}

std::string pass_name(const Cut& c, size_t i, bool multi) {
  return multi ? fmt::format("pass {} (start {})", i + 1, c.start + 1)
               : fmt::format("pass {}", i + 1);
}

std::string point(Vec2 v) {
  return fmt::format("X{:.4f} Z{:.4f}", 2 * v.x, v.z);
}

}  // namespace

std::string compare_cuts(const std::vector<Cut>& control, const std::vector<Cut>& plan,
                         const CutCompareOptions& o) {
  std::vector<Cut> a = control, b = plan;
  if (o.start_by_start) {
    auto by_start = [](const Cut& x, const Cut& y) { return x.start < y.start; };
    std::stable_sort(a.begin(), a.end(), by_start);
    std::stable_sort(b.begin(), b.end(), by_start);
  }
  bool multi = std::any_of(b.begin(), b.end(), [](const Cut& c) { return c.start > 0; });
  const double tol = o.tolerance + 1e-9;
  size_t n = std::min(a.size(), b.size());
  for (size_t i = 0; i < n; ++i) {
    const Cut& c = a[i];
    const Cut& p = b[i];
    std::string name = pass_name(p, i, multi);
    if (c.start != p.start)
      return fmt::format("{}: start {}, plan start {}", name, c.start + 1, p.start + 1);
    if (std::fabs(c.depth - p.depth) > tol)
      return fmt::format("{}: depth {:.4f}, plan {:.4f}", name, c.depth, p.depth);
    if (dist(c.from, p.from) > tol)
      return fmt::format("{}: starts at {}, plan {}", name, point(c.from), point(p.from));
    if (c.corners.size() != p.corners.size())
      return fmt::format("{}: {} segments, plan {}", name, c.corners.size() + 1,
                         p.corners.size() + 1);
    for (size_t j = 0; j < c.corners.size(); ++j)
      if (dist(c.corners[j], p.corners[j]) > tol)
        return fmt::format("{}: segment {} ends at {}, plan {}", name, j + 1, point(c.corners[j]),
                           point(p.corners[j]));
    if (dist(c.to, p.to) > tol)
      return fmt::format("{}: ends at {}, plan {}", name, point(c.to), point(p.to));
    if (dist(c.end, p.end) > tol)
      return fmt::format("{}: pull-out ends at {}, plan {}", name, point(c.end), point(p.end));
  }
  if (a.size() != b.size()) {
    if (a.size() > b.size())
      return fmt::format("{} passes, plan {}: extra pass at depth {:.4f}", a.size(), b.size(),
                         a[n].depth);
    return fmt::format("{} passes, plan {}: pass {} at depth {:.4f} missing", a.size(), b.size(),
                       n + 1, b[n].depth);
  }
  return {};
}

}  // namespace clpost

#include "laws/hole_law.h"

#include <algorithm>
#include <cmath>

namespace clpost {

std::string_view hole_kind_name(HoleKind k) {
  switch (k) {
    case HoleKind::kDrill:
      return "drilling";
    case HoleKind::kDeep:
      return "peck drilling";
    case HoleKind::kChipBreak:
      return "chip-breaking drilling";
    case HoleKind::kTap:
      return "tapping";
    case HoleKind::kBore:
      return "boring";
    case HoleKind::kReam:
      return "reaming";
  }
  return "?";
}

std::vector<double> hole_feed_ends(const Hole& h) {
  std::vector<double> ends;
  const double total = std::fabs(h.bottom - h.r);
  const bool pecks = (h.kind == HoleKind::kDeep || h.kind == HoleKind::kChipBreak) && h.peck > 0;
  double reached = 0;
  double step = pecks ? (h.first_peck > 0 ? h.first_peck : h.peck) : total;
  while (ends.size() < kMaxHolePecks) {
    reached = std::min(total, reached + step);
    ends.push_back(reached);
    if (reached >= total - 1e-9) break;
    step = h.peck;
  }
  for (double& e : ends) e = h.r + h.dir * e;
  if (!ends.empty()) ends.back() = h.bottom;
  return ends;
}

}  // namespace clpost

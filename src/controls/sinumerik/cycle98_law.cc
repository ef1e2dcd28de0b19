// SINUMERIK CYCLE98, the cuts from the words (cycle98_law.h).
#include "controls/sinumerik/cycle98_law.h"

#include <fmt/format.h>

#include <algorithm>
#include <cmath>
#include <numbers>

#include "support/angles.h"
#include "support/vec2_math.h"

namespace clpost {

using namespace vec2_math;

namespace {

// The contour: the points up to the first that repeats the one before it. Empty (with `alarm`)
// when it is not one CYCLE98 can cut.
std::vector<Vec2> contour_of(const Cycle98Words& w, std::string& alarm) {
  std::vector<Vec2> pts{{w.dm[0] / 2, w.po[0]}};
  for (int j = 1; j < 4; ++j) {
    const Vec2 p{w.dm[j] / 2, w.po[j]};
    if (length(p - pts.back()) <= 1e-12) break;
    pts.push_back(p);
  }
  if (pts.size() < 2) {
    alarm = "the contour has no length (PO1, DM1 = PO2, DM2)";
    return {};
  }
  const double sense = pts[1].z > pts[0].z ? 1 : -1;
  for (size_t j = 1; j < pts.size(); ++j) {
    const Vec2 d = pts[j] - pts[j - 1];
    if (d.z * sense <= 0 || std::fabs(d.x) > std::fabs(d.z) + 1e-12) {
      alarm = fmt::format("segment {} does not advance along Z at 45 degrees or less", j);
      return {};
    }
  }
  for (size_t j = 1; j + 1 < pts.size(); ++j)
    if (w.pp[j] != w.pp[0]) {
      alarm = fmt::format("PP{} {} differs from PP1 {}: one lead per chain is expanded", j + 1,
                          w.pp[j], w.pp[0]);
      return {};
    }
  return pts;
}

// The paraxial depth of every cut of one start: roughing, FAL, idle passes.
std::vector<double> depths_of(const Cycle98Words& w) {
  std::vector<double> depths;
  const double rough = w.tdep - w.fal;
  const bool section = w.vari == 3 || w.vari == 4;
  for (int i = 1; i <= w.nrc; ++i) {
    const double f = static_cast<double>(i) / w.nrc;
    depths.push_back(rough * (section ? std::sqrt(f) : f));
  }
  if (w.fal > 0) depths.push_back(w.tdep);
  for (int i = 0; i < w.nid; ++i) depths.push_back(w.tdep);
  return depths;
}

}  // namespace

Cycle98Expansion expand_cycle98(const Cycle98Words& w) {
  Cycle98Expansion out;
  if (w.vari < 1 || w.vari > 4) {
    out.alarm = fmt::format("VARI {} is not 1 to 4", w.vari);
    return out;
  }
  if (w.nrc < 1 || w.nid < 0 || w.numth < 0 || !(w.tdep > 0) || w.fal < 0 || w.fal >= w.tdep ||
      w.app < 0 || w.rop < 0) {
    out.alarm = fmt::format(
        "not a thread CYCLE98 can cut: NRC {}, NID {}, NUMTH {}, TDEP {}, FAL {}, APP {}, ROP {} "
        "(needs NRC >= 1, 0 <= FAL < TDEP, APP and ROP 0 or more)",
        w.nrc, w.nid, w.numth, w.tdep, w.fal, w.app, w.rop);
    return out;
  }
  const std::vector<Vec2> pts = contour_of(w, out.alarm);
  if (pts.empty()) return out;
  const Vec2 a{0, pts[1].z > pts[0].z ? 1.0 : -1.0};  // cutting direction along Z
  const Vec2 in{w.vari == 2 || w.vari == 4 ? 1.0 : -1.0, 0};
  const Vec2 first = (1 / length(pts[1] - pts[0])) * (pts[1] - pts[0]);
  const Vec2 last =
      (1 / length(pts.back() - pts[pts.size() - 2])) * (pts.back() - pts[pts.size() - 2]);
  const double tan_iang = std::tan(radians(w.iang));
  const double slide = w.tdep * std::max(0.0, tan_iang) / dot(last, a) + w.rop;
  Vec2 into{last.z, -last.x};  // the last segment's normal toward the material
  if (dot(into, in) < 0) into = -into;
  const Vec2 run_out = w.rop * last - w.rop * into;
  const std::vector<double> depths = depths_of(w);
  const int starts = std::max(1, w.numth);
  for (int k = 0; k < starts; ++k) {
    for (double d : depths) {
      const Vec2 base = d * in + (d * tan_iang) * a;
      Cut c;
      c.start = k;
      c.depth = d;
      c.from = pts.front() + base - w.app * first;
      for (size_t j = 1; j + 1 < pts.size(); ++j) c.corners.push_back(pts[j] + base);
      c.to = pts.back() + base - slide * last;
      c.end = w.rop > 0 ? c.to + run_out : c.to;
      out.cuts.push_back(std::move(c));
    }
  }
  return out;
}

}  // namespace clpost

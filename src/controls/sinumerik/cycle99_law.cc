#include "controls/sinumerik/cycle99_law.h"

#include <fmt/format.h>

#include <cmath>
#include <numbers>

namespace clpost {

namespace {

Vec2 add(Vec2 a, Vec2 b) {
  return {a.x + b.x, a.z + b.z};
}
Vec2 mul(double k, Vec2 a) {
  return {k * a.x, k * a.z};
}
double dot(Vec2 a, Vec2 b) {
  return a.x * b.x + a.z * b.z;
}

bool internal_vari(int vari) {
  return vari == kVariInternalConstantInfeed || vari == kVariInternalConstantSection;
}
bool section_vari(int vari) {
  return vari == kVariExternalConstantSection || vari == kVariInternalConstantSection;
}

}  // namespace

double cycle99_lead(const Cycle99Words& w, bool inch) {
  if (w.pita == 1) return w.pit;
  if (w.pita == 2 && w.pit > 0) return (inch ? 1.0 : 25.4) / w.pit;
  return 0;
}

Cycle99Expansion expand_cycle99(const Cycle99Words& w) {
  Cycle99Expansion out;
  if (w.vari < kVariExternalConstantInfeed || w.vari > kVariInternalConstantSection) {
    out.alarm = fmt::format("alarm 61002: machining type defined incorrectly (VARI {})", w.vari);
    return out;
  }
  if (w.psys != 0 && w.psys != 10 && w.psys != 20) {
    out.alarm = fmt::format("PSYS {} is not 0 (longitudinal), 10 (face) or 20 (taper)", w.psys);
    return out;
  }
  if (w.nrc < 1 || w.nid < 0 || w.numth < 0 || !(w.tdep > 0) || w.fal < 0 || w.fal >= w.tdep) {
    out.alarm = fmt::format(
        "not a thread CYCLE99 can cut: NRC {}, NID {}, NUMTH {}, TDEP {}, FAL {} (needs NRC >= 1 "
        "and 0 <= FAL < TDEP)",
        w.nrc, w.nid, w.numth, w.tdep, w.fal);
    return out;
  }
  const Vec2 ps{w.dm1 / 2, w.spl};
  const Vec2 pf{w.dm2 / 2, w.fpl};
  const Vec2 d{pf.x - ps.x, pf.z - ps.z};
  const double len = std::hypot(d.x, d.z);
  if (len <= 0) {
    out.alarm = "the thread has no length (SPL, DM1 = FPL, DM2)";
    return out;
  }
  const Vec2 t = mul(1 / len, d);
  // The infeed axis, toward the material.
  const Vec2 a_in = w.psys == 10 ? Vec2{0, -1} : Vec2{internal_vari(w.vari) ? 1.0 : -1.0, 0};
  Vec2 n{t.z, -t.x};
  if (dot(n, a_in) < 0) n = mul(-1, n);
  const double cosv = dot(n, a_in);  // perpendicular depth per unit of paraxial depth
  if (cosv < 1e-6) {
    out.alarm = "the thread runs along the infeed axis";
    return out;
  }
  const double tan_iang = std::tan(w.iang * std::numbers::pi / 180);

  // Paraxial depths, cut by cut.
  std::vector<double> depths;
  const double rough = w.tdep - w.fal;
  for (int i = 1; i <= w.nrc; ++i) {
    double f = static_cast<double>(i) / w.nrc;
    depths.push_back(rough * (section_vari(w.vari) ? std::sqrt(f) : f));
  }
  if (w.fal > 0) depths.push_back(w.tdep);
  for (int i = 0; i < w.nid; ++i) depths.push_back(w.tdep);

  const double shift_full = w.tdep * cosv * tan_iang;
  const Vec2 start = add(ps, mul(-w.app, t));
  const Vec2 end = add(pf, mul(-w.rop, t));
  const Vec2 runout = add(mul(w.rop, t), mul(-w.rop, n));
  const int starts = std::max(1, w.numth);
  out.cuts.reserve(depths.size() * static_cast<size_t>(starts));
  for (int k = 0; k < starts; ++k) {
    for (double p : depths) {
      const double dperp = p * cosv;
      const Vec2 offset = add(mul(p, a_in), mul(dperp * tan_iang, t));
      Cut c;
      c.start = k;
      c.depth = dperp;
      c.from = add(start, offset);
      c.to = add(add(end, offset), mul(-shift_full, t));
      c.end = w.rop > 0 ? add(c.to, runout) : c.to;
      out.cuts.push_back(c);
    }
  }
  return out;
}

}  // namespace clpost

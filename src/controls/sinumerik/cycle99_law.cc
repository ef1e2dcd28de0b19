#include "controls/sinumerik/cycle99_law.h"
#include "support/angles.h"

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

namespace {

// The control's refusal of the words themselves (alarm text), "" when it takes them.
std::string words_alarm(const Cycle99Words& w) {
  if (w.vari < kVariExternalConstantInfeed || w.vari > kVariInternalConstantSection)
    return fmt::format("alarm 61002: machining type defined incorrectly (VARI {})", w.vari);
  if (w.psys != 0 && w.psys != 10 && w.psys != 20)
    return fmt::format("PSYS {} is not 0 (longitudinal), 10 (face) or 20 (taper)", w.psys);
  if (w.nrc < 1 || w.nid < 0 || w.numth < 0 || !(w.tdep > 0) || w.fal < 0 || w.fal >= w.tdep)
    return fmt::format(
        "not a thread CYCLE99 can cut: NRC {}, NID {}, NUMTH {}, TDEP {}, FAL {} (needs NRC >= 1 "
        "and 0 <= FAL < TDEP)",
        w.nrc, w.nid, w.numth, w.tdep, w.fal);
  return {};
}

// The thread line from (DM1/2, SPL) to (DM2/2, FPL) and the directions the cuts are set out in.
struct ThreadLine {
  Vec2 ps, pf;      // its start and end
  Vec2 t;           // along it, the cutting direction
  Vec2 a_in;        // the infeed axis, toward the material
  Vec2 n;           // at right angles to it, toward the material
  double cosv = 0;  // perpendicular depth per unit of paraxial depth
};

// Sets `line` from the words; the alarm when the line has no length or runs along the infeed
// axis, else "".
std::string thread_line(const Cycle99Words& w, ThreadLine& line) {
  line.ps = {w.dm1 / 2, w.spl};
  line.pf = {w.dm2 / 2, w.fpl};
  const Vec2 d{line.pf.x - line.ps.x, line.pf.z - line.ps.z};
  const double len = std::hypot(d.x, d.z);
  if (len <= 0) return "the thread has no length (SPL, DM1 = FPL, DM2)";
  line.t = mul(1 / len, d);
  // The infeed axis, toward the material.
  line.a_in = w.psys == 10 ? Vec2{0, -1} : Vec2{internal_vari(w.vari) ? 1.0 : -1.0, 0};
  line.n = {line.t.z, -line.t.x};
  if (dot(line.n, line.a_in) < 0) line.n = mul(-1, line.n);
  line.cosv = dot(line.n, line.a_in);  // perpendicular depth per unit of paraxial depth
  if (line.cosv < 1e-6) return "the thread runs along the infeed axis";
  return {};
}

// Paraxial depths, cut by cut: NRC roughing cuts to TDEP - FAL (constant infeed or constant
// cross-section by VARI), the finishing cut at TDEP when FAL > 0, then NID idle passes at TDEP.
std::vector<double> paraxial_depths(const Cycle99Words& w) {
  std::vector<double> depths;
  const double rough = w.tdep - w.fal;
  for (int i = 1; i <= w.nrc; ++i) {
    double f = static_cast<double>(i) / w.nrc;
    depths.push_back(rough * (section_vari(w.vari) ? std::sqrt(f) : f));
  }
  if (w.fal > 0) depths.push_back(w.tdep);
  for (int i = 0; i < w.nid; ++i) depths.push_back(w.tdep);
  return depths;
}

// The cuts at `depths`, start after start: each the thread line from APP before SPL to ROP before
// FPL, moved by its depth along the infeed axis and shifted along the line by IANG, less the
// full-depth shift, with the 45-degree run-out over ROP.
std::vector<Cut> thread_cuts(const Cycle99Words& w, const ThreadLine& line,
                             const std::vector<double>& depths) {
  const Vec2 t = line.t, n = line.n;
  const double tan_iang = std::tan(radians(w.iang));
  const double shift_full = w.tdep * line.cosv * tan_iang;
  const Vec2 start = add(line.ps, mul(-w.app, t));
  const Vec2 end = add(line.pf, mul(-w.rop, t));
  const Vec2 runout = add(mul(w.rop, t), mul(-w.rop, n));
  const int starts = std::max(1, w.numth);
  std::vector<Cut> cuts;
  cuts.reserve(depths.size() * static_cast<size_t>(starts));
  for (int k = 0; k < starts; ++k) {
    for (double p : depths) {
      const double dperp = p * line.cosv;
      const Vec2 offset = add(mul(p, line.a_in), mul(dperp * tan_iang, t));
      Cut c;
      c.start = k;
      c.depth = dperp;
      c.from = add(start, offset);
      c.to = add(add(end, offset), mul(-shift_full, t));
      c.end = w.rop > 0 ? add(c.to, runout) : c.to;
      cuts.push_back(c);
    }
  }
  return cuts;
}

}  // namespace

Cycle99Expansion expand_cycle99(const Cycle99Words& w) {
  Cycle99Expansion out;
  out.alarm = words_alarm(w);
  if (!out.alarm.empty()) return out;
  ThreadLine line;
  out.alarm = thread_line(w, line);
  if (!out.alarm.empty()) return out;
  out.cuts = thread_cuts(w, line, paraxial_depths(w));
  return out;
}

}  // namespace clpost

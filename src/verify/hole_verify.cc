#include "verify/hole_verify.h"

#include <fmt/format.h>

#include <algorithm>
#include <cmath>
#include <numbers>

#include "laws/cut_pass.h"
#include "support/angles.h"

namespace clpost {

namespace {

std::string z_text(double z) {
  return fmt::format("Z{:.4f}", z);
}

// A position along hole `h`'s axis: Z, or X (a radius) for a radial hole.
std::string along_text(const Hole& h, double v) {
  return h.radial ? fmt::format("X{:.4f} (radius)", v) : z_text(v);
}

// Where hole `p` is drilled against CL hole `h`: its X (a radius; a radial hole: its Z), and off
// the centre line its C (docs/millturn.md), the angle as the arc it moves the hole at its radius
// (a radial hole: at its top); "" when the same.
std::string position_difference(const Hole& h, const SimHole& p, double tol) {
  if (h.radial != p.radial)
    return h.radial ? "drilled along Z, CL: a radial hole along X" : "drilled along X, CL along Z";
  if (h.radial && std::fabs(p.z - h.z) > tol)
    return fmt::format("at {}, CL {}", z_text(p.z), z_text(h.z));
  const double radius = h.radial ? h.top : h.x;
  if (!h.radial && std::fabs(p.x - h.x) > tol)
    return fmt::format("at radius {:.4f}, CL radius {:.4f}", p.x, h.x);
  if (std::fabs(radius) <= tol) return {};
  if (!h.c || !p.c)
    return h.c ? fmt::format("C is not written, CL C{:.4f}", *h.c)
               : fmt::format("at C{:.4f} off the centre line, where the CL has no C", *p.c);
  const double turn = std::remainder(*p.c - *h.c, 360.0);
  if (radians(std::fabs(turn)) * std::fabs(radius) > tol)
    return fmt::format("at C{:.4f}, CL C{:.4f} ({:.4f} mm along the circle of radius {:.4f})", *p.c,
                       *h.c, radians(std::fabs(turn)) * std::fabs(radius), std::fabs(radius));
  return {};
}

// The first difference between CL hole `h` and the program's `p`, or "".
std::string hole_difference(const Hole& h, const SimHole& p, double tol) {
  const std::vector<double> want = hole_feed_ends(h);
  if (p.feed_ends.empty()) return "the program does not feed into it";
  if (std::string at = position_difference(h, p, tol); !at.empty()) return at;
  if (std::fabs(p.feed_ends.back() - h.bottom) > tol)
    return fmt::format("bottom {}, CL {}", along_text(h, p.feed_ends.back()),
                       along_text(h, h.bottom));
  if (std::fabs(p.r - h.r) > tol)
    return fmt::format("feeds in from {}, CL R plane {}", along_text(h, p.r), along_text(h, h.r));
  if (p.feed_ends.size() != want.size())
    return fmt::format("{} feeds into the hole, CL {}", p.feed_ends.size(), want.size());
  for (size_t i = 0; i < want.size(); ++i)
    if (std::fabs(p.feed_ends[i] - want[i]) > tol)
      return fmt::format("peck {} ends at {}, CL {}", i + 1, along_text(h, p.feed_ends[i]),
                         along_text(h, want[i]));
  // Out of the hole: back to its R plane, or to its retract plane where that is nearer the hole
  // (a drill that starts below its R plane returns there).
  const double out_to = (h.retract - h.r) * h.dir > 0 ? h.retract : h.r;
  if (!p.left && !(p.out && (*p.out - out_to) * h.dir <= tol))
    return fmt::format("the tool does not come back out to {}", along_text(h, out_to));
  if (h.kind == HoleKind::kTap && h.c && !p.lead)
    return "the live tool's speed is not written before the tap: its lead is not known";
  if (h.kind == HoleKind::kTap && p.lead && std::fabs(*p.lead - h.lead) > 1e-6)
    return fmt::format("lead {:g}, CL {:g}", *p.lead, h.lead);
  return {};
}

void problem(Diagnostics& d, const SimHole* p, std::string msg) {
  if (p != nullptr) {
    d.error(SourceLoc{p->line, 1}, p->line_text, std::move(msg));
  } else {
    d.error({}, {}, std::move(msg));
  }
}

}  // namespace

HoleReport verify_holes(const std::vector<Hole>& cl, const std::vector<SimHole>& nc,
                        const Machine& m, const VerifyOptions& options, Diagnostics& nc_diags) {
  HoleReport r;
  if (cl.empty() && std::all_of(nc.begin(), nc.end(), [](const SimHole& h) {
        return h.source == "moves" && h.feed_ends.empty();
      }))
    return r;
  const double shown = options.tolerance > 0 ? options.tolerance : cut_tolerance(m);
  const double tol = shown + 1e-9;
  std::vector<bool> used(nc.size(), false);
  // A marker comment no CL hole claims, with no feed into a hole after it, is only a comment.
  const auto just_a_comment = [&](size_t i) {
    return !used[i] && nc[i].source == "moves" && nc[i].feed_ends.empty();
  };
  const std::string& from = options.plan_name;
  for (const Hole& h : cl) {
    const SimHole* p = nullptr;
    for (size_t i = 0; i < nc.size() && p == nullptr; ++i)
      if (!used[i] && nc[i].cl_line == h.cl_line) used[i] = true, p = &nc[i];
    const std::string what =
        fmt::format("{}:{}  {}{} to {}", from, h.cl_line, h.radial ? "radial " : "",
                    hole_kind_name(h.kind), along_text(h, h.bottom));
    const std::string why = p == nullptr ? "not in the program" : hole_difference(h, *p, tol);
    if (why.empty()) {
      r.text += fmt::format("  {}  ok  {}, NC line {}\n", what, p->source, p->line);
      continue;
    }
    ++r.problems;
    r.text += fmt::format("  {}  DIFFERS: {}\n", what, why);
    problem(nc_diags, p, fmt::format("hole at {}:{}: {}", from, h.cl_line, why));
  }
  size_t in_program = nc.size();
  for (size_t i = 0; i < nc.size(); ++i) {
    if (just_a_comment(i)) --in_program;
    if (used[i] || just_a_comment(i)) continue;
    ++r.problems;
    r.text += fmt::format("  hole at NC line {}  DIFFERS: the CL has no such hole\n", nc[i].line);
    problem(nc_diags, &nc[i],
            nc[i].cl_line > 0
                ? fmt::format("a hole for {}:{}, where the CL has none", from, nc[i].cl_line)
                : std::string("a hole the CL does not have"));
  }
  const auto off_centre =
      std::count_if(cl.begin(), cl.end(), [](const Hole& h) { return h.c && !h.radial; });
  const auto radial = std::count_if(cl.begin(), cl.end(), [](const Hole& h) { return h.radial; });
  r.text = fmt::format(
      "holes {}: {} in the CL, {} in the program\n{}{}\n",
      off_centre + radial == 0 ? std::string("on the centre line")
      : radial == 0            ? fmt::format("({} on the face at their X and C)", off_centre)
                    : fmt::format("({} on the face at their X and C, {} radial at their Z and C)",
                                  off_centre, radial),
      cl.size(), in_program, r.text,
      r.problems == 0 ? fmt::format("ok: every hole is drilled as planned, within {:g}", shown)
                      : fmt::format("FAILED: {} of the holes not drilled as planned", r.problems));
  return r;
}

}  // namespace clpost

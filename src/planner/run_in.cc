// Run-in and run-out (run_in.h).
#include "planner/run_in.h"

#include <fmt/format.h>

#include <algorithm>
#include <cmath>
#include <vector>

#include "support/number_text.h"
#include "support/vec2_math.h"

namespace clpost {

using namespace vec2_math;

namespace {

// Lengths below this (CL units) are zero.
constexpr double kEps = 1e-9;

// a − 1 − ln a: δ1 / (T1·V).
double run_in_factor(double a) {
  return a - 1 - std::log(a);
}

double along(Vec2 p, bool along_z) {
  return along_z ? p.z : p.x;
}

// The synchronized cuts, each from its first point to its last.
struct CutEnds {
  Vec2 from, to;
};

std::vector<CutEnds> cut_ends(const ThreadPlan& plan) {
  std::vector<CutEnds> cuts;
  const bool path_form = plan.form == ThreadForm::kSingle || plan.form == ThreadForm::kCouple;
  if (path_form && plan.path.size() >= 2) {
    cuts.push_back({plan.path.front(), plan.path.back()});
    return cuts;
  }
  for (const ThreadPass& p : plan.passes) cuts.push_back({p.from, p.to});
  return cuts;
}

// The thread line as the CL gives it, for the lead at its end: its length and first direction.
double line_length(const ThreadPlan& plan) {
  const std::vector<Vec2>& pts = plan.form == ThreadForm::kChain ? plan.points : plan.path;
  if (pts.size() < 2) return length(plan.p2 - plan.p1);
  double len = 0;
  for (size_t j = 1; j < pts.size(); ++j) len += length(pts[j] - pts[j - 1]);
  return len;
}

Vec2 first_direction(const ThreadPlan& plan) {
  Vec2 d = plan.p2 - plan.p1;
  if (plan.form == ThreadForm::kChain && plan.points.size() >= 2)
    d = plan.points[1] - plan.points[0];
  const double len = length(d);
  return len > 0 ? (1 / len) * d : Vec2{0, 1};
}

}  // namespace

RunInOut run_in_out(double rpm, double lead, const LeadLaw& law) {
  if (!(rpm > 0) || !(lead > 0) || !(law.lead_error > 0)) return {};
  const double t1v = law.servo_time_constant * rpm * lead / 60;
  return {t1v * run_in_factor(law.lead_error), t1v};
}

RunInOut short_form_run_in_out(double rpm, double lead, double lead_error) {
  const double base = rpm * lead / 1800;
  return {base * (-1 - std::log(lead_error)), base};
}

int largest_rpm_with_right_lead(double length, double lead, const LeadLaw& law,
                                bool run_in_inside) {
  const double per_rpm = law.servo_time_constant * lead / 60 *
                         (1 + (run_in_inside ? run_in_factor(law.lead_error) : 0));
  if (!(length > 0) || !(per_rpm > 0)) return 0;
  // Below `limit` rpm the two are shorter than the cut; at it they fill it exactly.
  const double limit = length / per_rpm;
  if (limit > 1e9) return 1000000000;
  return std::max(0, static_cast<int>(std::ceil(limit)) - 1);
}

void set_run_in_out(ThreadPlan& plan, double rpm, const LeadLaw& law) {
  plan.rpm = rpm > 0 ? rpm : 0;
  const double start_lead = plan.lead;
  double end_lead = plan.lead;
  if (plan.pitch.lead_change != 0) {
    // K² grows by 2·ΔK per unit of travel (as the emulation's variable lead does).
    const double k2 = start_lead * start_lead + 2 * plan.pitch.lead_change * line_length(plan);
    end_lead = std::sqrt(std::max(0.0, k2));
  }
  plan.run_in = run_in_out(plan.rpm, start_lead, law).run_in;
  plan.run_out = run_in_out(plan.rpm, end_lead, law).run_out;
}

void plan_run_in_out(ThreadPlan& plan, double rpm, const LeadLaw& law, bool add_run_in) {
  set_run_in_out(plan, rpm, law);
  plan.run_in_added = add_run_in && plan.run_in > 0;
}

double added_run_in_along(const ThreadPlan& plan) {
  if (!plan.run_in_added) return 0;
  const double t_lead = std::fabs(along(first_direction(plan), plan.lead_along_z));
  return t_lead > kEps ? plan.run_in / t_lead : 0;
}

LeadSpan lead_span(const ThreadPlan& plan) {
  LeadSpan s;
  const std::vector<CutEnds> cuts = cut_ends(plan);
  if (!(plan.rpm > 0) || cuts.empty()) return s;
  s.known = true;
  s.along_z = plan.lead_along_z;
  const double first = along(cuts[0].to, s.along_z) - along(cuts[0].from, s.along_z);
  const double dir = first < 0 ? -1 : 1;  // the cutting direction along the lead axis
  double lo = dir * along(cuts[0].from, s.along_z), hi = dir * along(cuts[0].to, s.along_z);
  for (const CutEnds& c : cuts) {
    lo = std::max(lo, dir * along(c.from, s.along_z));
    hi = std::min(hi, dir * along(c.to, s.along_z));
  }
  s.cut_from = dir * lo;
  s.cut_to = dir * hi;
  s.from = dir * (lo + plan.run_in);
  s.to = dir * (hi - plan.run_out);
  s.any = (hi - plan.run_out) - (lo + plan.run_in) > kEps;
  return s;
}

std::string no_right_lead_warning(const ThreadPlan& plan, const LeadLaw& law) {
  const LeadSpan s = lead_span(plan);
  if (!s.known || s.any) return {};
  const double cut = std::fabs(s.cut_to - s.cut_from);
  // The cut as the CL gives it: without the run-in clpost added before its start.
  const double added = plan.run_in_added ? plan.run_in : 0;
  const int rpm = largest_rpm_with_right_lead(cut - added, plan.lead, law, !plan.run_in_added);
  return fmt::format(
      "run-in {} and run-out {} at {} rpm, lead {}, cover the whole synchronized cut ({} long): "
      "no length of this thread has the right lead; {}",
      num_text(plan.run_in), num_text(plan.run_out), num_text(plan.rpm), num_text(plan.lead),
      num_text(cut),
      rpm > 0 ? fmt::format("{} rpm or less leaves one", rpm)
              : std::string("no speed of 1 rpm or more leaves one"));
}

}  // namespace clpost

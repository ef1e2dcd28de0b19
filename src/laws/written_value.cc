#include "laws/written_value.h"

#include <fmt/format.h>

#include <algorithm>
#include <charconv>
#include <cmath>
#include <string>

#include "writer/number_format.h"

namespace clpost {

namespace {
double unscale(const NumberFormat& nf) {
  return nf.scale > 0 ? nf.scale : 1;
}
}  // namespace

double as_read(const Machine& m, std::string_view f, double v) {
  return as_read(m.format_for(f), v);
}

double as_read(const NumberFormat& nf, double v) {
  const std::string s = number_text(v, nf);
  double r = 0;
  std::from_chars(s.data(), s.data() + s.size(), r);
  r /= unscale(nf);
  return r == 0 ? 0 : r;
}

double least_increment(const Machine& m, std::string_view f) {
  return least_increment(m.format_for(f));
}

double least_increment(const NumberFormat& nf) {
  return std::pow(10.0, -nf.decimals) / unscale(nf);
}

double read_up(const Machine& m, std::string_view f, double v) {
  double r = as_read(m, f, v);
  if (r < v - 1e-9) r = as_read(m, f, r + least_increment(m, f));
  return r;
}

double read_down(const Machine& m, std::string_view f, double v) {
  double r = as_read(m, f, v);
  if (r > v + 1e-9) r = as_read(m, f, r - least_increment(m, f));
  return r;
}

Vec2 point_as_read(const Machine& m, Vec2 p) {
  const double k = diameter_factor(m);
  return {as_read(m, "X", k * p.x) / k, as_read(m, "Z", p.z)};
}

double thread_turns(const ThreadPlan& plan) {
  Vec2 d{plan.p2.x - plan.p1.x, plan.p2.z - plan.p1.z};
  if (plan.form != ThreadForm::kMulti && plan.path.size() >= 2)
    d = {plan.path.back().x - plan.path.front().x, plan.path.back().z - plan.path.front().z};
  const double travel = plan.lead_along_z ? std::fabs(d.z) : std::fabs(d.x);
  return plan.lead > 0 ? std::max(1.0, travel / plan.lead) : 1;
}

std::string lead_mismatch(const Machine& m, const ThreadPlan& plan, double lead,
                          std::string_view word, std::string_view format, double tol) {
  const double turns = thread_turns(plan);
  const double off = std::fabs(lead - plan.lead) * turns;
  if (!(plan.lead > 0) || off <= tol) return {};
  const int decimals = m.format_for(format).decimals;
  return fmt::format(
      "the lead {:.6f} is written {}, {:.6f} (formats.{}: {} decimal{}): {:.4g} off over the "
      "thread's {:.1f} turns, more than the tolerance {:g}",
      plan.lead, word, lead, format, decimals, decimals == 1 ? "" : "s", off, turns, tol);
}

std::string lead_word_mismatch(const Machine& m, const ThreadPlan& plan, std::string_view address,
                               std::string_view format, double tol) {
  const std::string word =
      fmt::format("{}{}", address, number_text(plan.lead, m.format_for(format)));
  return lead_mismatch(m, plan, as_read(m, format, plan.lead), word, format, tol);
}

std::string sync_lead_mismatch(const Machine& m, const ThreadPlan& plan, double tol) {
  if (!(plan.lead > 0)) return {};
  if (plan.pitch.from_tpi && !m.tpi_address.empty()) {
    const double per_inch = plan.units == LengthUnit::kMm ? 25.4 : 1.0;
    const std::string& a = m.tpi_address;
    const double tpi = as_read(m, a, per_inch / plan.lead);
    const std::string word =
        fmt::format("{}{}", a, number_text(per_inch / plan.lead, m.format_for(a)));
    return lead_mismatch(m, plan, tpi > 0 ? per_inch / tpi : 0, word, a, tol);
  }
  const bool along_x = !plan.lead_along_z && !m.thread_lead_address_x.empty();
  const std::string& a = along_x ? m.thread_lead_address_x : m.thread_lead_address;
  return lead_word_mismatch(m, plan, a, a, tol);
}

}  // namespace clpost

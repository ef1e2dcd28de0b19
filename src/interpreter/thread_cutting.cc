// Writing planned threads (thread_cutting.h).
#include "interpreter/thread_cutting.h"

#include <fmt/format.h>

#include <algorithm>
#include <cmath>
#include <numbers>
#include <tuple>

#include "emitters/emulation_emitter.h"
#include "interpreter/clock.h"
#include "interpreter/statement_table.h"

namespace clpost {

double thread_rpm(const PostState& s, double radius) {
  const SpindleState& sp = s.spindle;
  if (!sp.on) return 0;
  if (!sp.css) return sp.value;
  // Constant surface speed cannot cut a thread: the rpm it gives at the thread's largest
  // diameter, limited by the CSS speed limit.
  const double diameter = 2 * std::max(std::abs(radius), 1e-9);
  const double per_unit = s.units == LengthUnit::kInch ? 12.0 : 1000.0;  // ft/min or m/min
  const double rpm = std::floor(sp.value * per_unit / (std::numbers::pi * diameter));
  return std::max(std::min(rpm, sp.css_max_rpm), 1.0);
}

bool begin_thread_spindle(PostState& s, double radius, CutSite at) {
  restart_stopped_spindle(s, at.loc, at.line);
  const SpindleState& sp = s.spindle;
  if (!sp.on) {
    s.diags.error(at.loc, at.line,
                  "thread cut with the spindle stopped: program SPINDL/ before the thread");
    return false;
  }
  ThreadSequence& t = s.thread;
  t.rpm = sp.value;
  t.forced_rpm = false;
  if (!sp.css) return true;
  // Turned into the rpm at the thread's largest diameter; CSS is restored afterwards.
  const double rpm = thread_rpm(s, radius);
  ensure_started(s);
  s.prog.comment(
      fmt::format("constant surface speed {} off for the thread: {} rpm", sp.value, rpm));
  if (TemplateWrite r = s.prog.spindle_rpm(rpm, sp.dir); !r) {
    s.diags.error(at.loc, at.line, template_error(s.m, r));
    return false;
  }
  t.rpm = rpm;
  t.forced_rpm = true;
  return true;
}

void end_thread_spindle(PostState& s) {
  if (!s.thread.forced_rpm) return;
  s.thread.forced_rpm = false;
  // Written at its SPINDL line already, so it cannot fail here; never silently, though.
  if (TemplateWrite r = s.prog.spindle_css(s.spindle.value, s.spindle.css_max_rpm, s.spindle.dir);
      !r)
    s.diags.error(SourceLoc{}, {}, template_error(s.m, r));
}

bool check_thread_feed(PostState& s, Vec2 from, Vec2 to, double lead, CutSite at) {
  const Machine& m = s.m;
  const double rpm = s.thread.rpm;
  const double feed = lead * rpm;
  if (m.max_feed > 0 && feed > m.max_feed + 1e-9) {
    s.diags.error(at.loc, at.line,
                  fmt::format("thread feed too fast for machine '{}': lead {} x {} rpm = {} per "
                              "minute, above its maximum feed {}",
                              m.name, lead, rpm, feed, m.max_feed));
    return false;
  }
  // The axis of the larger travel moves the lead per revolution (as G33 measures it), the
  // other one its share: a taper's X, a face taper's Z.
  const double dx = std::abs(to.x - from.x), dz = std::abs(to.z - from.z);
  const bool along_z = dz >= dx;
  const double fz = along_z ? feed : (dx > 0 ? feed * dz / dx : 0);
  const double fx = along_z ? (dz > 0 ? feed * dx / dz : 0) : feed;
  for (auto [axis, f, limit] :
       {std::tuple{'X', fx, m.max_feed_x}, std::tuple{'Z', fz, m.max_feed_z}}) {
    if (limit > 0 && f > limit + 1e-9) {
      s.diags.error(
          at.loc, at.line,
          fmt::format("thread feed too fast for machine '{}': the {} axis moves {} per "
                      "minute (lead {} x {} rpm), above its limit {} (limits.max_feed_{})",
                      m.name, axis, f, lead, rpm, limit, static_cast<char>(axis + 32)));
      return false;
    }
  }
  return true;
}

void warn_no_right_lead(PostState& s, const ThreadPlan& plan, CutSite at) {
  const std::string why = no_right_lead_warning(plan, s.thread.settings.lead_law);
  if (!why.empty()) s.diags.warning(at.loc, at.line, why);
}

void thread_planned(PostState& s, const ThreadPlan& plan) {
  ++s.stats.threads;
  if (s.on_thread) s.on_thread(plan);
}

void cut_multi_thread(PostState& s, ThreadPlan& plan, const SavedLines& lines) {
  ensure_started(s);
  const CutSite at{plan.loc, lines.text(plan.loc.line)};
  double radius = std::max(std::abs(plan.p1.x), std::abs(plan.p2.x));
  for (const Vec2& p : plan.points) radius = std::max(radius, std::abs(p.x));  // a chain
  if (!begin_thread_spindle(s, radius, at)) return;
  // Every synchronized move: the thread line, and the pull-out when it is cut synchronized.
  bool fits = true;
  if (plan.form == ThreadForm::kChain) {
    for (size_t j = 1; fits && j < plan.points.size(); ++j)
      fits = check_thread_feed(s, plan.points[j - 1], plan.points[j], plan.lead, at);
  } else {
    fits = check_thread_feed(s, plan.p1, plan.p2, plan.lead, at);
  }
  if (fits && plan.pullout && !plan.pullout_linear && !plan.passes.empty())
    fits = check_thread_feed(s, plan.passes[0].to, plan.passes[0].pullout_end, plan.lead, at);
  if (!fits) return;
  warn_no_right_lead(s, plan, at);
  thread_planned(s, plan);
  s.stats.passes += plan.passes.size();
  s.prog.comment(fmt::format("thread line {}: {} passes, pitch {:.6g}, depth {:.6g}", plan.loc.line,
                             plan.passes.size(), plan.pitch.pitch, plan.depth));
  EmitContext ctx{s.diags, lines, s.thread.rpm, s.feed, s.feed_mode, plan.loc, &s.outputs};
  s.thread.emitter->emit(plan, s.prog, ctx);
  time_thread(s, plan, s.thread.rpm);
  s.stats.motions += plan.passes.size() * 4;
  s.pos = cl_point(s, plan.end_position);  // where the plan leaves the tool
  record_exit(s, plan.loc.line, plan.end_position, {}, static_cast<uint32_t>(plan.passes.size()));
  end_thread_spindle(s);
}

bool cut_path_move(PostState& s, const ThreadPlan& plan, const ThreadPass& pass, double travel,
                   CutSite at) {
  ThreadLead lead = thread_lead(plan);
  if (lead.lead_change != 0) {
    const char* code = lead.lead_change > 0 ? "thread_increasing" : "thread_decreasing";
    if (s.m.code(code).empty()) {
      s.diags.error(
          at.loc, at.line,
          fmt::format("machine '{}' has no code for a variable lead ({})", s.m.name, code));
      return false;
    }
    if (travel > 0) {
      // The lead where this move begins: K² grows by 2·ΔK per unit of travel (as the
      // emulation's pull-out does).
      lead.lead = std::sqrt(std::max(0.0, lead.lead * lead.lead + 2 * lead.lead_change * travel));
      lead.tpi = 0;
    }
  }
  if (!check_thread_feed(s, pass.from, pass.to, lead.lead, at)) return false;
  s.prog.thread(LathePoint{pass.to.x, pass.to.z}, lead);
  time_sync(s, pass.to, lead.lead, s.thread.rpm);
  ++s.stats.motions;
  ++s.stats.passes;
  return true;
}

}  // namespace clpost

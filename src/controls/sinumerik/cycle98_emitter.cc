// SINUMERIK CYCLE98 for chained threads (cycle98_emitter.h).
#include "controls/sinumerik/cycle98_emitter.h"

#include <fmt/format.h>

#include <algorithm>
#include <cmath>
#include <limits>

#include "controls/sinumerik/cycle99_emitter.h"
#include "controls/sinumerik/sinumerik_templates.h"
#include "laws/written_value.h"
#include "planner/run_in.h"
#include "support/angles.h"
#include "support/number_text.h"
#include "support/vec2_math.h"

namespace clpost {

using namespace vec2_math;

namespace {

// The named number formats CYCLE98 shares with CYCLE99 (posts/sinumerik.yaml).
constexpr std::string_view kDepthFormat = "cycle99_depth";  // APP ROP TDEP FAL _VRT
constexpr std::string_view kAngleFormat = "cycle99_angle";  // IANG NSP
constexpr std::string_view kLeadFormat = "cycle99_lead";    // PP1 PP2 PP3

// What a plan must be for CYCLE98 to be tried at all; the reason when it is not.
std::string cycle98_shape(const ThreadPlan& plan, const Machine& m) {
  if (plan.form != ThreadForm::kChain || plan.passes.empty())
    return "CYCLE98 cuts chained threads (THREAD/ON,...,CHAIN) only";
  if (!m.templates.count(std::string(tmpl::kCycle98.name)))
    return fmt::format("machine '{}' has no 'cycle98' template", m.name);
  if (!plan.lead_along_z) return "a face chain: CYCLE98 cuts along Z";
  if (plan.points.size() > 4)
    return fmt::format("{} segments: CYCLE98 cuts at most 3", plan.points.size() - 1);
  if (plan.option == 0)
    return "OPTION 0, steps shrinking by a constant amount: CYCLE98 cuts constant infeed (VARI "
           "1, "
           "2) or constant cross-section (VARI 3, 4)";
  if (plan.option == 2 || plan.option == 4)
    return fmt::format("OPTION {} alternates the flanks: CYCLE98 infeeds along one flank (IANG)",
                       plan.option);
  if (plan.pitch.starts > 1 && !plan.starts_by_angle)
    return fmt::format(
        "CYCLE98 spreads the {} starts over the spindle angle (NUMTH); this plan "
        "offsets them by the pitch",
        plan.pitch.starts);
  return {};
}

// The first segment's direction.
Vec2 first_segment(const ThreadPlan& plan) {
  const Vec2 d = plan.points[1] - plan.points[0];
  return (1 / length(d)) * d;
}

// Where the cuts start: the contour's first point, less a run-in clpost added before it
// (threading.run_in auto), which CYCLE98 cuts as its run-in APP.
Vec2 cut_start(const ThreadPlan& plan) {
  return plan.points.front() - added_run_in_along(plan) * first_segment(plan);
}

// TDEP, FAL, NRC, NID and IANG from the passes of start 0 (paraxial depths along X).
std::string ladder_words(const ThreadPlan& plan, const Machine& m, Cycle98Words& w) {
  const double in = plan.side == ThreadSide::kInternal ? 1 : -1;
  const double a = plan.points[1].z > plan.points[0].z ? 1 : -1;
  const Vec2 p1 = cut_start(plan);
  const ThreadPass* deepest = nullptr;
  double rough = 0, finish = -1;
  w.nrc = 0;
  w.nid = 0;
  for (const ThreadPass& p : plan.passes) {
    if (p.start != 0) continue;
    const double r = (p.from.x - p1.x) * in;
    if (p.kind == PassKind::kRough) ++w.nrc, rough = r;
    if (p.kind == PassKind::kFinish) finish = r;
    if (p.kind == PassKind::kSpring) ++w.nid;
    if (deepest == nullptr || r > (deepest->from.x - p1.x) * in) deepest = &p;
  }
  const double full = finish >= 0 ? finish : rough;
  if (w.nrc < 1 || !(full > cut_tolerance(m)))
    return "CYCLE98 needs a thread depth (TDEP) and roughing cuts";
  w.tdep = as_read(m, kDepthFormat, full);
  w.fal = finish >= 0 ? as_read(m, kDepthFormat, finish - rough) : 0;
  const double shift = (deepest->from.z - p1.z) * a;
  w.iang = as_read(m, kAngleFormat, degrees(std::atan2(shift, full)));
  const bool section = plan.option == 1 || plan.option == 2;
  w.vari = plan.side == ThreadSide::kInternal ? (section ? 4 : 2) : (section ? 3 : 1);
  return {};
}

// ROP from a 45 degree run-out on the last segment (CL CHAMFR with a negative length).
std::string run_out_word(const ThreadPlan& plan, const Machine& m, Cycle98Words& w) {
  w.rop = 0;
  if (!plan.pullout) return {};
  const Vec2 b = plan.points.back(), a = plan.points[plan.points.size() - 2];
  const Vec2 t = (1 / length(b - a)) * (b - a);
  Vec2 into{t.z, -t.x};
  if (into.x * (plan.side == ThreadSide::kInternal ? 1 : -1) < 0) into = -into;
  // The run-out ends where the pass would have ended: no pass pulls out past the last point.
  const double a_z = plan.points[1].z > plan.points[0].z ? 1 : -1;
  double past = 0;
  for (const ThreadPass& p : plan.passes) past = std::max(past, (p.pullout_end.z - b.z) * a_z);
  if (past > cut_tolerance(m))
    return fmt::format(
        "CYCLE98 has no pull-out past the contour's end, only the run-out ROP "
        "(CL CHAMFR with a negative length); this one ends {} past Z {}",
        num_text(past), num_text(b.z));
  const double along = dot(*plan.pullout, t), out = -dot(*plan.pullout, into);
  if (std::fabs(out - along) > cut_tolerance(m))
    return fmt::format(
        "CYCLE98's run-out ROP leaves the thread at 45 degrees (unverified); this "
        "pull-out rises {} over {}",
        num_text(out), num_text(along));
  w.rop = as_read(m, kDepthFormat, along);
  return {};
}

}  // namespace

Cycle98Call cycle98_call(const ThreadPlan& plan, const Machine& m) {
  Cycle98Call call;
  Cycle98Words& w = call.words;
  call.mismatch = cycle98_shape(plan, m);
  if (call.mismatch.empty()) call.mismatch = ladder_words(plan, m, w);
  if (call.mismatch.empty()) call.mismatch = run_out_word(plan, m, w);
  if (!call.mismatch.empty()) return call;
  for (size_t j = 0; j < 4; ++j) {
    const Vec2 p = plan.points[std::min(j, plan.points.size() - 1)];
    w.po[j] = as_read(m, "Z", p.z);
    w.dm[j] = as_read(m, "X", 2 * p.x);
  }
  for (double& pp : w.pp) pp = as_read(m, kLeadFormat, plan.lead);
  call.mismatch = lead_mismatch(m, plan, w.pp[0], fmt::format("PP1 {}", num_text(w.pp[0])),
                                kLeadFormat, cut_tolerance(m));
  if (!call.mismatch.empty()) return call;
  w.app = as_read(m, kDepthFormat, added_run_in_along(plan));  // 0 unless run_in is auto
  w.numth = plan.pitch.starts > 1 ? plan.pitch.starts : 1;
  w.nsp = 0;
  // _VRT: how far the clear line is outside the contour's outermost point.
  const double out = plan.side == ThreadSide::kInternal ? -1 : 1;
  double vrt = std::numeric_limits<double>::infinity();
  for (const Vec2& p : plan.points) vrt = std::min(vrt, (plan.end_position.x - p.x) * out);
  w.vrt = as_read(m, kDepthFormat, vrt);
  const Cycle98Expansion e = expand_cycle98(w);
  if (!e.alarm.empty()) {
    call.mismatch = "the CYCLE98 law does not cover the words: " + e.alarm;
    return call;
  }
  std::string diff =
      compare_cuts(e.cuts, plan_cuts(plan), {cut_tolerance(m), plan.pitch.starts > 1});
  if (!diff.empty()) call.mismatch = "CYCLE98 would cut " + diff;
  return call;
}

Fit Cycle98Emitter::fit(const ThreadPlan& plan, const Machine& m) const {
  return Fit{cycle98_call(plan, m).mismatch, {}, {}};
}

bool Cycle98Emitter::emit(const ThreadPlan& plan, NcProgram& prog, const EmitContext& ctx) {
  const Machine& m = prog.machine();
  const Cycle98Call c = cycle98_call(plan, m);
  if (!c.mismatch.empty()) return unfit_error(plan, ctx, m, name(), c.mismatch);
  const Cycle98Words& w = c.words;
  const LathePoint above = go_to_cycle_start(plan, prog);  // above the first point
  auto num = [&](std::string_view f, double v) { return prog.num(f, v); };
  TemplateFill<tmpl::kCycle98> a;
  a.text<"po1">(num("Z", w.po[0]));
  a.text<"dm1">(num("X", w.dm[0]));
  a.text<"po2">(num("Z", w.po[1]));
  a.text<"dm2">(num("X", w.dm[1]));
  a.text<"po3">(num("Z", w.po[2]));
  a.text<"dm3">(num("X", w.dm[2]));
  a.text<"po4">(num("Z", w.po[3]));
  a.text<"dm4">(num("X", w.dm[3]));
  fill_shared_cycle_words(a, w, prog);
  a.text<"pp1">(num(kLeadFormat, w.pp[0]));
  a.text<"pp2">(num(kLeadFormat, w.pp[1]));
  a.text<"pp3">(num(kLeadFormat, w.pp[2]));
  a.text<"vari">(std::to_string(w.vari));
  a.text<"numth">(std::to_string(w.numth));
  a.text<"vrt">(num(kDepthFormat, w.vrt));
  if (TemplateWrite r = prog.write_template(a); !r) return template_failed(plan, ctx, m, r);
  // The cycle returns to where it was called from (unverified); the modal words are unknown.
  prog.cycle_ended_at(above);
  return true;
}

}  // namespace clpost

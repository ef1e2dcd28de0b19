#include "emitters/siemens_emitter.h"

#include <fmt/format.h>

#include <algorithm>
#include <cmath>

#include "emitters/written_value.h"
#include "planner/number_text.h"
#include "planner/vec2_math.h"
#include "writer/number_format.h"

namespace clpost {

using namespace vec2_math;

namespace {

// Named number formats of the post (formats: map) for the CYCLE99 words besides X and Z.
constexpr std::string_view kDepthFormat = "cycle99_depth";  // APP ROP TDEP FAL _VRT
constexpr std::string_view kAngleFormat = "cycle99_angle";  // IANG NSP
constexpr std::string_view kLeadFormat = "cycle99_lead";    // PIT

std::string vec_text(Vec2 v) {
  return fmt::format("(X {}, Z {})", num_text(v.x), num_text(v.z));
}

const char* law_name(int vari) {
  return vari == kVariExternalConstantSection || vari == kVariInternalConstantSection
             ? "constant cross-section"
             : "constant infeed";
}

}  // namespace

Cycle99Call cycle99_call(const ThreadPlan& plan, const Machine& m) {
  Cycle99Call call;
  Cycle99Words& w = call.words;
  auto fail = [&](std::string why) {
    call.mismatch = std::move(why);
    return call;
  };
  if (plan.form == ThreadForm::kChain)
    return fail("a chained thread: CYCLE99 cuts one straight thread line");
  if (plan.form != ThreadForm::kMulti || plan.passes.empty())
    return fail("CYCLE99 cuts multi-pass threads (THREAD/ON) only");
  if (!m.templates.count(std::string(tmpl::kCycle99.name)))
    return fail(fmt::format("machine '{}' has no 'cycle99' template", m.name));
  if (plan.pitch.lead_change != 0)
    return fail(fmt::format("CYCLE99 cuts a constant lead; this lead {} by {} per revolution",
                            plan.pitch.lead_change > 0 ? "grows (INCR)" : "shrinks (DECR)",
                            num_text(std::fabs(plan.pitch.lead_change))));
  const double tol = cut_tolerance(m);
  const Vec2 p1 = plan.p1, p2 = plan.p2;
  const double len = length(p2 - p1);
  const Vec2 t = (1 / len) * (p2 - p1);
  const Vec2 u = direction(plan.cutang);
  Vec2 n{t.z, -t.x};  // toward the material (the side the infeed goes to)
  if (dot(n, u) < 0) n = -n;

  // --- Kind, side, infeed axis. ---
  Vec2 a_in;
  if (plan.kind == ThreadKind::kFace) {
    w.psys = 10;
    a_in = {0, -1};
    if (n.z >= 0)
      return fail(
          "CYCLE99 cuts a face thread toward -Z (unverified); this one's infeed goes toward +Z");
  } else {
    if (!plan.lead_along_z)
      return fail(
          fmt::format("CYCLE99 takes a taper thread's lead along Z (unverified); this "
                      "taper's lead is along X (X travel {} > Z travel {})",
                      num_text(std::fabs(p2.x - p1.x)), num_text(std::fabs(p2.z - p1.z))));
    w.psys = plan.kind == ThreadKind::kTaper ? 20 : 0;
    a_in = {plan.side == ThreadSide::kInternal ? 1.0 : -1.0, 0};
  }
  const bool internal = w.psys != 10 && plan.side == ThreadSide::kInternal;
  const double cosv = dot(n, a_in);

  // --- Depth ladder (start 0): NRC roughing cuts, FAL, NID idle passes. ---
  std::vector<const ThreadPass*> ladder;
  for (const ThreadPass& p : plan.passes)
    if (p.start == 0) ladder.push_back(&p);
  int nrc = 0, nid = 0;
  double rough = 0, finish = -1;
  for (const ThreadPass* p : ladder) {
    if (p->kind == PassKind::kRough) ++nrc, rough = p->depth;
    if (p->kind == PassKind::kFinish) finish = p->depth;
    if (p->kind == PassKind::kSpring) ++nid;
  }
  const double full = finish >= 0 ? finish : rough;
  if (!(full > tol))
    return fail("CYCLE99 needs a thread depth (TDEP); this thread is one pass on the contour");
  w.nrc = nrc;
  w.nid = nid;
  w.tdep = as_read(m, kDepthFormat, full / cosv);
  w.fal = finish >= 0 ? as_read(m, kDepthFormat, (finish - rough) / cosv) : 0;

  // --- Flank infeed: every pass's shift along t, beyond what the paraxial infeed gives. ---
  const ThreadPass& deepest = *ladder.back();
  auto shift_of = [&](const ThreadPass& p) {
    return dot(p.from - p1, t) - (p.depth / cosv) * dot(a_in, t);
  };
  const double tan_iang = shift_of(deepest) / deepest.depth;
  for (const ThreadPass* p : ladder) {
    double s = shift_of(*p);
    if (std::fabs(s - p->depth * tan_iang) <= tol) continue;
    if (plan.option == 2 || plan.option == 4)
      return fail(fmt::format(
          "CYCLE99 infeeds along one flank (IANG); OPTION {} alternates the "
          "flanks (pass {} shift {:.4f}, pass {} shift {:.4f})",
          plan.option, ladder.front()->n, shift_of(*ladder.front()), deepest.n, shift_of(deepest)));
    return fail(
        fmt::format("CYCLE99 shifts every cut by depth x tan(IANG); pass {} is shifted "
                    "{:.4f}, not {:.4f}",
                    p->n, s, p->depth * tan_iang));
  }
  const double iang = deg(std::atan(tan_iang));
  if (std::fabs(iang) > plan.tool_angle / 2 + 1e-6)
    return fail(
        fmt::format("IANG {:.4f} is more than half the tool angle {} (CYCLE99 allows at "
                    "most {})",
                    iang, num_text(plan.tool_angle), num_text(plan.tool_angle / 2)));
  w.iang = as_read(m, kAngleFormat, iang);

  // --- Pull-out: only the run-out ROP (CHAMFR with a negative length). ---
  double sigma_max = 0;
  for (const ThreadPass* p : ladder) sigma_max = std::max(sigma_max, p->shift);
  const double shorten = len - sigma_max - dot(deepest.to - deepest.from, t);
  double rop = 0;
  if (plan.pullout) {
    const double along = dot(*plan.pullout, t), out = dot(*plan.pullout, -n);
    if (shorten <= tol)
      return fail(
          fmt::format("CYCLE99 has no pull-out past the thread end, only the run-out ROP "
                      "that ends at FPL (CL CHAMFR with a negative length); this "
                      "pull-out moves {} from the pass end",
                      vec_text(*plan.pullout)));
    if (std::fabs(out - along) > tol)
      return fail(
          fmt::format("CYCLE99's run-out ROP leaves the thread at 45 degrees "
                      "(unverified); this run-out rises {} over {} ({} degrees)",
                      num_text(out), num_text(along), num_text(deg(std::atan2(out, along)))));
    rop = along;
  }
  w.rop = as_read(m, kDepthFormat, rop);
  w.app = as_read(m, kDepthFormat, m.run_in);

  // --- Start and end points: the full-depth cut's run-out ends at FPL. ---
  // Along t the deepest cut's end is FPL - ROP plus what its paraxial infeed moves along t.
  const double end_t = dot(deepest.to - p1, t) - (deepest.depth / cosv) * dot(a_in, t) + rop;
  if (w.app >= end_t)
    return fail(fmt::format("threading.run_in {} is not shorter than the thread ({})",
                            num_text(m.run_in), num_text(end_t)));
  const Vec2 sp = p1 + w.app * t, fp = p1 + end_t * t;
  w.spl = as_read(m, "Z", sp.z);
  w.dm1 = as_read(m, "X", 2 * sp.x);
  w.fpl = as_read(m, "Z", fp.z);
  w.dm2 = as_read(m, "X", 2 * fp.x);

  // --- Starts. ---
  const int starts = plan.pitch.starts;
  if (starts > 1) {
    if (!plan.starts_by_angle)
      return fail(
          fmt::format("CYCLE99 spreads the {} starts over the spindle angle (NUMTH); this "
                      "plan offsets them by the pitch (threading.start_angle_word is "
                      "false)",
                      starts));
    w.numth = starts;
    call.notes.push_back(
        fmt::format("CYCLE99 cuts start by start: every pass of start 1, then of start 2{}",
                    starts > 2 ? " ..." : ""));
  }
  w.nsp = 0;

  // --- Lead. ---
  const bool inch = plan.units == LengthUnit::kInch;
  if (plan.pitch.from_tpi || inch) {
    w.pita = 2;
    w.pit = as_read(m, kLeadFormat, (inch ? 1.0 : 25.4) / plan.lead);
  } else {
    w.pita = 1;
    w.pit = as_read(m, kLeadFormat, plan.lead);
  }
  const double lead = cycle99_lead(w, inch);
  const double travel = plan.lead_along_z ? std::fabs(p2.z - p1.z) : std::fabs(p2.x - p1.x);
  const double turns = travel / plan.lead;
  if (std::fabs(lead - plan.lead) * turns > tol)
    return fail(fmt::format(
        "PIT {} (PITA {}) is a lead of {:.6f}, plan {:.6f}: {:.4f} off over "
        "the thread's {:.1f} turns",
        num_text(w.pit), w.pita, lead, plan.lead, std::fabs(lead - plan.lead) * turns, turns));

  // --- Law and retraction. ---
  const bool section = plan.option == 1 || plan.option == 2;
  w.vari = internal ? (section ? kVariInternalConstantSection : kVariInternalConstantInfeed)
                    : (section ? kVariExternalConstantSection : kVariExternalConstantInfeed);
  w.vrt = as_read(m, kDepthFormat, plan.clearance);

  // --- What the control cuts from these words, against the plan. ---
  Cycle99Expansion cut = expand_cycle99(w);
  if (!cut.alarm.empty()) return fail("CYCLE99 would stop: " + cut.alarm);
  std::string diff = compare_cuts(cut.cuts, plan_cuts(plan), {tol, true});
  if (!diff.empty()) {
    if (plan.option == 0)
      return fail(
          fmt::format("CYCLE99 has no infeed with steps decreasing by a constant amount "
                      "(OPTION 0): VARI {} ({}) cuts {}",
                      w.vari, law_name(w.vari), diff));
    return fail(fmt::format("VARI {} ({}) cuts {}", w.vari, law_name(w.vari), diff));
  }
  return call;
}

Fit Cycle99Emitter::fit(const ThreadPlan& plan, const Machine& m) const {
  Cycle99Call c = cycle99_call(plan, m);
  return Fit{c.mismatch, c.notes};
}

LathePoint go_to_cycle_start(const ThreadPlan& plan, NcProgram& prog) {
  const LathePoint above{plan.end_position.x, plan.end_position.z};
  if (plan.feed_approach)
    prog.linear(above);
  else
    prog.rapid(above);
  return above;
}

bool Cycle99Emitter::emit(const ThreadPlan& plan, NcProgram& prog, const EmitContext& ctx) {
  Cycle99Call c = cycle99_call(plan, prog.machine());
  if (!c.mismatch.empty()) {
    ctx.diags.error(plan.loc, ctx.lines.text(plan.loc.line), "CYCLE99: " + c.mismatch);
    return false;
  }
  const Cycle99Words& w = c.words;
  const LathePoint above = go_to_cycle_start(plan, prog);
  auto num = [&](std::string_view f, double v) { return prog.num(f, v); };
  TemplateFill<tmpl::kCycle99> a;
  a.text<"spl">(num("Z", w.spl));
  a.text<"dm1">(num("X", w.dm1));
  a.text<"fpl">(num("Z", w.fpl));
  a.text<"dm2">(num("X", w.dm2));
  fill_shared_cycle_words(a, w, prog);
  a.text<"pit">(num(kLeadFormat, w.pit));
  a.text<"vari">(std::to_string(w.vari));
  a.text<"numth">(std::to_string(w.numth));
  a.text<"vrt">(num(kDepthFormat, w.vrt));
  a.text<"pita">(std::to_string(w.pita));
  a.text<"psys">(std::to_string(w.psys));
  const Machine& m = prog.machine();
  if (TemplateWrite r = prog.write_template(a); !r) return template_failed(plan, ctx, m, r);
  // The cycle returns to where it was called from (unverified); the modal words are unknown.
  prog.cycle_ended_at(above);
  return true;
}

}  // namespace clpost

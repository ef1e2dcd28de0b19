#include "controls/sinumerik/cycle99_emitter.h"

#include <fmt/format.h>

#include <algorithm>
#include <cmath>

#include "controls/sinumerik/sinumerik_templates.h"
#include "laws/written_value.h"
#include "planner/run_in.h"
#include "support/angles.h"
#include "support/number_text.h"
#include "support/vec2_math.h"
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

// Why CYCLE99 cannot cut this kind of plan at all (empty: it may).
std::string cycle99_refusal(const ThreadPlan& plan, const Machine& m) {
  if (plan.form == ThreadForm::kChain)
    return "a chained thread: CYCLE99 cuts one straight thread line";
  if (plan.form != ThreadForm::kMulti || plan.passes.empty())
    return "CYCLE99 cuts multi-pass threads (THREAD/ON) only";
  if (!m.templates.count(std::string(tmpl::kCycle99.name)))
    return fmt::format("machine '{}' has no 'cycle99' template", m.name);
  if (plan.pitch.lead_change != 0)
    return fmt::format("CYCLE99 cuts a constant lead; this lead {} by {} per revolution",
                       plan.pitch.lead_change > 0 ? "grows (INCR)" : "shrinks (DECR)",
                       num_text(std::fabs(plan.pitch.lead_change)));
  return {};
}

// The thread line and the infeed as CYCLE99 reads them.
struct Cycle99Frame {
  double tol = 0;     // cut_tolerance
  Vec2 p1;            // where the cuts start: the thread start, less a run-in clpost added
  double run_in = 0;  // that run-in along t (threading.run_in auto), else 0
  double len = 0;     // p1 to P2
  Vec2 t;             // unit cutting direction
  Vec2 n;             // unit normal toward the material (the side the infeed goes to)
  Vec2 a_in;          // the paraxial infeed axis
  double cosv = 1;    // n . a_in
};

// PSYS (the kind, side and infeed axis) and the frame, or why CYCLE99 does not cut this thread
// that way.
std::string frame_words(const ThreadPlan& plan, const Machine& m, Cycle99Frame& f,
                        Cycle99Words& w) {
  f.tol = cut_tolerance(m);
  const Vec2 p1 = plan.p1, p2 = plan.p2;
  f.t = (1 / length(p2 - p1)) * (p2 - p1);
  f.run_in = added_run_in_along(plan);
  f.p1 = p1 - f.run_in * f.t;
  f.len = length(p2 - p1) + f.run_in;
  const Vec2 u = direction(plan.cutang);
  f.n = {f.t.z, -f.t.x};
  if (dot(f.n, u) < 0) f.n = -f.n;
  if (plan.kind == ThreadKind::kFace) {
    w.psys = 10;
    f.a_in = {0, -1};
    if (f.n.z >= 0)
      return "CYCLE99 cuts a face thread toward -Z (unverified); this one's infeed goes toward "
             "+Z";
  } else {
    if (!plan.lead_along_z)
      return fmt::format(
          "CYCLE99 takes a taper thread's lead along Z (unverified); this "
          "taper's lead is along X (X travel {} > Z travel {})",
          num_text(std::fabs(p2.x - p1.x)), num_text(std::fabs(p2.z - p1.z)));
    w.psys = plan.kind == ThreadKind::kTaper ? 20 : 0;
    f.a_in = {plan.side == ThreadSide::kInternal ? 1.0 : -1.0, 0};
  }
  f.cosv = dot(f.n, f.a_in);
  return {};
}

// The depth ladder: the passes of the first start (start 0).
std::vector<const ThreadPass*> depth_ladder(const ThreadPlan& plan) {
  std::vector<const ThreadPass*> ladder;
  for (const ThreadPass& p : plan.passes)
    if (p.start == 0) ladder.push_back(&p);
  return ladder;
}

// NRC roughing cuts, FAL, NID idle passes and TDEP from the ladder.
std::string depth_words(const std::vector<const ThreadPass*>& ladder, const Machine& m,
                        const Cycle99Frame& f, Cycle99Words& w) {
  int nrc = 0, nid = 0;
  double rough = 0, finish = -1;
  for (const ThreadPass* p : ladder) {
    if (p->kind == PassKind::kRough) ++nrc, rough = p->depth;
    if (p->kind == PassKind::kFinish) finish = p->depth;
    if (p->kind == PassKind::kSpring) ++nid;
  }
  const double full = finish >= 0 ? finish : rough;
  if (!(full > f.tol))
    return "CYCLE99 needs a thread depth (TDEP); this thread is one pass on the contour";
  w.nrc = nrc;
  w.nid = nid;
  w.tdep = as_read(m, kDepthFormat, full / f.cosv);
  w.fal = finish >= 0 ? as_read(m, kDepthFormat, (finish - rough) / f.cosv) : 0;
  return {};
}

// A pass's shift along the thread line beyond what the paraxial infeed to its depth gives.
double flank_shift(const ThreadPass& p, const Cycle99Frame& f) {
  return dot(p.from - f.p1, f.t) - (p.depth / f.cosv) * dot(f.a_in, f.t);
}

// IANG: every pass shifted by depth x tan(IANG) (one flank), within half the tool angle.
std::string flank_words(const ThreadPlan& plan, const Machine& m, const Cycle99Frame& f,
                        const std::vector<const ThreadPass*>& ladder, Cycle99Words& w) {
  const ThreadPass& deepest = *ladder.back();
  const double tan_iang = flank_shift(deepest, f) / deepest.depth;
  for (const ThreadPass* p : ladder) {
    double s = flank_shift(*p, f);
    if (std::fabs(s - p->depth * tan_iang) <= f.tol) continue;
    if (plan.option == 2 || plan.option == 4)
      return fmt::format(
          "CYCLE99 infeeds along one flank (IANG); OPTION {} alternates the "
          "flanks (pass {} shift {:.4f}, pass {} shift {:.4f})",
          plan.option, ladder.front()->n, flank_shift(*ladder.front(), f), deepest.n,
          flank_shift(deepest, f));
    return fmt::format(
        "CYCLE99 shifts every cut by depth x tan(IANG); pass {} is shifted "
        "{:.4f}, not {:.4f}",
        p->n, s, p->depth * tan_iang);
  }
  const double iang = degrees(std::atan(tan_iang));
  if (std::fabs(iang) > plan.tool_angle / 2 + 1e-6)
    return fmt::format(
        "IANG {:.4f} is more than half the tool angle {} (CYCLE99 allows at "
        "most {})",
        iang, num_text(plan.tool_angle), num_text(plan.tool_angle / 2));
  w.iang = as_read(m, kAngleFormat, iang);
  return {};
}

// ROP and APP. The only pull-out is the run-out ROP (CHAMFR with a negative length); `rop` is
// its length along the thread as planned (ROP unrounded).
std::string runout_words(const ThreadPlan& plan, const Machine& m, const Cycle99Frame& f,
                         const std::vector<const ThreadPass*>& ladder, Cycle99Words& w,
                         double& rop) {
  const ThreadPass& deepest = *ladder.back();
  double sigma_max = 0;
  for (const ThreadPass* p : ladder) sigma_max = std::max(sigma_max, p->shift);
  const double shorten = f.len - sigma_max - dot(deepest.to - deepest.from, f.t);
  rop = 0;
  if (plan.pullout) {
    const double along = dot(*plan.pullout, f.t), out = dot(*plan.pullout, -f.n);
    if (shorten <= f.tol)
      return fmt::format(
          "CYCLE99 has no pull-out past the thread end, only the run-out ROP "
          "that ends at FPL (CL CHAMFR with a negative length); this "
          "pull-out moves {} from the pass end",
          vec_text(*plan.pullout));
    if (std::fabs(out - along) > f.tol)
      return fmt::format(
          "CYCLE99's run-out ROP leaves the thread at 45 degrees "
          "(unverified); this run-out rises {} over {} ({} degrees)",
          num_text(out), num_text(along), num_text(degrees(std::atan2(out, along))));
    rop = along;
  }
  w.rop = as_read(m, kDepthFormat, rop);
  // APP: the run-in clpost added before the CL's start (auto), else the machine's, taken from
  // the start of the CL's thread.
  w.app = as_read(m, kDepthFormat, m.run_in.automatic ? f.run_in : m.run_in.value);
  return {};
}

// SPL, DM1, FPL, DM2: the start APP after where the cuts start (the CL's start with `auto`), the
// full-depth cut's run-out ending at FPL.
// Along t the deepest cut's end is FPL - ROP plus what its paraxial infeed moves along t.
std::string end_point_words(const Machine& m, const Cycle99Frame& f, const ThreadPass& deepest,
                            double rop, Cycle99Words& w) {
  const double end_t =
      dot(deepest.to - f.p1, f.t) - (deepest.depth / f.cosv) * dot(f.a_in, f.t) + rop;
  if (w.app >= end_t)
    return fmt::format("threading.run_in {} is not shorter than the thread ({})", num_text(w.app),
                       num_text(end_t));
  const Vec2 sp = f.p1 + w.app * f.t, fp = f.p1 + end_t * f.t;
  w.spl = as_read(m, "Z", sp.z);
  w.dm1 = as_read(m, "X", 2 * sp.x);
  w.fpl = as_read(m, "Z", fp.z);
  w.dm2 = as_read(m, "X", 2 * fp.x);
  return {};
}

// NUMTH and NSP: several starts spread over the spindle angle, cut start by start (a note).
std::string start_words(const ThreadPlan& plan, Cycle99Words& w, std::vector<std::string>& notes) {
  const int starts = plan.pitch.starts;
  if (starts > 1) {
    if (!plan.starts_by_angle)
      return fmt::format(
          "CYCLE99 spreads the {} starts over the spindle angle (NUMTH); this "
          "plan offsets them by the pitch (threading.start_angle_word is "
          "false)",
          starts);
    w.numth = starts;
    notes.push_back(
        fmt::format("CYCLE99 cuts start by start: every pass of start 1, then of start 2{}",
                    starts > 2 ? " ..." : ""));
  }
  w.nsp = 0;
  return {};
}

// PIT and PITA: the lead in mm (PITA 1) or threads per inch (PITA 2), as read back, within the
// tolerance over the thread's turns.
std::string lead_words(const ThreadPlan& plan, const Machine& m, double tol, Cycle99Words& w) {
  const bool inch = plan.units == LengthUnit::kInch;
  if (plan.pitch.from_tpi || inch) {
    w.pita = 2;
    w.pit = as_read(m, kLeadFormat, (inch ? 1.0 : 25.4) / plan.lead);
  } else {
    w.pita = 1;
    w.pit = as_read(m, kLeadFormat, plan.lead);
  }
  return lead_mismatch(m, plan, cycle99_lead(w, inch),
                       fmt::format("PIT {} (PITA {})", num_text(w.pit), w.pita), kLeadFormat, tol);
}

// VARI (the infeed law and side) and VRT (the retraction).
void law_words(const ThreadPlan& plan, const Machine& m, Cycle99Words& w) {
  const bool internal = w.psys != 10 && plan.side == ThreadSide::kInternal;
  const bool section = plan.option == 1 || plan.option == 2;
  w.vari = internal ? (section ? kVariInternalConstantSection : kVariInternalConstantInfeed)
                    : (section ? kVariExternalConstantSection : kVariExternalConstantInfeed);
  w.vrt = as_read(m, kDepthFormat, plan.clearance);
}

// What the control cuts from the words, against the plan (empty: the same cuts).
std::string cut_mismatch(const ThreadPlan& plan, double tol, const Cycle99Words& w) {
  Cycle99Expansion cut = expand_cycle99(w);
  if (!cut.alarm.empty()) return "CYCLE99 would stop: " + cut.alarm;
  std::string diff = compare_cuts(cut.cuts, plan_cuts(plan), {tol, true});
  if (diff.empty()) return {};
  if (plan.option == 0)
    return fmt::format(
        "CYCLE99 has no infeed with steps decreasing by a constant amount "
        "(OPTION 0): VARI {} ({}) cuts {}",
        w.vari, law_name(w.vari), diff);
  return fmt::format("VARI {} ({}) cuts {}", w.vari, law_name(w.vari), diff);
}

}  // namespace

Cycle99Call cycle99_call(const ThreadPlan& plan, const Machine& m) {
  Cycle99Call call;
  Cycle99Words& w = call.words;
  auto failed = [&](std::string why) {
    call.mismatch = std::move(why);
    return !call.mismatch.empty();
  };
  Cycle99Frame f;
  if (failed(cycle99_refusal(plan, m)) || failed(frame_words(plan, m, f, w))) return call;
  const std::vector<const ThreadPass*> ladder = depth_ladder(plan);
  double rop = 0;
  if (failed(depth_words(ladder, m, f, w)) || failed(flank_words(plan, m, f, ladder, w)) ||
      failed(runout_words(plan, m, f, ladder, w, rop)) ||
      failed(end_point_words(m, f, *ladder.back(), rop, w)) ||
      failed(start_words(plan, w, call.notes)) || failed(lead_words(plan, m, f.tol, w)))
    return call;
  law_words(plan, m, w);
  failed(cut_mismatch(plan, f.tol, w));
  return call;
}

Fit Cycle99Emitter::fit(const ThreadPlan& plan, const Machine& m) const {
  Cycle99Call c = cycle99_call(plan, m);
  return Fit{c.mismatch, c.notes, {}};
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

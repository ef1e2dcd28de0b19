#include "controls/heidenhain/heidenhain_emitter.h"

#include <fmt/format.h>

#include <algorithm>
#include <cmath>
#include <cstdlib>

#include "controls/heidenhain/heidenhain_templates.h"
#include "laws/written_value.h"
#include "planner/run_in.h"
#include "support/number_text.h"
#include "support/vec2_math.h"
#include "writer/number_format.h"

namespace clpost {

namespace {

using namespace vec2_math;

constexpr const char* kTemplate = tmpl::kHeidenhainG31.name.data();

Vec2 clear_start(const ThreadPlan& plan) {
  return plan.end_position;  // the clear line above the thread start
}

// Why G31 cannot cut the plan's kind of thread ("" when it can): one straight, single-start
// multi-pass thread of constant pitch, fed in radially or by the flank offset, without pull-out.
std::string shape_mismatch(const ThreadPlan& plan) {
  if (plan.form == ThreadForm::kChain)
    return "a chained thread: clpost writes G31 for one straight thread line only";
  if (plan.form != ThreadForm::kMulti || plan.passes.empty())
    return "G31 cuts multi-pass threads only";
  if (plan.pitch.lead_change != 0)
    return "G31 cuts a constant pitch; the CL gives a variable lead, INCR/DECR";
  if (plan.pitch.starts > 1)
    return fmt::format(
        "G31's multi-start order and spacing, D and C, are not documented; "
        "the thread has {} starts",
        plan.pitch.starts);
  if (plan.option == 0)
    return "G31 has no infeed type for OPTION 0, steps decreasing by a constant amount";
  if (std::fmod(std::fabs(plan.cutang), 90.0) > 1e-9)
    return fmt::format(
        "G31 feeds in radially or by its flank offset H; CUTANG {} is not "
        "mapped",
        plan.cutang);
  if (plan.pullout) return "G31's run-out K geometry is not documented; the plan has a pull-out";
  return {};
}

// The contour G31 is written with, its run-in B and its run-out P. The cuts start where the
// plan's passes do (P1, or a run-in clpost added before it with threading.run_in `auto`) and end
// at P2. A number for run_in is taken from the start of the CL's thread: the contour starts B
// after P1 (as CYCLE99's SPL). With `auto` the contour starts at P1 with B the run-in added
// before it, and ends the run-out δ2 before P2 with P = δ2 after it. B and P are what is left
// between the contour's written ends and the cut's, so that only their own rounding counts.
// Why the contour has no length, or "".
std::string contour_words(const ThreadPlan& plan, const Machine& m, HeidenhainG31& w) {
  const double dm = diameter_factor(m);
  const Vec2 t = (1 / length(plan.p2 - plan.p1)) * (plan.p2 - plan.p1);
  const double t_lead = std::fabs(plan.lead_along_z ? t.z : t.x);
  const double added = added_run_in_along(plan);
  const Vec2 cut_start = plan.p1 - added * t;
  const double b = m.run_in.automatic ? added : m.run_in.value;
  const double p = m.run_in.automatic && t_lead > 0 ? plan.run_out / t_lead : 0;
  auto written = [&](Vec2 q) { return Vec2{as_read(m, "X", dm * q.x) / dm, as_read(m, "Z", q.z)}; };
  w.from = written(cut_start + b * t);
  w.to = written(plan.p2 - p * t);
  w.b = as_read(m, "B", dot(w.from - cut_start, t));
  w.p = as_read(m, "P", dot(plan.p2 - w.to, t));
  if (dot(w.to - w.from, t) > 0) return {};
  return fmt::format("run-in B {} and run-out P {} leave the G31 contour no length (thread {})",
                     num_text(w.b), num_text(w.p), num_text(length(plan.p2 - plan.p1)));
}

}  // namespace

std::optional<HeidenhainG31> HeidenhainG31Emitter::words_for(const ThreadPlan& plan,
                                                             const Machine& m, std::string& why) {
  auto no = [&](std::string reason) {
    why = std::move(reason);
    return std::nullopt;
  };
  if (std::string reason = shape_mismatch(plan); !reason.empty()) return no(reason);
  if (!m.templates.count(kTemplate))
    return no(fmt::format("machine '{}' has no template '{}'", m.name, kTemplate));
  if (std::string why = lead_word_mismatch(m, plan, "F", "F", cut_tolerance(m)); !why.empty())
    return no(why);

  double d_max = 0;
  for (const ThreadPass& p : plan.passes) d_max = std::max(d_max, p.depth);
  if (d_max <= 0) return no("G31 needs a thread depth U > 0; the plan cuts on the contour");
  size_t first_full = 0;
  while (plan.passes[first_full].depth < d_max - 1e-9) ++first_full;

  const G31FlankCodes codes = g31_flank_codes(m);
  HeidenhainG31 w;
  w.f = as_read(m, "F", plan.pitch.pitch);
  w.u = as_read(m, "U", d_max);
  w.ic = static_cast<int>(first_full) + 1;
  w.q = static_cast<int>(plan.passes.size() - first_full) - 1;
  w.v = plan.option <= 2 ? 0 : 1;
  const Vec2 t = plan.p2 - plan.p1;
  const bool face = std::fabs(t.x) > std::fabs(t.z);
  const double toward = face ? t.x : t.z;
  if (plan.option == 2 || plan.option == 4)
    w.h = codes.alternating;
  else
    w.h = toward < 0 ? codes.toward_minus : codes.toward_plus;
  w.a = as_read(m, "A", plan.tool_angle / 2);
  w.d = 1;
  w.c = 0;
  w.bd = plan.side == ThreadSide::kInternal ? 1 : 0;
  w.k = 0;
  if (std::string reason = contour_words(plan, m, w); !reason.empty()) return no(reason);
  return w;
}

Fit HeidenhainG31Emitter::fit(const ThreadPlan& plan, const Machine& m) const {
  Fit f;
  std::optional<HeidenhainG31> w = words_for(plan, m, f.mismatch);
  if (!w) return f;
  std::string refused;
  std::vector<Cut> cuts = expand_heidenhain_g31(*w, g31_flank_codes(m), &refused);
  std::string diff = refused.empty()
                         ? compare_cuts(cuts, plan_cuts(plan), {cut_tolerance(m), false})
                         : "the G31 law does not cover the words: " + refused;
  if (diff.empty()) {
    f.notes.push_back("G31 infeed law and flank offsets as clpost assumes them, unverified");
    return f;
  }
  const bool finish = std::any_of(plan.passes.begin(), plan.passes.end(),
                                  [](const ThreadPass& p) { return p.kind == PassKind::kFinish; });
  f.mismatch = finish
                   ? "G31 has no finish allowance, FINCUT: " + diff
                   : fmt::format("G31's V{} law does not give the planned depths: {}", w->v, diff);
  return f;
}

bool HeidenhainG31Emitter::emit(const ThreadPlan& plan, NcProgram& prog, const EmitContext& ctx) {
  const Machine& m = prog.machine();
  std::string why;
  std::optional<HeidenhainG31> w = words_for(plan, m, why);
  if (!w) {
    return unfit_error(plan, ctx, m, "G31", why);
  }
  const double dm = diameter_factor(m);
  // To the clear line above the thread start, then the cycle with its contour.
  if (plan.feed_approach)
    prog.linear(lp(clear_start(plan)));
  else
    prog.rapid(lp(clear_start(plan)));
  TemplateFill<tmpl::kHeidenhainG31> a;
  a.text<"f">(prog.num("F", w->f));
  a.text<"u">(prog.num("U", w->u));
  a.text<"ic">(fmt::format("{}", w->ic));
  a.text<"v">(fmt::format("{}", w->v));
  a.text<"h">(fmt::format("{}", w->h));
  a.text<"a">(prog.num("A", w->a));
  a.text<"d">(fmt::format("{}", w->d));
  a.text<"q">(fmt::format("{}", w->q));
  a.text<"c">(prog.num("C", w->c));
  a.text<"bd">(fmt::format("{}", w->bd));
  a.text<"b">(prog.num("B", w->b));
  a.text<"p">(prog.num("P", w->p));
  a.text<"k">(prog.num("K", w->k));
  a.text<"x1">(prog.num("X", dm * w->from.x));
  a.text<"z1">(prog.num("Z", w->from.z));
  a.text<"x2">(prog.num("X", dm * w->to.x));
  a.text<"z2">(prog.num("Z", w->to.z));
  if (TemplateWrite r = prog.write_template(a); !r) return template_failed(plan, ctx, m, r);
  // Where the cycle leaves the tool is not documented: take it as unknown and go to the
  // thread's end position with both axes written.
  prog.cycle_ended_at(lp(clear_start(plan)));
  prog.rapid(lp(plan.end_position));
  return true;
}

}  // namespace clpost

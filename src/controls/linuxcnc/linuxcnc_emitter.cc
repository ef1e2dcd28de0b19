#include "controls/linuxcnc/linuxcnc_emitter.h"

#include <fmt/format.h>

#include <algorithm>
#include <cmath>
#include <cstdlib>

#include "controls/linuxcnc/linuxcnc_templates.h"
#include "laws/written_value.h"
#include "planner/run_in.h"
#include "support/angles.h"
#include "support/vec2_math.h"
#include "writer/number_format.h"

namespace clpost {

namespace {

using namespace vec2_math;

constexpr const char* kTemplate = tmpl::kLinuxcncG76.name.data();
constexpr const char* kTaperTemplate = tmpl::kLinuxcncG76Taper.name.data();

double deepest(const ThreadPlan& plan) {
  double d = 0;
  for (const ThreadPass& p : plan.passes) d = std::max(d, p.depth);
  return d;
}

// Passes at the deepest depth (the control's H + 1).
int full_depth_passes(const ThreadPlan& plan, double d_max) {
  return static_cast<int>(
      std::count_if(plan.passes.begin(), plan.passes.end(),
                    [&](const ThreadPass& p) { return p.depth >= d_max - 1e-9; }));
}

bool alternates(const ThreadPlan& plan) {
  bool straight = false, shifted = false;
  for (const ThreadPass& p : plan.passes) {
    if (p.depth <= 0) continue;
    (std::fabs(p.shift) > 1e-12 ? shifted : straight) = true;
  }
  return straight && shifted;
}

// Why G76 cannot cut the plan's kind of thread ("" when it can): one straight, single-start Z
// thread of constant lead, its passes on one flank and not all of them at the full depth.
std::string shape_mismatch(const ThreadPlan& plan, double d_max, int n_full) {
  if (plan.form == ThreadForm::kChain) return "a chained thread: G76 cuts one straight thread line";
  if (plan.form != ThreadForm::kMulti || plan.passes.empty())
    return "G76 cuts multi-pass threads only";
  if (plan.pitch.lead_change != 0)
    return "G76 cuts a constant lead; the CL gives a variable lead, INCR/DECR";
  if (plan.kind == ThreadKind::kFace) return "G76 threads along Z only; this is a face thread";
  if (plan.kind == ThreadKind::kTaper) return "G76 has no taper word; this is a taper thread";
  if (plan.pitch.starts > 1)
    return fmt::format("G76 has no start word; the thread has {} starts", plan.pitch.starts);
  if (d_max <= 0 || n_full == static_cast<int>(plan.passes.size()))
    return fmt::format(
        "G76 needs a first cut J below the full depth K; every pass of the "
        "plan is at depth {:.4f}",
        d_max);
  if (alternates(plan))
    return fmt::format("G76 cuts every pass on one flank; OPTION {} alternates flanks",
                       plan.option);
  return {};
}

// E and L (an exit taper) for the plan's pull-out, along the thread `t` and out of it `out`;
// "" when set, else why G76's exit taper, rising by the thread depth, is not that pull-out.
std::string exit_taper_words(const ThreadPlan& plan, const Machine& m, Vec2 t, Vec2 out,
                             double d_max, LinuxcncG76& w) {
  const double tol = cut_tolerance(m);
  const Vec2 d = *plan.pullout;
  const double along = dot(d, t), rise = dot(d, out);
  if (along <= tol)
    return fmt::format(
        "G76's exit taper runs along the thread; the plan pulls straight out "
        "by X{:.4f} Z{:.4f}",
        2 * d.x, d.z);
  if (plan.pullout_linear)
    return fmt::format(
        "the plan feeds its pull-out with G1, {:.1f} degrees to the thread is "
        "outside 30..60; G76 threads its exit taper",
        degrees(std::atan2(rise, along)));
  if (std::fabs(rise - d_max) > tol)
    return fmt::format(
        "G76's exit taper rises by the thread depth {:.4f}; the plan's "
        "pull-out rises {:.4f}",
        d_max, rise);
  w.e = as_read(m, "g76_taper", along);
  w.l = 2;
  return {};
}

// The expansion of `b` compared with the plan: "" when equal.
std::string compare(const LinuxcncG76Block& b, const ThreadPlan& plan, const Machine& m) {
  std::string refused;
  std::vector<Cut> cuts = expand_linuxcnc_g76(b.words, b.start, m.diameter_output, &refused);
  if (!refused.empty()) return "the control would refuse the block: " + refused;
  return compare_cuts(cuts, plan_cuts(plan), {cut_tolerance(m), false});
}

// The words (R and J settled) that cut the plan, or the reason there are none.
std::optional<LinuxcncG76Block> choose(const ThreadPlan& plan, const Machine& m, Fit& f) {
  std::optional<LinuxcncG76Block> b = LinuxcncG76Emitter::words_for(plan, m, f.mismatch);
  if (!b) return std::nullopt;
  // OPTION 3 and 4 are constant steps (R 1); the others try the degressive √n law first.
  const bool constant = plan.option == 3 || plan.option == 4;
  const double order[2] = {constant ? 1.0 : 2.0, constant ? 2.0 : 1.0};
  std::string first;
  for (double r : order) {
    LinuxcncG76Block t = *b;
    t.words.r = r;
    std::string diff = compare(t, plan, m);
    // Where the control's J·c^(1/R) lands a hair below K after rounding, it would add a pass:
    // one more increment on J settles it.
    if (!diff.empty()) {
      LinuxcncG76Block t2 = t;
      t2.words.j = as_read(m, "g76_depth", t.words.j + least_increment(m, "g76_depth"));
      if (compare(t2, plan, m).empty()) {
        t = t2;
        diff.clear();
      }
    }
    if (diff.empty()) {
      if (plan.feed_approach)
        f.notes.push_back("G76 rapids its infeed and retract; the CL feeds the approach");
      return t;
    }
    if (first.empty()) first = fmt::format("with R{}, {}", r, diff);
  }
  const bool finish = std::any_of(plan.passes.begin(), plan.passes.end(),
                                  [](const ThreadPass& p) { return p.kind == PassKind::kFinish; });
  if (finish)
    f.mismatch = "G76 has no finish allowance, FINCUT: " + first;
  else if (plan.option == 0)
    f.mismatch =
        "G76's depth law, J times the R-th root of n, is not OPTION 0's steps decreasing "
        "by a constant amount; " +
        first;
  else
    f.mismatch =
        "G76's depth law, J times the R-th root of n, does not give the planned depths; " + first;
  return std::nullopt;
}

}  // namespace

std::optional<LinuxcncG76Block> LinuxcncG76Emitter::words_for(const ThreadPlan& plan,
                                                              const Machine& m, std::string& why) {
  auto no = [&](std::string reason) {
    why = std::move(reason);
    return std::nullopt;
  };
  const double d_max = deepest(plan);
  const int n_full = full_depth_passes(plan, d_max);
  if (std::string reason = shape_mismatch(plan, d_max, n_full); !reason.empty()) return no(reason);

  const double tol = cut_tolerance(m);
  if (std::string why = lead_word_mismatch(m, plan, "P", "g76_lead", tol); !why.empty())
    return no(why);
  const Vec2 t = (1 / length(plan.p2 - plan.p1)) * (plan.p2 - plan.p1);
  const double out_sign = plan.side == ThreadSide::kExternal ? 1 : -1;
  const Vec2 out{out_sign, 0};
  LinuxcncG76Block b;
  LinuxcncG76& w = b.words;
  if (plan.pullout) {
    if (std::string reason = exit_taper_words(plan, m, t, out, d_max, w); !reason.empty())
      return no(reason);
  }
  const char* tname = plan.pullout ? kTaperTemplate : kTemplate;
  if (!m.templates.count(tname))
    return no(fmt::format("machine '{}' has no template '{}'", m.name, tname));

  const double dm = diameter_factor(m);
  // The tool waits on the clear line above where the cuts start (the thread start, less a run-in
  // clpost added with threading.run_in auto): that is G76's drive line and start Z.
  const Vec2 cut_start = plan.p1 - added_run_in_along(plan) * t;
  b.start.x = as_read(m, "X", dm * (plan.p1.x + out_sign * plan.clearance)) / dm;
  b.start.z = as_read(m, "Z", cut_start.z);
  // The first pass at the deepest depth fixes Z (where it or its exit taper ends) and Q.
  const ThreadPass* full = nullptr;
  for (const ThreadPass& p : plan.passes)
    if (p.depth >= d_max - 1e-9) {
      full = &p;
      break;
    }
  w.p = as_read(m, "g76_lead", plan.lead);
  w.z = as_read(m, "Z", full->pullout_end.z);
  w.i = as_read(m, "g76_depth", dm * (plan.p1.x - b.start.x));
  w.j = read_up(m, "g76_depth", dm * plan.passes.front().depth);
  w.k = as_read(m, "g76_depth", dm * d_max);
  w.q = as_read(m, "g76_angle", degrees(std::atan2(dot(full->from - cut_start, t), d_max)));
  w.h = n_full - 1;
  return b;
}

Fit LinuxcncG76Emitter::fit(const ThreadPlan& plan, const Machine& m) const {
  Fit f;
  choose(plan, m, f);
  return f;
}

namespace {

// G76 through template `T` (linuxcnc_g76 or, with an exit taper, linuxcnc_g76_taper).
template <const TemplateSpec& T>
TemplateWrite write_g76(NcProgram& prog, const LinuxcncG76& w) {
  TemplateFill<T> a;
  a.template text<"p">(prog.num("g76_lead", w.p));
  a.template text<"z">(prog.num("Z", w.z));
  a.template text<"i">(prog.num("g76_depth", w.i));
  a.template text<"j">(prog.num("g76_depth", w.j));
  a.template text<"k">(prog.num("g76_depth", w.k));
  a.template text<"r">(fmt::format("{}", w.r));
  a.template text<"q">(prog.num("g76_angle", w.q));
  a.template text<"h">(fmt::format("{}", w.h));
  a.template text<"e">(prog.num("g76_taper", w.e));
  a.template text<"l">(fmt::format("{}", w.l));
  return prog.write_template(a);
}

}  // namespace

bool LinuxcncG76Emitter::emit(const ThreadPlan& plan, NcProgram& prog, const EmitContext& ctx) {
  const Machine& m = prog.machine();
  Fit f;
  std::optional<LinuxcncG76Block> b = choose(plan, m, f);
  if (!b) {
    return unfit_error(plan, ctx, m, "G76", f.mismatch);
  }
  const LinuxcncG76& w = b->words;
  // To the drive line above the thread start, fed or rapid as the CL had the approach.
  if (plan.feed_approach)
    prog.linear(lp(b->start));
  else
    prog.rapid(lp(b->start));
  const TemplateWrite r =
      w.l ? write_g76<tmpl::kLinuxcncG76Taper>(prog, w) : write_g76<tmpl::kLinuxcncG76>(prog, w);
  if (!r) return template_failed(plan, ctx, m, r);
  // G76 leaves the tool on the drive line at Z; the thread ends above its start.
  prog.cycle_ended_at(LathePoint{b->start.x, w.z});
  prog.rapid(lp(plan.end_position));
  return true;
}

}  // namespace clpost

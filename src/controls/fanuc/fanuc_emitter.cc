#include "controls/fanuc/fanuc_emitter.h"

#include <fmt/format.h>

#include <algorithm>
#include <cmath>
#include <cstdlib>
#include <optional>

#include "controls/fanuc/fanuc_templates.h"
#include "support/angles.h"
#include "support/vec2_math.h"
#include "writer/number_format.h"

namespace clpost {

using namespace vec2_math;

namespace g76 {

std::string describe_pullout(const ThreadPlan& plan) {
  if (!plan.pullout) return "none";
  return fmt::format("X {:.4g}, Z {:.4g}", plan.pullout->x, plan.pullout->z);
}

namespace {

// The start's passes (heights, shifts, cuts) and the flank angle every one is shifted by, -1 when
// they do not share one (alternating); "" when read, else why not.
std::string read_passes(const ThreadPlan& plan, int start, CyclePlan& out) {
  std::optional<double> flank;
  bool one_angle = true;
  for (const ThreadPass& p : plan.passes) {
    if (p.start != start) continue;
    out.heights.push_back(p.depth / out.cos_t);
    out.shifts.push_back(p.shift);
    out.cuts.push_back(Cut{p.start, p.depth, p.from, p.to, p.pullout_end, {}});
    if (p.depth <= 1e-12) continue;
    const double a = degrees(std::atan(p.shift / p.depth));
    if (flank && std::fabs(*flank - a) > 1e-6) one_angle = false;
    if (!flank) flank = a;
  }
  if (out.heights.empty()) return fmt::format("start {} has no pass", start + 1);
  out.flank = !one_angle ? -1 : flank.value_or(0);
  return {};
}

// The plan's pull-out as the cycle's chamfer along the thread (length along Z and angle); "" when
// read, else why it is not one.
std::string read_chamfer(const ThreadPlan& plan, std::string_view cycle, CyclePlan& out) {
  const double dirz = out.t.z < 0 ? -1 : 1;
  const Vec2 v = *plan.pullout;
  const double along = v.z * dirz, up = v.x * out.outward;
  if (along <= 1e-9 || up <= 1e-9)
    return fmt::format("pull-out ({}) is not a chamfer along the thread: {} has none",
                       describe_pullout(plan), cycle);
  out.chamfer = along;
  out.chamfer_angle = degrees(std::atan2(up, along));
  return {};
}

// The cycle start: the clear line at the start's P1 Z (the first pass's start less its shift);
// and its full-depth end, where the deepest pass ends.
void set_start_and_end(const ThreadPlan& plan, int start, CyclePlan& out) {
  const ThreadPass* first = nullptr;
  const ThreadPass* deepest = nullptr;
  for (const ThreadPass& p : plan.passes) {
    if (p.start != start) continue;
    if (!first) first = &p;
    if (!deepest || p.depth >= deepest->depth - 1e-12) deepest = &p;
  }
  const double a_z = first->from.z - first->shift * out.t.z;
  const Vec2 e = plan.end_position;
  out.start = {e.x + out.slope * (a_z - e.z), a_z};
  const double z_end = deepest->pullout_end.z;
  const double h_max = deepest->depth / out.cos_t;
  out.end = {plan.p1.x + out.slope * (z_end - plan.p1.z) - out.outward * h_max, z_end};
}

}  // namespace

std::string read_cycle_plan(const ThreadPlan& plan, int start, std::string_view cycle,
                            CyclePlan& out) {
  if (plan.form == ThreadForm::kChain)
    return fmt::format("a chained thread: {} cuts one straight thread line", cycle);
  if (plan.form != ThreadForm::kMulti || plan.passes.empty())
    return fmt::format("not a multi-pass thread: {} is a multi-pass cycle", cycle);
  if (plan.kind == ThreadKind::kFace || !plan.lead_along_z)
    return fmt::format("face thread: {} threads along Z", cycle);
  const Vec2 d = plan.p2 - plan.p1;
  out = CyclePlan{};
  out.t = (1 / length(d)) * d;
  out.outward = plan.side == ThreadSide::kExternal ? 1 : -1;
  out.slope = d.x / d.z;
  out.cos_t = std::fabs(out.t.z);
  double c = std::fmod(std::fabs(plan.cutang), 180.0);
  if (c > 1e-9 && c < 180 - 1e-9)
    return fmt::format(
        "CUTANG {:g}: {} infeeds from a radial line (along the flank at half the "
        "tool angle)",
        plan.cutang, cycle);
  if (std::string why = read_passes(plan, start, out); !why.empty()) return why;
  if (plan.pullout) {
    if (std::string why = read_chamfer(plan, cycle, out); !why.empty()) return why;
  }
  set_start_and_end(plan, start, out);
  return {};
}

bool at_end(const NcProgram& prog, Vec2 p) {
  std::optional<LathePoint> at = prog.position();
  return at && std::fabs(at->r - p.x) < 1e-9 && std::fabs(at->z - p.z) < 1e-9;
}

double move_ends_to_deepest(const CyclePlan& cp, std::vector<Cut>& cuts) {
  const double s_max = *std::max_element(cp.shifts.begin(), cp.shifts.end());
  double most = 0;
  for (size_t i = 0; i < cuts.size() && i < cp.shifts.size(); ++i) {
    const double k = s_max - cp.shifts[i];
    cuts[i].to = cuts[i].to + k * cp.t;
    cuts[i].end = cuts[i].end + k * cp.t;
    most = std::max(most, k);
  }
  return most;
}

size_t passes_at(const std::vector<double>& heights, double h) {
  size_t n = 0;
  while (n < heights.size() && heights[heights.size() - 1 - n] >= h - 1e-9) ++n;
  return n;
}

std::string pass_end_mismatch(const std::vector<Cut>& cuts, const std::vector<Cut>& want,
                              const std::vector<Cut>& moved, double most, double z,
                              const Machine& m, const CutCompareOptions& opt,
                              std::vector<std::string>& notes) {
  const std::string diff = compare_cuts(cuts, want, opt);
  if (diff.empty()) return {};
  if (m.cycle_shifted_end) return "G76 would cut " + diff;
  // A difference beyond the pass ends is what to report.
  const std::string rest = compare_cuts(cuts, moved, opt);
  if (!rest.empty()) return "G76 would cut " + rest;
  const std::string z_text = number_text(z, m.format_for("Z"));
  if (!m.accept_pass_end)
    return fmt::format(
        "G76 ends every pass at Z{}; the plan ends the shallower passes "
        "up to {:.4f} earlier (threading.accept_pass_end is off)",
        z_text, most);
  notes.push_back(
      fmt::format("G76 ends every pass at Z{}; the plan ends the shallower "
                  "passes up to {:.4f} earlier (threading.accept_pass_end)",
                  z_text, most));
  return {};
}

}  // namespace g76

namespace {

using g76::at_end;

std::string_view depth_format(const ThreadPlan& plan) {
  return plan.units == LengthUnit::kInch ? "g76_depth_in" : "g76_depth";
}

constexpr const char* kFanucTemplate = tmpl::kFanucG76.name.data();
constexpr const char* kAllowance = "g76_allowance";

struct FanucBlock {
  FanucG76Words w;
  Vec2 start;  // A as written
};

// Why G76 cannot cut this kind of plan at all (empty: it may).
std::string fanuc_refusal(const ThreadPlan& plan) {
  if (plan.form == ThreadForm::kChain) return "a chained thread: G76 cuts one straight thread line";
  if (plan.pitch.lead_change != 0) return "variable lead: G76 cuts a constant lead";
  if (plan.pitch.starts > 1)
    return fmt::format("{} starts: G76 has no start-angle word (G92 with Q cuts them)",
                       plan.pitch.starts);
  if (plan.option == 0)
    return "OPTION 0, steps shrinking by a constant amount: G76 cuts depths Q x root n";
  if (plan.option == 3 || plan.option == 4)
    return fmt::format("OPTION {}, constant depth: G76 cuts depths Q x root n", plan.option);
  if (plan.option == 2) return "OPTION 2 alternates flanks: G76 infeeds along one flank";
  return {};
}

// a (the tool angle G76 takes, the passes along the flank at half of it) and F.
std::string angle_words(const ThreadPlan& plan, const Machine& m, const g76::CyclePlan& cp,
                        FanucG76Words& w) {
  const double a = plan.tool_angle;
  if (std::fabs(a - std::round(a)) > 1e-9 || !fanuc_g76_tool_angle_ok(static_cast<int>(a)))
    return fmt::format("tool angle {:g}: G76 takes 80, 60, 55, 30, 29 or 0", a);
  if (cp.flank < 0 || std::fabs(cp.flank - a / 2) > 1e-6)
    return fmt::format(
        "the passes are not shifted along the flank at {:g} deg: G76 infeeds "
        "at half the tool angle",
        a / 2);
  w.tool_angle = static_cast<int>(a);
  w.lead = as_read(m, "F", plan.lead);
  return lead_word_mismatch(m, plan, "F", "F", cut_tolerance(m));
}

// r: the pull-out as G76's chamfer (threading.chamfer_angle) of whole tenths of the lead.
std::string chamfer_word(const ThreadPlan& plan, const Machine& m, const g76::CyclePlan& cp,
                         FanucG76Words& w) {
  if (cp.chamfer <= 0) return {};
  if (std::fabs(cp.chamfer_angle - m.chamfer_angle) > 1e-6)
    return fmt::format(
        "pull-out ({}) is not G76's {:g} deg chamfer "
        "(threading.chamfer_angle)",
        g76::describe_pullout(plan), m.chamfer_angle);
  const double r = cp.chamfer / (0.1 * plan.lead);
  if (std::fabs(r - std::round(r)) > 1e-6 || std::round(r) < 1 || std::round(r) > 99)
    return fmt::format(
        "chamfer {:g} is not a whole number of tenths of the lead {:g} "
        "(r 01-99 of G76)",
        cp.chamfer, plan.lead);
  w.chamfer = static_cast<int>(std::round(r));
  return {};
}

// k, d, Δd and m from the pass heights; `extra` when G76 adds a spring pass the plan has not.
std::string depth_words(const ThreadPlan& plan, const Machine& m, const g76::CyclePlan& cp,
                        FanucG76Words& w, bool& extra) {
  const std::string_view df = depth_format(plan);
  const double h_max = *std::max_element(cp.heights.begin(), cp.heights.end());
  w.height = as_read(m, df, h_max);
  const size_t at_k = g76::passes_at(cp.heights, h_max);
  const size_t below = cp.heights.size() - at_k;
  extra = false;
  if (below == 0) {
    // Roughing reaches k in its first pass (d = 0), then m passes at k.
    w.allowance = 0;
    w.first_cut = w.height;
    w.finish_passes = static_cast<int>(at_k) - 1;
    if (w.finish_passes == 0) {
      if (!m.extra_spring_passes)
        return "one pass at full depth: G76 cuts at least two (roughing to k - d, then m >= "
               "1 at k) and threading.extra_spring_passes is off";
      w.finish_passes = 1;
      extra = true;
    }
  } else {
    // Roughing stops at k - d = the deepest pass below k; m = the passes at k.
    w.allowance = read_up(m, kAllowance, w.height - cp.heights[below - 1]);
    w.first_cut = read_up(m, df, cp.heights[0]);
    w.finish_passes = static_cast<int>(at_k);
  }
  if (w.finish_passes > 99)
    return fmt::format("{} passes at full depth: G76 m is 01-99", w.finish_passes);
  return {};
}

// Δdmin: the smallest increment of the roughing, rounded down, so that it never raises one.
double min_cut_word(const ThreadPlan& plan, const Machine& m, const FanucG76Words& w) {
  FanucG76Words probe = w;
  probe.min_cut = 0;
  probe.finish_passes = 0;
  std::vector<double> rough = fanuc_g76_depths(probe);
  double least = -1, prev = 0;
  for (size_t i = 0; i + 1 < rough.size(); ++i) {
    const double inc = rough[i] - prev;
    least = least < 0 ? inc : std::min(least, inc);
    prev = rough[i];
  }
  return least > 0 ? read_down(m, depth_format(plan), least) : 0;
}

// X, Z (the full-depth end), R (the taper) and A, the start, as written.
void position_words(const Machine& m, const g76::CyclePlan& cp, FanucBlock& b) {
  FanucG76Words& w = b.w;
  const double k = diameter_factor(m);
  w.x = as_read(m, "X", k * cp.end.x);
  w.z = as_read(m, "Z", cp.end.z);
  b.start = point_as_read(m, cp.start);
  w.taper = std::fabs(cp.slope) > 1e-12 ? as_read(m, "R", cp.slope * (b.start.z - w.z)) : 0;
}

// What the control cuts from the block, against the plan (with its extra spring pass).
std::string fanuc_cut_mismatch(const Machine& m, const g76::CyclePlan& cp, const FanucBlock& b,
                               bool extra, std::vector<std::string>& notes) {
  CycleLaw law{m.diameter_output, m.cycle_shifted_end, m.chamfer_angle};
  std::vector<Cut> cuts = expand_fanuc_g76(b.w, b.start, law);
  std::vector<Cut> want = cp.cuts;
  if (extra) want.push_back(want.back());
  std::vector<Cut> moved = want;
  const double most = g76::move_ends_to_deepest(cp, moved);
  if (extra) moved.back() = moved[moved.size() - 2];
  return g76::pass_end_mismatch(cuts, want, moved, most, b.w.z, m,
                                CutCompareOptions{cut_tolerance(m), false}, notes);
}

// The words that cut `plan` (single start) with G76, or a mismatch in `f`.
std::optional<FanucBlock> fanuc_words(const ThreadPlan& plan, const Machine& m, Fit& f) {
  auto failed = [&](std::string why) {
    f.mismatch = std::move(why);
    return !f.mismatch.empty();
  };
  g76::CyclePlan cp;
  FanucBlock b;
  FanucG76Words& w = b.w;
  if (failed(fanuc_refusal(plan)) || failed(g76::read_cycle_plan(plan, 0, "G76", cp)) ||
      failed(angle_words(plan, m, cp, w)) || failed(chamfer_word(plan, m, cp, w)))
    return std::nullopt;
  if (!m.templates.count(kFanucTemplate)) {
    failed(fmt::format("machine '{}' has no template '{}'", m.name, kFanucTemplate));
    return std::nullopt;
  }
  bool extra = false;
  if (failed(depth_words(plan, m, cp, w, extra))) return std::nullopt;
  w.min_cut = min_cut_word(plan, m, w);
  position_words(m, cp, b);
  if (failed(fanuc_cut_mismatch(m, cp, b, extra, f.notes))) return std::nullopt;
  if (extra)
    f.notes.push_back("G76 adds one spring pass at full depth (threading.extra_spring_passes)");
  return b;
}

// --- G92 ---

struct G92Plan {
  std::vector<G92Pass> passes;
};

std::optional<G92Plan> g92_words(const ThreadPlan& plan, const Machine& m, Fit& f) {
  auto fail = [&](std::string why) -> std::optional<G92Plan> {
    f.mismatch = std::move(why);
    return std::nullopt;
  };
  if (plan.form == ThreadForm::kChain)
    return fail("a chained thread: G92 cuts one straight line per pass");
  if (plan.form != ThreadForm::kMulti || plan.passes.empty())
    return fail("not a multi-pass thread");
  if (plan.pitch.lead_change != 0) return fail("variable lead: G92 cuts a constant lead");
  if (plan.kind == ThreadKind::kFace || !plan.lead_along_z)
    return fail("face thread: G92 threads along Z");
  if (std::string why = lead_word_mismatch(m, plan, "F", "F", cut_tolerance(m)); !why.empty())
    return fail(why);
  if (plan.pullout)
    return fail(
        fmt::format("pull-out ({}): G92 cuts the control's own chamfer (a parameter), "
                    "not the plan's",
                    g76::describe_pullout(plan)));
  for (const char* t : {tmpl::kG92.name.data(), tmpl::kG92Next.name.data()})
    if (!m.templates.count(t))
      return fail(fmt::format("machine '{}' has no template '{}'", m.name, t));
  const Vec2 d = plan.p2 - plan.p1;
  const double slope = d.x / d.z;
  const Vec2 e = plan.end_position;
  const double k = diameter_factor(m);
  const bool by_angle = plan.starts_by_angle && plan.pitch.starts > 1;
  G92Plan g;
  for (const ThreadPass& p : plan.passes) {
    G92Pass q;
    q.start = point_as_read(m, {e.x + slope * (p.from.z - e.z), p.from.z});
    q.words.x = as_read(m, "X", k * p.to.x);
    q.words.z = as_read(m, "Z", p.to.z);
    q.words.taper = std::fabs(slope) > 1e-12 ? as_read(m, "R", p.from.x - p.to.x) : 0;
    q.words.lead = as_read(m, "F", plan.lead);
    if (by_angle) q.words.start_angle = as_read(m, "thread_angle", p.start_angle);
    g.passes.push_back(q);
  }
  std::vector<Cut> cuts =
      expand_g92(g.passes, m.diameter_output, plan.p1, plan.p2, plan.pitch.starts);
  std::string diff = compare_cuts(cuts, plan_cuts(plan), {cut_tolerance(m), false});
  if (!diff.empty()) return fail("G92 would cut " + diff);
  return g;
}

}  // namespace

Fit FanucG76Emitter::fit(const ThreadPlan& plan, const Machine& m) const {
  Fit f;
  fanuc_words(plan, m, f);
  return f;
}

bool FanucG76Emitter::emit(const ThreadPlan& plan, NcProgram& prog, const EmitContext& ctx) {
  const Machine& m = prog.machine();
  Fit f;
  std::optional<FanucBlock> b = fanuc_words(plan, m, f);
  if (!b) {
    return unfit_error(plan, ctx, m, "G76", f.mismatch);
  }
  const FanucG76Words& w = b->w;
  const std::string_view df = depth_format(plan);
  prog.rapid(lp(b->start));
  TemplateFill<tmpl::kFanucG76> a;
  a.text<"m">(fmt::format("{:02}", w.finish_passes));
  a.text<"chamfer">(fmt::format("{:02}", w.chamfer));
  a.text<"angle">(fmt::format("{:02}", w.tool_angle));
  a.text<"min_cut">(prog.num(df, w.min_cut));
  a.text<"allowance">(prog.num(kAllowance, w.allowance));
  a.text<"x">(prog.num("X", w.x));
  a.text<"z">(prog.num("Z", w.z));
  a.text<"taper">(w.taper != 0 ? " R" + prog.num("R", w.taper) : std::string());
  a.text<"height">(prog.num(df, w.height));
  a.text<"first_cut">(prog.num(df, w.first_cut));
  a.text<"lead">(prog.num("F", w.lead));
  if (TemplateWrite r = prog.write_template(a); !r) return template_failed(plan, ctx, m, r);
  prog.cycle_ended_at(lp(b->start));
  const Vec2 e = point_as_read(m, plan.end_position);
  if (!at_end(prog, e)) prog.rapid(lp(plan.end_position));
  return true;
}

Fit G92Emitter::fit(const ThreadPlan& plan, const Machine& m) const {
  Fit f;
  g92_words(plan, m, f);
  return f;
}

namespace {

// One G92 block through template `T` (g92 or g92_next).
template <const TemplateSpec& T>
TemplateWrite write_g92(NcProgram& prog, std::string x, std::string z, std::string taper,
                        std::string lead, std::string start_angle) {
  TemplateFill<T> a;
  a.template text<"x">(std::move(x))
      .template text<"z">(std::move(z))
      .template text<"taper">(std::move(taper))
      .template text<"lead">(std::move(lead))
      .template text<"start_angle">(std::move(start_angle));
  return prog.write_template(a);
}

}  // namespace

bool G92Emitter::emit(const ThreadPlan& plan, NcProgram& prog, const EmitContext& ctx) {
  const Machine& m = prog.machine();
  Fit f;
  std::optional<G92Plan> g = g92_words(plan, m, f);
  if (!g) {
    return unfit_error(plan, ctx, m, "G92", f.mismatch);
  }
  const double k = diameter_factor(m);
  bool modal = false;      // a G92 is in force (a G0 ends it)
  G92Words last;           // its words
  std::optional<Vec2> at;  // where the tool is (known after the first block)
  for (const G92Pass& p : g->passes) {
    if (!at) {
      prog.rapid(lp(p.start));
    } else if (at->x != p.start.x || at->z != p.start.z) {
      // The flank shift (or the next start): a rapid to the new start point ends the G92 mode.
      NcWriter& w = prog.writer();
      w.code(m.code("rapid"));
      if (at->x != p.start.x) w.word("X", k * p.start.x);
      if (at->z != p.start.z) w.word("Z", p.start.z);
      w.end_block();
      modal = false;
    }
    const G92Words& q = p.words;
    const std::string angle =
        q.start_angle ? " Q" + prog.num("thread_angle", *q.start_angle) : std::string();
    // The first block of a thread says every word; the next ones, while G92 is modal, only
    // what changed.
    const TemplateWrite r =
        !modal ? write_g92<tmpl::kG92>(prog, prog.num("X", q.x), prog.num("Z", q.z),
                                       q.taper != 0 ? " R" + prog.num("R", q.taper) : std::string(),
                                       prog.num("F", q.lead), angle)
               : write_g92<tmpl::kG92Next>(
                     prog, prog.num("X", q.x),
                     q.z != last.z ? " Z" + prog.num("Z", q.z) : std::string(),
                     q.taper != last.taper ? " R" + prog.num("R", q.taper) : std::string(),
                     std::string(), angle);
    if (!r) return template_failed(plan, ctx, m, r);
    last = q;
    modal = true;
    at = p.start;
    prog.cycle_ended_at(lp(p.start));
  }
  const Vec2 e = point_as_read(m, plan.end_position);
  if (!at_end(prog, e)) prog.rapid(lp(plan.end_position));
  return true;
}

}  // namespace clpost

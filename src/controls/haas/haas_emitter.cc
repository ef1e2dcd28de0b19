#include "controls/haas/haas_emitter.h"

#include <fmt/format.h>

#include <algorithm>
#include <cmath>
#include <optional>

#include "controls/fanuc/fanuc_emitter.h"
#include "controls/haas/haas_templates.h"
#include "writer/number_format.h"

namespace clpost {

namespace {

using g76::at_end;

constexpr const char* kTemplate = tmpl::kHaasG76.name.data();

struct HaasBlock {
  HaasG76Words w;
  Vec2 start;  // A as written
};

// Why Haas G76 cannot cut this kind of plan at all (empty: it may).
std::string haas_refusal(const ThreadPlan& plan, const Machine& m) {
  if (plan.form == ThreadForm::kChain) return "a chained thread: G76 cuts one straight thread line";
  if (plan.pitch.lead_change != 0) return "variable lead: G76 cuts a constant lead";
  if (std::string why = lead_word_mismatch(m, plan, "F", "F", cut_tolerance(m)); !why.empty())
    return why;
  if (plan.option == 0)
    return "OPTION 0, steps shrinking by a constant amount: Haas G76 cuts D x root n "
           "with P1 or n x D with P3";
  if (plan.option == 2 || plan.option == 4)
    return fmt::format(
        "OPTION {} alternates flanks: the control's alternating infeed P{} "
        "is not documented in our sources, unverified",
        plan.option, plan.option);
  const double a = plan.tool_angle;
  if (std::fabs(a - std::round(a)) > 1e-9 || a > 120)
    return fmt::format("tool angle {:g}: A takes whole degrees 0-120", a);
  if (!m.templates.count(kTemplate))
    return fmt::format("machine '{}' has no template '{}'", m.name, kTemplate);
  return {};
}

// Whether a start's pull-out is the control's chamfer (settings 95/96), or why not.
std::string haas_chamfer_mismatch(const ThreadPlan& plan, const HaasSettings& s,
                                  const g76::CyclePlan& cp) {
  const double chamfer = s.chamfer * plan.lead;
  if (cp.chamfer == 0 && chamfer > 0)
    return fmt::format(
        "the plan has no pull-out; the control chamfers {:g} leads (setting "
        "95, threading.haas_chamfer)",
        s.chamfer);
  if (cp.chamfer > 0 && chamfer == 0)
    return fmt::format(
        "pull-out ({}): the control's chamfer (setting 95, "
        "threading.haas_chamfer) is 0",
        g76::describe_pullout(plan));
  if (cp.chamfer > 0 && (std::fabs(cp.chamfer - chamfer) > 1e-6 ||
                         std::fabs(cp.chamfer_angle - s.chamfer_angle) > 1e-6))
    return fmt::format(
        "pull-out ({}) is not the control's chamfer of {:g} leads at {:g} deg "
        "(settings 95/96)",
        g76::describe_pullout(plan), s.chamfer, s.chamfer_angle);
  return {};
}

// Whether a start's depths are what the control cuts: one pass at full depth, the last step the
// finish allowance (setting 86), or why not.
std::string haas_depth_mismatch(const ThreadPlan& plan, const HaasSettings& s,
                                const g76::CyclePlan& cp) {
  const double h_max = *std::max_element(cp.heights.begin(), cp.heights.end());
  const size_t at_k = g76::passes_at(cp.heights, h_max);
  if (at_k > 1)
    return fmt::format("{} passes at full depth: Haas G76 cuts one (no spring passes)", at_k);
  const size_t below = cp.heights.size() - 1;
  const double gap = below > 0 ? h_max - cp.heights[below - 1] : h_max;
  const bool finish = plan.passes.back().kind == PassKind::kFinish;
  if (s.finish_allowance == 0 && finish)
    return fmt::format(
        "finish allowance {:.4g} (FINCUT): the control's setting 86 "
        "(threading.haas_finish_allowance) is 0",
        gap);
  if (s.finish_allowance > 0 && std::fabs(gap - s.finish_allowance) > 1e-6)
    return fmt::format(
        "the last step {:.4g} is not the control's finish allowance {:.4g} "
        "(setting 86, threading.haas_finish_allowance)",
        gap, s.finish_allowance);
  return {};
}

// The block of start `k` of `starts`.
HaasBlock haas_block(const ThreadPlan& plan, const Machine& m, const g76::CyclePlan& cp, int k,
                     int starts) {
  const double h_max = *std::max_element(cp.heights.begin(), cp.heights.end());
  const double xk = diameter_factor(m);
  HaasBlock b;
  HaasG76Words& w = b.w;
  w.mode = plan.option == 3 ? 3 : 1;
  w.tool_angle = static_cast<int>(std::round(plan.tool_angle));
  w.lead = as_read(m, "F", plan.lead);
  w.height = as_read(m, "K", h_max);
  w.first_cut = read_up(m, "D", cp.heights[0]);
  w.x = as_read(m, "X", xk * cp.end.x);
  w.z = as_read(m, "Z", cp.end.z);
  b.start = point_as_read(m, cp.start);
  w.taper = std::fabs(cp.slope) > 1e-12 ? as_read(m, "I", cp.slope * (b.start.z - w.z)) : 0;
  if (plan.starts_by_angle && starts > 1)
    w.start_angle = as_read(m, "thread_angle", k * 360.0 / starts);
  return b;
}

// The cuts of every start, one after the other: as the control cuts them, as planned, and as
// planned with the pass ends moved to the deepest pass's (by up to `most`).
struct HaasCuts {
  std::vector<Cut> cuts, want, moved;
  double most = 0;
};

// Reads start `k` of the plan as one block, adding its cuts to `all`, or says why it is not one.
std::string haas_start(const ThreadPlan& plan, const Machine& m, const HaasSettings& s, int k,
                       int starts, std::vector<HaasBlock>& blocks, HaasCuts& all) {
  g76::CyclePlan cp;
  std::string why = g76::read_cycle_plan(plan, k, "G76", cp);
  if (!why.empty()) return why;
  const double a = plan.tool_angle;
  if (cp.flank < 0 || std::fabs(cp.flank - a / 2) > 1e-6)
    return fmt::format(
        "the passes are not shifted along the flank at {:g} deg: G76 infeeds "
        "at half the tool angle A",
        a / 2);
  why = haas_chamfer_mismatch(plan, s, cp);
  if (why.empty()) why = haas_depth_mismatch(plan, s, cp);
  if (!why.empty()) return why;
  const HaasBlock b = haas_block(plan, m, cp, k, starts);
  const CycleLaw law{m.diameter_output, m.cycle_shifted_end, s.chamfer_angle};
  std::vector<Cut> c = expand_haas_g76(b.w, b.start, s, law, starts);
  all.cuts.insert(all.cuts.end(), c.begin(), c.end());
  all.want.insert(all.want.end(), cp.cuts.begin(), cp.cuts.end());
  std::vector<Cut> mv = cp.cuts;
  all.most = std::max(all.most, g76::move_ends_to_deepest(cp, mv));
  all.moved.insert(all.moved.end(), mv.begin(), mv.end());
  blocks.push_back(b);
  return {};
}

std::optional<std::vector<HaasBlock>> haas_words(const ThreadPlan& plan, const Machine& m, Fit& f) {
  auto failed = [&](std::string why) {
    f.mismatch = std::move(why);
    return !f.mismatch.empty();
  };
  if (failed(haas_refusal(plan, m))) return std::nullopt;
  const HaasSettings s = haas_settings(m, plan.units);
  const int starts = std::max(1, plan.pitch.starts);
  std::vector<HaasBlock> blocks;
  HaasCuts all;
  for (int k = 0; k < starts; ++k)
    if (failed(haas_start(plan, m, s, k, starts, blocks, all))) return std::nullopt;
  const CutCompareOptions opt{cut_tolerance(m), true};
  if (failed(g76::pass_end_mismatch(all.cuts, all.want, all.moved, all.most, blocks.front().w.z, m,
                                    opt, f.notes)))
    return std::nullopt;
  if (starts > 1)
    f.notes.push_back(
        fmt::format("G76 cuts the {} starts one after the other (the plan "
                    "interleaves them)",
                    starts));
  return blocks;
}

}  // namespace

Fit HaasG76Emitter::fit(const ThreadPlan& plan, const Machine& m) const {
  Fit f;
  haas_words(plan, m, f);
  return f;
}

bool HaasG76Emitter::emit(const ThreadPlan& plan, NcProgram& prog, const EmitContext& ctx) {
  const Machine& m = prog.machine();
  Fit f;
  std::optional<std::vector<HaasBlock>> blocks = haas_words(plan, m, f);
  if (!blocks) {
    return unfit_error(plan, ctx, m, "G76", f.mismatch);
  }
  for (const HaasBlock& b : *blocks) {
    const HaasG76Words& w = b.w;
    prog.rapid(lp(b.start));
    TemplateFill<tmpl::kHaasG76> a;
    a.text<"x">(prog.num("X", w.x));
    a.text<"z">(prog.num("Z", w.z));
    a.text<"taper">(w.taper != 0 ? " I" + prog.num("I", w.taper) : std::string());
    a.text<"height">(prog.num("K", w.height));
    a.text<"first_cut">(prog.num("D", w.first_cut));
    a.text<"angle">(fmt::format("{}", w.tool_angle));
    a.text<"mode">(fmt::format("{}", w.mode));
    a.text<"start_angle">(w.start_angle ? " Q" + prog.num("thread_angle", *w.start_angle)
                                        : std::string());
    a.text<"lead">(prog.num("F", w.lead));
    if (TemplateWrite r = prog.write_template(a); !r) return template_failed(plan, ctx, m, r);
    prog.cycle_ended_at(lp(b.start));
  }
  const Vec2 e = point_as_read(m, plan.end_position);
  if (!at_end(prog, e)) prog.rapid(lp(plan.end_position));
  return true;
}

}  // namespace clpost

// Holes along the spindle axis (at X = h.x, 0 on the centre line): a control's canned cycle through
// its `hole_*` template, or moves.
//
// What each template's cycle does is the integrator's claim in the post file (posts/*.yaml name
// the control's manual); clpost checks only what a template cannot say: a cycle has one peck
// word, so a first peck that differs from the others is written as moves, and so is a dwell the
// template has no field for. The moves are the cycle's own definition: rapid to the R plane,
// feed to each peck depth, measured from the R plane as the controls' G83 does (a full retract to
// the R plane between pecks, or a back-off of holes.peck_clearance for chip breaking; going back in
// stops holes.peck_clearance short of the depth reached), dwell, rapid out (bore and ream: feed
// out; tap: feed out with the spindle reversed).
#include "emitters/hole_output.h"

#include <fmt/format.h>

#include <algorithm>
#include <cmath>

#include "support/number_text.h"

namespace clpost {

namespace {

double depth_of(const Hole& h) {
  return std::fabs(h.bottom - h.top);
}

// The index of hole field `f`: every hole template has the same fields (tmpl::kHoleFields).
consteval size_t field(std::string_view f, FieldKind kind = FieldKind::kText) {
  return tmpl::kHoleDrill.field(f, kind);
}

// The index of radial hole field `f` (tmpl::kRadialHoleFields).
consteval size_t radial_field(std::string_view f, FieldKind kind = FieldKind::kText) {
  return tmpl::kHoleRadialDrill.field(f, kind);
}

// A radial hole's cycle: X along the hole (a diameter where X is one), Z where it is.
TemplateWrite write_radial_cycle(NcProgram& prog, const Hole& h, const TemplateSpec& t) {
  const Machine& m = prog.machine();
  const double d = diameter_factor(m);
  TemplateValues v(t);
  v.set_text(radial_field("x"), prog.num("X", h.bottom * d));
  v.set_text(radial_field("z"), prog.num("Z", h.z));
  v.set_text(radial_field("top"), prog.num("X", h.top * d));
  v.set_text(radial_field("r"), prog.num("X", h.r * d));
  v.set_text(radial_field("r_radius"), prog.num("X", h.r));
  v.set_text(radial_field("r_inc"), prog.num("X", h.r - h.start));
  v.set_text(radial_field("start"), prog.num("X", h.start * d));
  v.set_text(radial_field("safety"), prog.num("X", std::fabs(h.r - h.top)));
  v.set_text(radial_field("depth"), prog.num("X", depth_of(h)));
  v.set_text(radial_field("peck"),
             prog.num("hole_peck", h.peck > 0 ? h.peck : std::fabs(h.bottom - h.r)));
  v.set_text(radial_field("dwell"), prog.num("dwell", h.dwell));
  v.set_whole(radial_field("dwell_ms", FieldKind::kWhole), std::llround(h.dwell * 1000));
  v.set_text(radial_field("feed"), prog.num("F", h.feed));
  v.set_text(radial_field("feed_mode"), prog.feed_mode_code(h.feed_mode));
  v.set_text(radial_field("lead"), prog.num("F", h.lead));
  v.set_text(radial_field("rpm"), prog.num("S", h.rpm));
  return prog.write_template(v);
}

TemplateWrite write_cycle(NcProgram& prog, const Hole& h, const TemplateSpec& t) {
  if (h.radial) return write_radial_cycle(prog, h, t);
  TemplateValues v(t);
  v.set_text(field("x"), prog.num("X", h.x * diameter_factor(prog.machine())));
  v.set_text(field("z"), prog.num("Z", h.bottom));
  v.set_text(field("top"), prog.num("Z", h.top));
  v.set_text(field("r"), prog.num("Z", h.r));
  v.set_text(field("r_inc"), prog.num("Z", h.r - h.start));
  v.set_text(field("start"), prog.num("Z", h.start));
  v.set_text(field("safety"), prog.num("Z", std::fabs(h.r - h.top)));
  v.set_text(field("depth"), prog.num("Z", depth_of(h)));
  v.set_text(field("peck"), prog.num("hole_peck", h.peck > 0 ? h.peck : std::fabs(h.bottom - h.r)));
  v.set_text(field("dwell"), prog.num("dwell", h.dwell));
  v.set_whole(field("dwell_ms", FieldKind::kWhole), std::llround(h.dwell * 1000));
  v.set_text(field("feed"), prog.num("F", h.feed));
  v.set_text(field("feed_mode"), prog.feed_mode_code(h.feed_mode));
  v.set_text(field("lead"), prog.num("F", h.lead));
  v.set_text(field("rpm"), prog.num("S", h.rpm));
  return prog.write_template(v);
}

// The point `along` the hole's axis (Z, or X for a radial hole) on its line.
LathePoint on_axis(const Hole& h, double along) {
  return h.radial ? LathePoint{along, h.z} : LathePoint{h.x, along};
}

const TemplateSpec& radial_hole_template(const Hole& h) {
  switch (h.kind) {
    case HoleKind::kDrill:
      return h.dwell > 0 ? tmpl::kHoleRadialDwell : tmpl::kHoleRadialDrill;
    case HoleKind::kTap:
      return h.spindle == SpindleDir::kCcw ? tmpl::kHoleRadialTapLeft : tmpl::kHoleRadialTap;
    case HoleKind::kDeep:
      return tmpl::kHoleRadialPeck;
    case HoleKind::kChipBreak:
      return tmpl::kHoleRadialChipBreak;
    case HoleKind::kBore:
    case HoleKind::kReam:
      break;
  }
  return tmpl::kHoleRadialBore;
}

}  // namespace

const TemplateSpec& hole_template(const Machine& m, const Hole& h) {
  if (h.radial) return radial_hole_template(h);
  switch (h.kind) {
    case HoleKind::kDrill:
      return h.dwell > 0 ? tmpl::kHoleDwell : tmpl::kHoleDrill;
    case HoleKind::kDeep:
      return tmpl::kHolePeck;
    case HoleKind::kChipBreak:
      return tmpl::kHoleChipBreak;
    case HoleKind::kTap:  // a live tool's (at a C) with its own spindle, right- or left-hand
      if (h.c) return h.spindle == SpindleDir::kCcw ? tmpl::kHoleLiveTapLeft : tmpl::kHoleLiveTap;
      return m.rigid_tapping ? tmpl::kHoleTapRigid : tmpl::kHoleTap;
    case HoleKind::kBore:
    case HoleKind::kReam:
      break;
  }
  return tmpl::kHoleBore;
}

namespace {

// The cycle of hole_template(m, h), as its reader calls it.
std::string cycle_name(const Machine& m, const Hole& h) {
  std::string name = h.radial ? "radial " : "";
  if (h.kind == HoleKind::kTap && (h.c || h.radial) && h.spindle == SpindleDir::kCcw)
    name += "left-hand ";
  if (h.kind == HoleKind::kTap && !h.c && !h.radial && m.rigid_tapping) name += "rigid ";
  name += hole_kind_name(h.kind);
  if (h.kind == HoleKind::kDrill && h.dwell > 0) name += " with a dwell";
  return name;
}

// G83, G33.1, CYCLE81: a cycle's code word (a template's word is its text up to a '(').
bool is_cycle_code(std::string_view w) {
  std::string_view digits;
  if (w.starts_with("CYCLE")) {
    digits = w.substr(5);
  } else if (w.starts_with("G")) {
    digits = w.substr(1);
    if (const size_t dot = digits.find('.'); dot != std::string_view::npos && dot > 0)
      digits.remove_prefix(dot + 1);
  } else {
    return false;
  }
  return !digits.empty() &&
         std::all_of(digits.begin(), digits.end(), [](char c) { return c >= '0' && c <= '9'; });
}

// The cycle's code in a hole template: on its first line with the hole's {z}, the last code
// word before it ("{feed_mode} G83 X{x} Z{z} …": G83; "G98 {feed_mode} G81 …": G81); "" when
// none.
std::string cycle_code(const std::vector<std::string>& lines) {
  for (const std::string& l : lines) {
    const size_t z = l.find("{z}");
    if (z == std::string::npos) continue;
    std::string code;
    for (size_t i = 0; i < z;) {
      const size_t end = std::min(l.find(' ', i), z);
      const std::string_view w = std::string_view(l).substr(i, end - i);
      if (const std::string_view head = w.substr(0, w.find('(')); is_cycle_code(head)) code = head;
      i = end + 1;
    }
    return code;
  }
  return {};
}

}  // namespace

std::string hole_output_text(const Machine& m, const Hole& h, std::string_view output) {
  if (output == kHoleMoves) return fmt::format("{}/{} moves", m.code("rapid"), m.code("linear"));
  const TemplateSpec& t = hole_template(m, h);
  if (output != t.name) return std::string(output);
  const auto lines = m.templates.find(std::string(t.name));
  const std::string code = lines == m.templates.end() ? "" : cycle_code(lines->second);
  const std::string name = cycle_name(m, h);
  return code.empty() ? name : fmt::format("{} ({})", name, code);
}

std::string hole_misfit(const Machine& m, const Hole& h) {
  const TemplateSpec& t = hole_template(m, h);
  if (m.templates.count(std::string(t.name)) == 0)
    return fmt::format("machine '{}' has no template '{}'", m.name, t.name);
  if (h.first_peck > 0 && std::fabs(h.first_peck - h.peck) > 1e-9)
    return fmt::format("first peck {} differs from the next pecks {}: '{}' has one peck word",
                       num_text(h.first_peck), num_text(h.peck), t.name);
  if ((h.kind == HoleKind::kDeep || h.kind == HoleKind::kChipBreak) && h.peck > 0 &&
      !template_has_field(m, t, "peck"))
    return fmt::format("template '{}' has no {{peck}}", t.name);
  if (h.kind == HoleKind::kTap && !h.c && h.spindle == SpindleDir::kCcw && m.tap_turns_cw)
    return fmt::format(
        "a left-hand tap, spindle counter-clockwise: '{}' turns the spindle "
        "clockwise, holes.tap_turns_cw",
        t.name);
  if (h.kind == HoleKind::kChipBreak && h.backoff &&
      std::fabs(*h.backoff - m.peck_clearance) > 1e-9)
    return fmt::format(
        "each peck backs off {}, the control by its own setting (holes.peck_clearance {})",
        num_text(*h.backoff), num_text(m.peck_clearance));
  if (h.dwell > 0 && !template_has_field(m, t, "dwell") && !template_has_field(m, t, "dwell_ms"))
    return fmt::format("a dwell of {} s at the bottom: template '{}' has no {{dwell}}",
                       num_text(h.dwell), t.name);
  return {};
}

TemplateWrite expand_hole(NcProgram& prog, const Hole& h) {
  const double clr = prog.machine().peck_clearance;
  const double back_off = chip_backoff(h, clr);
  if (h.radial) {
    if (prog.position() && std::fabs(prog.position()->z - h.z) > 1e-12)
      prog.rapid({prog.position()->r, h.z});
  } else if (prog.position() && std::fabs(prog.position()->r - h.x) > 1e-12) {
    prog.rapid({h.x, prog.position()->z});
  }
  prog.rapid(on_axis(h, h.r));
  prog.set_feed(h.feed, h.feed_mode);
  const std::vector<double> ends = hole_feed_ends(h);
  for (size_t i = 0; i < ends.size(); ++i) {
    prog.linear(on_axis(h, ends[i]));
    if (i + 1 == ends.size()) break;
    // Out to the R plane (peck) or back a little (chip breaking), then back in to just short
    // of the depth reached, never above the R plane.
    if (h.kind == HoleKind::kDeep) prog.rapid(on_axis(h, h.r));
    const double back =
        std::max(0.0, std::fabs(ends[i] - h.r) - (h.kind == HoleKind::kDeep ? clr : back_off));
    prog.rapid(on_axis(h, h.r + h.dir * back));
  }
  TemplateWrite dwell;
  if (h.dwell > 0)
    dwell =
        prog.dwell(h.dwell, h.rpm > 0 ? std::optional<double>(h.dwell * h.rpm / 60) : std::nullopt);
  if (h.kind == HoleKind::kTap) {
    const SpindleDir back = h.spindle == SpindleDir::kCw ? SpindleDir::kCcw : SpindleDir::kCw;
    if (TemplateWrite r = prog.spindle_rpm(h.rpm, back); !r) return r;
    prog.linear(on_axis(h, h.r));
    if (TemplateWrite r = prog.spindle_rpm(h.rpm, h.spindle); !r) return r;
  } else if (h.kind == HoleKind::kBore || h.kind == HoleKind::kReam) {
    prog.linear(on_axis(h, h.r));
  }
  prog.rapid(on_axis(h, h.retract));
  return dwell;
}

namespace {

bool template_written(const TemplateWrite& r, const Machine& m, const EmitContext& ctx) {
  if (!r) ctx.diags.error(ctx.loc, ctx.lines.text(ctx.loc.line), template_error(m, r));
  return static_cast<bool>(r);
}

// The machine's canned cycle for the hole, through its hole_* template.
class HoleCycleOutput : public CycleOutput<Hole> {
 public:
  explicit HoleCycleOutput(const TemplateSpec& t) : t_(t) {}
  std::string_view name() const override { return t_.name; }
  Fit fit(const Hole& h, const Machine& m) const override {
    Fit f;
    f.mismatch = hole_misfit(m, h);
    return f;
  }
  bool emit(const Hole& h, NcProgram& prog, const EmitContext& ctx) override {
    // The cycle starts where the tool is (Fanuc's R is measured from there): at the hole's start,
    // also after a home return, where the tool is at a position the program does not state.
    const LathePoint start = on_axis(h, h.start);
    if (!prog.position() || prog.is_at_machine_position() ||
        std::fabs(prog.position()->r - start.r) > 1e-12 ||
        std::fabs(prog.position()->z - start.z) > 1e-12)
      prog.rapid(start);
    if (!template_written(write_cycle(prog, h, t_), prog.machine(), ctx)) return false;
    prog.cycle_ended_at(start);
    if (std::fabs(h.retract - h.start) > 1e-12) prog.rapid(on_axis(h, h.retract));
    return true;
  }

 private:
  const TemplateSpec& t_;
};

// The hole as G0/G1/G4 moves (expand_hole): any hole, any machine.
class HoleMovesOutput : public CycleOutput<Hole> {
 public:
  std::string_view name() const override { return kHoleMoves; }
  Fit fit(const Hole&, const Machine&) const override { return {}; }
  bool emit(const Hole& h, NcProgram& prog, const EmitContext& ctx) override {
    return template_written(expand_hole(prog, h), prog.machine(), ctx);
  }
};

}  // namespace

bool write_hole(NcProgram& prog, const Hole& h, const EmitContext& ctx) {
  const Machine& m = prog.machine();
  const TemplateSpec& t = hole_template(m, h);
  const double d = diameter_factor(m);
  const std::string c =
      h.c ? fmt::format(" {}{}", m.c_address, prog.num("C", *h.c)) : std::string();
  if (h.radial)
    prog.comment(fmt::format("{}: radial {} at Z{}{} to X{}", h.name, hole_kind_name(h.kind),
                             prog.num("Z", h.z), c, prog.num("X", h.bottom * d)));
  else
    prog.comment(
        fmt::format("{}: {}{} to Z{}", h.name, hole_kind_name(h.kind),
                    h.c ? fmt::format(" at X{}{}", prog.num("X", h.x * d), c) : std::string(),
                    prog.num("Z", h.bottom)));
  HoleCycleOutput cycle(t);
  HoleMovesOutput moves;
  std::vector<CycleOutput<Hole>*> order;
  if (m.templates.count(std::string(t.name)) > 0) order.push_back(&cycle);
  order.push_back(&moves);
  Fit fit;
  std::vector<Unfit> unfit;
  CycleOutput<Hole>* used = first_exact<Hole>(order, h, m, false, fit, unfit);
  return emit_after_fallback(*used, fit, unfit, h, prog, ctx);
}

}  // namespace clpost

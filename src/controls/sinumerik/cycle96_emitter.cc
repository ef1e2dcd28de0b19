// SINUMERIK CYCLE96 for thread undercuts (cycle96_emitter.h).
#include "controls/sinumerik/cycle96_emitter.h"

#include <fmt/format.h>

#include "controls/sinumerik/sinumerik_templates.h"
#include "machine/template_values.h"
#include "support/number_text.h"

namespace clpost {

Fit Cycle96Emitter::fit(const Undercut& u, const Machine&) const {
  Fit f;
  const Din76Row* ext = din76_row('A', u.pitch);
  if (!internal_form(u.form) && ext && u.diam - ext->diameter_step < 3 - 1e-9) {
    f.mismatch = fmt::format(
        "CYCLE/UNDCUT: the undercut's final diameter {} (M{} pitch {}: DIN 76-1 d - {}) is below "
        "3 mm: CYCLE96 stops with an alarm",
        num_text(u.diam - ext->diameter_step), num_text(u.diam), num_text(u.pitch),
        num_text(ext->diameter_step));
    f.where = u.diam_loc;
  } else if (u.tool_offset <= 0) {
    f.mismatch =
        u.tool_offset < 0
            ? "CYCLE96 needs an active tool offset: no LOADTL/ before CYCLE/UNDCUT"
            : "CYCLE96 needs an active tool offset: the tool was loaded with offset 0 (D0), which "
              "selects none";
  }
  return f;
}

bool Cycle96Emitter::emit(const Undercut& u, NcProgram& prog, const EmitContext& ctx) {
  const Machine& m = prog.machine();
  prog.comment(fmt::format("thread undercut M{} form {} at Z{}", num_text(u.diam),
                           form_name(u.form), num_text(u.at)));
  // CYCLE96 moves at the feed programmed before it: make sure it is written.
  prog.writer().code(prog.feed_mode_code(u.feed_mode)).word("F", u.feed).end_block();
  TemplateFill<tmpl::kCycle96> args;
  args.text<"diath">(prog.num("X", u.diam))
      .text<"axsa">(prog.num("Z", u.at))
      .text<"form">(std::string(1, u.form));
  if (TemplateWrite r = prog.write_template(args); !r) {
    ctx.diags.error(ctx.loc, ctx.lines.text(ctx.loc.line), template_error(m, r));
    return false;
  }
  // The cycle returns to its starting point with G0 (seed 001).
  prog.cycle_ended_at(prog.position().value_or(LathePoint{}));
  return true;
}

}  // namespace clpost

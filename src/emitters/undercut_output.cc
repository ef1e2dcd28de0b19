// Thread undercuts: the machine's cycle or the DIN 76-1 contour as moves (undercut_output.h).
#include "emitters/undercut_output.h"

#include <fmt/format.h>

#include <cmath>

#include "emitters/emitter.h"
#include "support/number_text.h"

namespace clpost {

namespace {

// The DIN 76-1 undercut cut as a contour (no cycle on the machine).
class Din76ContourOutput : public CycleOutput<Undercut> {
 public:
  std::string_view name() const override { return "DIN 76-1 contour"; }
  Fit fit(const Undercut& u, const Machine&) const override {
    Fit f;
    if (!din76_row(u.form, u.pitch)) {
      f.mismatch = fmt::format(
          "CYCLE/UNDCUT: no DIN 76-1 row for form {}, pitch {} (M{}) in clpost's table: only the "
          "normal forms A and C are carried (cited in src/laws/din76_undercut.cc); use FORM,{} "
          "or a machine with CYCLE96",
          form_name(u.form), num_text(u.pitch), num_text(u.diam),
          internal_form(u.form) ? 'C' : 'A');
      f.where = u.form_loc;
    } else if (!u.tool) {
      f.mismatch =
          "CYCLE/UNDCUT needs the tool position to tell the undercut's side: no GOTO or FROM "
          "before it";
    } else if (std::fabs(u.tool->z - u.at) < 1e-9) {
      f.mismatch = fmt::format(
          "CYCLE/UNDCUT: the tool is at the undercut's Z {}: it must be on the side of AT where "
          "the undercut lies",
          num_text(u.at));
    }
    return f;
  }
  bool emit(const Undercut& u, NcProgram& prog, const EmitContext&) override {
    const Din76Row& row = *din76_row(u.form, u.pitch);
    const Vec2 here = *u.tool;
    const UndercutContour c = din76_contour(u.diam, u.at, u.form, here.z > u.at ? 1 : -1, row);
    const double step = internal_form(u.form) ? row.diameter_step : -row.diameter_step;
    prog.comment(fmt::format(
        "thread undercut DIN 76-1 form {} for M{} at Z{}: diameter {}, width {}, radius {}",
        form_name(u.form), num_text(u.diam), num_text(u.at), num_text(u.diam + step),
        num_text(row.width), num_text(row.radius)));
    prog.rapid(lp(c.start));
    for (Vec2 p : c.to_fillet) prog.linear(lp(p));
    prog.arc(lp(c.fillet_end), lp(c.fillet_center), c.fillet_ccw);
    prog.linear(lp(c.end));
    prog.rapid(lp(here));
    moves_ = c.to_fillet.size() + 4;
    return true;
  }
  size_t moves() const { return moves_; }

 private:
  size_t moves_ = 0;
};

}  // namespace

std::unique_ptr<CycleOutput<Undercut>> make_undercut_cycle(const Machine& m) {
  for (const Control* c : m.controls)
    if (c->undercut_cycle)
      if (std::unique_ptr<CycleOutput<Undercut>> u = c->undercut_cycle(m)) return u;
  return nullptr;
}

bool write_undercut(NcProgram& prog, const Undercut& u, const EmitContext& ctx,
                    UndercutWritten& written) {
  const Machine& m = prog.machine();
  std::unique_ptr<CycleOutput<Undercut>> cycle = make_undercut_cycle(m);
  Din76ContourOutput contour;
  CycleOutput<Undercut>* const order[] = {cycle ? cycle.get() : &contour};
  Fit fit;
  std::vector<Unfit> unfit;
  CycleOutput<Undercut>* used = first_exact<Undercut>(order, u, m, true, fit, unfit);
  if (!used) {
    const SourceLoc at = unfit.front().where.line != 0 ? unfit.front().where : ctx.loc;
    ctx.diags.error(at, ctx.lines.text(at.line), unfit.front().reason);
    return false;
  }
  if (!used->emit(u, prog, ctx)) return false;
  written = {};
  if (used == &contour) written = {contour.moves(), u.tool};
  return true;
}

}  // namespace clpost

// Words the CL passes through to the machine: AUXFUN/n (an M code), PREFUN/n (a G code),
// SELCTL/n, CLAMP/ON|OFF, OPSKIP/ON|OFF (block delete). Each becomes the machine's template or
// code, or — when the machine file has none — a warning and the statement as an NC comment:
// nothing is dropped silently.
#include <fmt/format.h>

#include <algorithm>
#include <utility>

#include <cmath>

#include "interpreter/millturn.h"
#include "interpreter/statement_table.h"

namespace clpost {

namespace {

// The statement as a comment, with a warning saying what the machine lacks.
void as_comment(PostState& s, const Statement& st, std::string_view lacks) {
  warning(
      s, st, st.loc,
      fmt::format("{}/: machine '{}' has no {}: written as a comment", st.major, s.m.name, lacks));
  ensure_started(s);
  s.prog.comment(st.source);
}

// AUXFUN/n, PREFUN/n, SELCTL/n through template `t`.
void code_word(PostState& s, const Statement& st, const TemplateSpec& t) {
  double n = 0;
  if (!number_arg(s, st, 0, "a code number", n)) return;
  if (!(n >= 0 && n <= 99999 && n == std::floor(n))) {
    error(s, st, st.args[0].loc,
          fmt::format("{}/ needs a whole number 0..99999, got {}", st.major, st.args[0].text));
    return;
  }
  if (const std::string rest = rest_of_args(st, 1); !rest.empty())
    warning(s, st, st.args[1].loc,
            fmt::format("{}/: the words after the number are not written ('{}')", st.major, rest));
  if (s.m.templates.count(std::string(t.name)) == 0)
    return as_comment(s, st, fmt::format("template '{}'", t.name));
  ensure_started(s);
  TemplateValues v(t);
  v.set_whole(0, static_cast<long long>(n));
  if (TemplateWrite r = s.prog.write_template(v); !r) error(s, st, st.loc, template_error(s.m, r));
}

// The ON or OFF of CLAMP/ and OPSKIP/; nullopt (reported) otherwise.
std::optional<bool> on_off(PostState& s, const Statement& st) {
  if (!st.args.empty() && (st.args[0].is("ON") || st.args[0].is("OFF"))) return st.args[0].is("ON");
  error(s, st, st.args.empty() ? st.loc : st.args[0].loc,
        fmt::format("expected {}/ON or {}/OFF", st.major, st.major));
  return std::nullopt;
}

// After OPSKIP/OFF: the program does the same whether the operator skipped the range or not
// (docs/cl-meaning.md). The next move states its motion, X, Z and F again, and the spindle and
// coolant are stated again when a skipped block changed them.
void end_skip_range(PostState& s, const Statement& st) {
  const auto [spindle, coolant] = *s.before_skip;
  s.before_skip.reset();
  s.prog.forget_modal();
  const SpindleState& now = s.spindle;
  const bool written = std::exchange(s.spindle_in_skip, false);  // perhaps skipped, then
  if (written || now.on != spindle.on || now.css != spindle.css || now.value != spindle.value ||
      now.css_max_rpm != spindle.css_max_rpm || now.dir != spindle.dir) {
    if (now.on) {
      restate_spindle(s, st);
    } else if (TemplateWrite r = s.prog.spindle_stop(); !r) {
      error(s, st, st.loc, template_error(s.m, r));
    }
  }
  if (s.coolant != coolant) {
    // One coolant at a time: the one before the range may still run (block delete on).
    if (coolant != Coolant::kOff && s.coolant != Coolant::kOff) s.prog.coolant(Coolant::kOff);
    s.prog.coolant(s.coolant);
  }
}

}  // namespace

void auxfun_stmt(PostState& s, const Statement& st) {
  code_word(s, st, tmpl::kAuxfun);
}

void prefun_stmt(PostState& s, const Statement& st) {
  code_word(s, st, tmpl::kPrefun);
}

void selctl_stmt(PostState& s, const Statement& st) {
  code_word(s, st, tmpl::kSelctl);
}

void clamp_stmt(PostState& s, const Statement& st) {
  if (std::any_of(st.args.begin(), st.args.end(), [](const Arg& a) { return a.is("CAXIS"); }))
    return clamp_c_stmt(s, st);
  if (!st.args.empty() && st.args[0].is("TABLE")) return clamp_table_stmt(s, st);
  const std::optional<bool> on = on_off(s, st);
  if (!on) return;
  const std::string& code = s.m.code(*on ? "clamp_on" : "clamp_off");
  if (code.empty()) return as_comment(s, st, *on ? "code 'clamp_on'" : "code 'clamp_off'");
  ensure_started(s);
  s.prog.writer().code(code).end_block();
}

void opskip_stmt(PostState& s, const Statement& st) {
  const std::optional<bool> on = on_off(s, st);
  if (!on) return;
  if (s.m.block_delete.empty()) return as_comment(s, st, "block delete mark (output.block_delete)");
  ensure_started(s);
  s.prog.writer().set_block_delete(*on ? std::string_view(s.m.block_delete) : std::string_view());
  if (*on) {
    if (!s.before_skip) s.before_skip.emplace(s.spindle, s.coolant);
    return;
  }
  if (s.before_skip) end_skip_range(s, st);
}

}  // namespace clpost

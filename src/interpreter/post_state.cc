// PostState: construction, diagnostics at a statement, the lathe frame (post_state.h).
#include "interpreter/post_state.h"

#include <fmt/format.h>

#include <algorithm>

#include "emitters/planner_settings.h"
#include "interpreter/tool_paths.h"

namespace clpost {

PostState::PostState(const Machine& machine, NcProgram& program, Diagnostics& d,
                     const PostOptions& o)
    : m(machine), prog(program), diags(d), opts(o), paths(std::make_unique<ToolPaths>()) {
  path = &paths->turning;  // no tool loaded yet: the lathe's
  radial_auto = machine.cl_radial == ClAxis::kAuto;
  // Undecided: the first of the two axes besides the axial one (all points so far on the axis).
  radial =
      radial_auto ? (machine.cl_axial == ClAxis::kX ? ClAxis::kY : ClAxis::kX) : machine.cl_radial;
  units = machine.default_units == "in" ? LengthUnit::kInch : LengthUnit::kMm;
  thread.settings = planner_settings(machine);
  thread.emitter = make_emitter(machine);
}

PostState::~PostState() = default;

void error(PostState& s, const Statement& st, SourceLoc loc, std::string msg) {
  s.diags.error(loc, st.line_text(loc.line), std::move(msg));
}

void warning(PostState& s, const Statement& st, SourceLoc loc, std::string msg) {
  s.diags.warning(loc, st.line_text(loc.line), std::move(msg));
}

void note_once(PostState& s, const Statement& st, std::string_view key, std::string msg) {
  if (std::find(s.noted.begin(), s.noted.end(), key) != s.noted.end()) return;
  s.noted.emplace_back(key);
  s.diags.note(st.loc, st.line_text(st.loc.line), std::move(msg));
}

bool bad_number_arg(PostState& s, const Statement& st, size_t i, std::string_view what) {
  if (i >= st.args.size()) {
    SourceLoc end = st.args.empty() ? st.loc : st.args.back().loc;
    error(s, st, end, fmt::format("{}/ needs {} (argument {})", st.major, what, i + 1));
    return false;
  }
  const Arg& a = st.args[i];
  if (!a.is_number()) {
    error(s, st, a.loc, fmt::format("expected {} but found {}", what, describe_arg(st, a)));
    return false;
  }
  return in_range(s, st, a, what);  // false: its error is reported
}

bool in_range(PostState& s, const Statement& st, const Arg& a, std::string_view what) {
  if (within_limits(a.number)) return true;
  error(s, st, a.loc,
        fmt::format("{} '{}' is out of range: CL values must be between -{} and {}", what, a.text,
                    kMaxClValue, kMaxClValue));
  return false;
}

std::string unknown_word(const Statement& st, const Arg& a, std::string_view major,
                         std::string_view expected) {
  if (a.is_word()) return fmt::format("unknown {} word '{}': expected {}", major, a.text, expected);
  return fmt::format("{}/: expected {}, found {}", major, expected, describe_arg(st, a));
}

std::string rest_of_args(const Statement& st, size_t from) {
  size_t last = st.args.size();
  while (last > from && st.args[last - 1].is_empty()) --last;
  std::string rest;
  for (size_t i = from; i < last; ++i) rest += (i > from ? "," : "") + std::string(st.args[i].text);
  return rest;
}

void ensure_started(PostState& s) {
  if (s.started) return;
  s.started = true;
  // Required by the loader: it cannot be missing, but a failure is never silent.
  if (TemplateWrite r = s.prog.start(s.partno, s.units == LengthUnit::kInch, s.diags.file()); !r)
    s.diags.error(SourceLoc{}, {}, template_error(s.m, r));
  if (!s.partno.empty()) s.prog.comment(s.partno);
}

double axis_value(Point3 p, ClAxis a) {
  return a == ClAxis::kX ? p.x : a == ClAxis::kY ? p.y : p.z;
}

ClAxis third_axis(const PostState& s) {
  return static_cast<ClAxis>(3 - static_cast<int>(s.radial) - static_cast<int>(s.m.cl_axial));
}

Vec2 cl2(const PostState& s, Point3 p) {
  double r = axis_value(p, s.radial);
  if (s.m.cl_x_is_diameter) r /= 2;
  return Vec2{r, axis_value(p, s.m.cl_axial)};
}

Point3 cl_point(const PostState& s, Vec2 v) {
  Point3 p;
  double* axes[3] = {&p.x, &p.y, &p.z};
  *axes[static_cast<int>(s.radial)] = v.x * diameter_factor(s.m.cl_x_is_diameter);
  *axes[static_cast<int>(s.m.cl_axial)] = v.z;
  return p;
}

}  // namespace clpost

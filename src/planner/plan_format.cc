#include "planner/plan_format.h"

#include <fmt/format.h>

#include <algorithm>
#include <cmath>
#include <string_view>

#include "planner/run_in.h"
#include "support/json_text.h"
#include "support/number_text.h"

namespace clpost {

const char* form_name(ThreadForm f) {
  switch (f) {
    case ThreadForm::kMulti:
      return "multi";
    case ThreadForm::kSingle:
      return "single";
    case ThreadForm::kCouple:
      return "couple";
    case ThreadForm::kChain:
      return "chain";
  }
  return "multi";
}

const char* kind_name(ThreadKind k) {
  switch (k) {
    case ThreadKind::kTurn:
      return "turn";
    case ThreadKind::kFace:
      return "face";
    case ThreadKind::kTaper:
      return "taper";
  }
  return "turn";
}

const char* side_name(ThreadSide s) {
  return s == ThreadSide::kInternal ? "internal" : "external";
}

const char* pass_kind_name(PassKind k) {
  switch (k) {
    case PassKind::kRough:
      return "rough";
    case PassKind::kFinish:
      return "finish";
    case PassKind::kSpring:
      return "spring";
  }
  return "rough";
}

const char* units_name(LengthUnit u) {
  return u == LengthUnit::kInch ? "in" : "mm";
}

namespace {

// Length of the UTF-8 sequence starting at s[i], or 0 when it is not valid UTF-8.
std::string json_num(double v) {
  return std::isfinite(v) ? num_text(v) : "null";
}

std::string json_point(Vec2 p) {
  return fmt::format("{{\"x\": {}, \"z\": {}}}", json_num(p.x), json_num(p.z));
}

std::string text_point(Vec2 p) {
  return fmt::format("(X {}, Z {})", num_text(p.x), num_text(p.z));
}

// A chain's points: "[{...}, {...}]" (JSON) or "(X .., Z ..) -> (X .., Z ..)" (text).
std::string json_points(const std::vector<Vec2>& v) {
  std::string o = "[";
  for (size_t i = 0; i < v.size(); ++i) o += (i ? ", " : "") + json_point(v[i]);
  return o + "]";
}
std::string text_points(const std::vector<Vec2>& v) {
  std::string o;
  for (size_t i = 0; i < v.size(); ++i) o += (i ? " -> " : "") + text_point(v[i]);
  return o;
}

// "rpm", "run_in", "run_out", "run_in_added" and "lead_right" (run_in.h), each on its line.
std::string json_lead(const ThreadPlan& p) {
  const LeadSpan s = lead_span(p);
  if (!s.known)
    return "      \"rpm\": null,\n      \"run_in\": null,\n      \"run_out\": null,\n"
           "      \"run_in_added\": false,\n      \"lead_right\": null,\n";
  std::string o = fmt::format("      \"rpm\": {},\n", json_num(p.rpm));
  o += fmt::format("      \"run_in\": {},\n", json_num(p.run_in));
  o += fmt::format("      \"run_out\": {},\n", json_num(p.run_out));
  o += fmt::format("      \"run_in_added\": {},\n", p.run_in_added ? "true" : "false");
  o += fmt::format("      \"lead_right\": {},\n",
                   s.any ? fmt::format("{{\"axis\": \"{}\", \"from\": {}, \"to\": {}}}",
                                       s.along_z ? "z" : "x", json_num(s.from), json_num(s.to))
                         : "null");
  return o;
}

// "  run-in …, run-out … at … rpm; lead right from Z … to Z …" (empty when the speed is not
// known).
std::string text_lead(const ThreadPlan& p) {
  const LeadSpan s = lead_span(p);
  if (!s.known) return {};
  const char* axis = s.along_z ? "Z" : "X";
  return fmt::format("  run-in {}{}, run-out {} at {} rpm; {}\n", num_text(p.run_in),
                     p.run_in_added ? " (before the thread start)" : "", num_text(p.run_out),
                     num_text(p.rpm),
                     s.any ? fmt::format("lead right from {} {} to {} {}", axis, num_text(s.from),
                                         axis, num_text(s.to))
                           : std::string("no length has the right lead"));
}

// A multi-pass form: multi or chain.
bool is_multi(const ThreadPlan& p) {
  return p.form == ThreadForm::kMulti || p.form == ThreadForm::kChain;
}

}  // namespace

std::vector<double> pass_steps(const ThreadPlan& p) {
  std::vector<double> steps;
  steps.reserve(p.passes.size());
  std::vector<double> last(static_cast<size_t>(std::max(1, p.pitch.starts)), 0.0);
  for (const ThreadPass& s : p.passes) {
    double step = s.depth;
    if (s.start >= 0 && static_cast<size_t>(s.start) < last.size()) {
      step = s.depth - last[static_cast<size_t>(s.start)];
      last[static_cast<size_t>(s.start)] = s.depth;
    }
    steps.push_back(step);
  }
  return steps;
}

std::string plan_to_json(const std::string& file, LengthUnit units,
                         const std::vector<ThreadPlan>& plans) {
  std::string o = "{\n";
  o += fmt::format("  \"file\": {},\n", json_string(file));
  o += fmt::format("  \"units\": \"{}\",\n", units_name(units));
  if (plans.empty()) {
    o += "  \"threads\": []\n}\n";
    return o;
  }
  o += "  \"threads\": [\n";
  for (size_t k = 0; k < plans.size(); ++k) {
    const ThreadPlan& p = plans[k];
    const bool multi = is_multi(p);
    const bool chain = p.form == ThreadForm::kChain;
    o += "    {\n";
    o += fmt::format("      \"line\": {},\n", p.loc.line);
    o += fmt::format("      \"form\": \"{}\",\n", form_name(p.form));
    o += fmt::format("      \"kind\": \"{}\",\n", kind_name(p.kind));
    o += fmt::format("      \"side\": \"{}\",\n", side_name(p.side));
    o += fmt::format("      \"pitch\": {},\n", json_num(p.pitch.pitch));
    o += fmt::format("      \"lead\": {},\n", json_num(p.lead));
    o += fmt::format("      \"starts\": {},\n", p.pitch.starts);
    o += fmt::format("      \"depth\": {},\n", json_num(p.depth));
    o += fmt::format("      \"option\": {},\n", multi ? fmt::format("{}", p.option) : "null");
    o += fmt::format("      \"tool_angle\": {},\n", multi ? json_num(p.tool_angle) : "null");
    o += fmt::format("      \"cutang\": {},\n", multi ? json_num(p.cutang) : "null");
    o += fmt::format("      \"p1\": {},\n", json_point(p.p1));
    o += fmt::format("      \"p2\": {},\n", json_point(p.p2));
    if (chain) o += fmt::format("      \"points\": {},\n", json_points(p.points));
    o += fmt::format("      \"pullout\": {},\n", p.pullout ? json_point(*p.pullout) : "null");
    o += json_lead(p);
    if (p.passes.empty()) {
      o += "      \"passes\": []\n";
    } else {
      o += "      \"passes\": [\n";
      for (size_t i = 0; i < p.passes.size(); ++i) {
        const ThreadPass& s = p.passes[i];
        o += fmt::format(
            "        {{\"n\": {}, \"start\": {}, \"depth\": {}, \"kind\": \"{}\", \"shift\": {}, "
            "\"from\": {}, \"to\": {}{}}}{}\n",
            s.n, s.start, json_num(s.depth), pass_kind_name(s.kind), json_num(s.shift),
            json_point(s.from), json_point(s.to),
            chain ? fmt::format(", \"path\": {}", json_points(s.path)) : "",
            i + 1 < p.passes.size() ? "," : "");
      }
      o += "      ]\n";
    }
    o += fmt::format("    }}{}\n", k + 1 < plans.size() ? "," : "");
  }
  o += "  ]\n}\n";
  return o;
}

std::string plan_to_text(const std::string& file, LengthUnit units,
                         const std::vector<ThreadPlan>& plans) {
  std::string o = fmt::format("{}: {} thread{} ({})\n", file, plans.size(),
                              plans.size() == 1 ? "" : "s", units_name(units));
  for (const ThreadPlan& p : plans) {
    const bool multi = is_multi(p);
    const bool chain = p.form == ThreadForm::kChain;
    std::string pitch = num_text(p.pitch.pitch);
    if (p.pitch.from_tpi) pitch += fmt::format(" ({} TPI)", num_text(p.pitch.tpi));
    std::string head =
        fmt::format("\nline {}: {} {} thread, {}, pitch {}, lead {}, {} start{}", p.loc.line,
                    form_name(p.form), kind_name(p.kind), side_name(p.side), pitch,
                    num_text(p.lead), p.pitch.starts, p.pitch.starts == 1 ? "" : "s");
    if (p.pitch.starts > 1 && multi)
      head += p.starts_by_angle ? " (by spindle start angle)" : " (by offset)";
    if (p.pitch.lead_change != 0)
      head += fmt::format(", lead change {}{} per rev", p.pitch.lead_change > 0 ? "+" : "",
                          num_text(p.pitch.lead_change));
    if (multi) {
      head += fmt::format(", depth {}, option {}, tool angle {}, cutang {}, pull-out ",
                          num_text(p.depth), p.option, num_text(p.tool_angle), num_text(p.cutang));
      if (p.pullout) {
        head += fmt::format("{} ({})", text_point(*p.pullout),
                            p.pullout_linear ? "linear" : "threaded");
      } else {
        head += "none";
      }
    }
    o += head + "\n";
    if (chain) o += fmt::format("  contour {}\n", text_points(p.points));
    const bool angles = p.starts_by_angle;
    o += fmt::format("  {:>4} {:>5}{} {:>10} {:>10} {:>10}  {:<7} {}\n", "pass", "start",
                     angles ? fmt::format(" {:>7}", "angle") : "", "depth", "step", "shift", "kind",
                     "from -> to");
    const std::vector<double> steps = pass_steps(p);
    for (size_t i = 0; i < p.passes.size(); ++i) {
      const ThreadPass& s = p.passes[i];
      const double step = steps[i];
      o += fmt::format("  {:>4} {:>5}{} {:>10} {:>10} {:>10}  {:<7} {}\n", s.n, s.start,
                       angles ? fmt::format(" {:>7}", num_text(s.start_angle)) : "",
                       num_text(s.depth), num_text(step), num_text(s.shift), pass_kind_name(s.kind),
                       chain ? text_points(s.path) : text_points({s.from, s.to}));
    }
    if (chain) {
      o += fmt::format("  returns to {} {}; ends at {}\n", p.lead_along_z ? "X" : "Z",
                       num_text(p.lead_along_z ? p.end_position.x : p.end_position.z),
                       text_point(p.end_position));
    } else if (multi) {
      o += fmt::format("  returns {} above the thread line; ends at {}\n", num_text(p.clearance),
                       text_point(p.end_position));
    } else {
      o += fmt::format("  ends at {}\n", text_point(p.end_position));
    }
    o += text_lead(p);
  }
  return o;
}

}  // namespace clpost

#include "verify/plan_json.h"

#include <fmt/format.h>
#include <yaml-cpp/yaml.h>

#include <cmath>
#include <numbers>
#include <optional>

#include "machine/yaml_text.h"
#include "planner/plan_format.h"
#include "support/angles.h"

namespace clpost {

namespace {

// The enum value whose name (plan_format.h, the names the JSON was written with) is `text`.
template <typename E, size_t N>
E named(const std::string& text, const E (&values)[N], const char* (*name)(E)) {
  for (E v : values)
    if (text == name(v)) return v;
  return values[0];
}

struct Reader {
  const YamlText& text;
  Diagnostics& diags;
  bool ok = true;

  void error(const YAML::Mark& mark, std::string message) {
    const uint32_t line = mark.line >= 0 ? static_cast<uint32_t>(mark.line + 1) : 0;
    const uint32_t col = mark.column >= 0 ? static_cast<uint32_t>(mark.column + 1) : 0;
    if (ok || diags.error_count() < 20)
      diags.error({line, col}, text.line(line), std::move(message));
    ok = false;
  }
  YAML::Node need(const YAML::Node& n, const char* key) {
    YAML::Node v = n[key];
    if (!v) error(n.Mark(), fmt::format("plan JSON: '{}' missing", key));
    return v;
  }
  double number(const YAML::Node& n, const char* key) {
    YAML::Node v = need(n, key);
    if (!v) return 0;
    try {
      const double d = v.as<double>();
      if (std::isfinite(d)) return d;
    } catch (const YAML::Exception&) {
    }
    error(v.Mark(), fmt::format("plan JSON: '{}' is not a number", key));
    return 0;
  }
  std::string word(const YAML::Node& n, const char* key) {
    YAML::Node v = need(n, key);
    if (!v || !v.IsScalar()) return {};
    return v.Scalar();
  }
  Vec2 point(const YAML::Node& n, const char* key) {
    YAML::Node v = need(n, key);
    if (!v) return {};
    if (!v.IsMap()) {
      error(v.Mark(), fmt::format("plan JSON: '{}' is not {{\"x\": ..., \"z\": ...}}", key));
      return {};
    }
    return {number(v, "x"), number(v, "z")};
  }
  // A list of points (a chain's `points`, a pass's `path`).
  std::vector<Vec2> points(const YAML::Node& n, const char* key) {
    std::vector<Vec2> out;
    YAML::Node v = need(n, key);
    if (!v) return out;
    if (!v.IsSequence()) {
      error(v.Mark(), fmt::format("plan JSON: '{}' is not a list of points", key));
      return out;
    }
    for (const YAML::Node& q : v) {
      if (!q.IsMap()) {
        error(q.Mark(),
              fmt::format("plan JSON: a point of '{}' is not {{\"x\": ..., \"z\": ...}}", key));
        return out;
      }
      out.push_back({number(q, "x"), number(q, "z")});
    }
    return out;
  }
};

// What a chain's JSON leaves to be worked out: the lead axis from its kind, and whether its
// pull-out is cut linear (at less than 30 or more than 60 degrees to the last segment, as the
// planner decides).
void chain_details(ThreadPlan& p) {
  p.lead_along_z = p.kind != ThreadKind::kFace;
  if (!p.pullout || p.points.size() < 2) return;
  const Vec2 a = p.points[p.points.size() - 2], b = p.points.back();
  const double tx = b.x - a.x, tz = b.z - a.z;
  const double along = (p.pullout->x * tx + p.pullout->z * tz) / std::hypot(tx, tz);
  const double out = std::fabs(p.pullout->x * tz - p.pullout->z * tx) / std::hypot(tx, tz);
  const double angle = degrees(std::atan2(out, along));
  p.pullout_linear = angle < 30 - 1e-9 || angle > 60 + 1e-9;
}

// One pass of thread `p` (a chain's passes have a path).
ThreadPass read_pass(Reader& r, const YAML::Node& q, const ThreadPlan& p, bool chain) {
  ThreadPass s;
  s.n = static_cast<int>(std::lround(r.number(q, "n")));
  s.start = static_cast<int>(std::lround(r.number(q, "start")));
  s.depth = r.number(q, "depth");
  constexpr PassKind kPassKinds[] = {PassKind::kRough, PassKind::kFinish, PassKind::kSpring};
  s.kind = named(r.word(q, "kind"), kPassKinds, pass_kind_name);
  s.shift = r.number(q, "shift");
  s.from = r.point(q, "from");
  s.to = r.point(q, "to");
  if (chain) s.path = r.points(q, "path");
  s.pullout_end = p.pullout ? Vec2{s.to.x + p.pullout->x, s.to.z + p.pullout->z} : s.to;
  s.start_angle = p.starts_by_angle ? s.start * 360.0 / p.pitch.starts : 0;
  return s;
}

// One thread of the JSON, or nothing when it cannot be verified from the JSON (a form whose
// path the JSON does not hold) or has no passes.
std::optional<ThreadPlan> read_thread(Reader& r, const YAML::Node& t, const std::string& units,
                                      const Machine& m) {
  ThreadPlan p;
  p.units = units == units_name(LengthUnit::kInch) ? LengthUnit::kInch : LengthUnit::kMm;
  p.loc.line = static_cast<uint32_t>(std::max(0.0, r.number(t, "line")));
  p.loc.col = 1;
  const std::string form = r.word(t, "form");
  const bool chain = form == form_name(ThreadForm::kChain);
  if (r.ok && form != form_name(ThreadForm::kMulti) && !chain) {
    r.error(t.Mark(), fmt::format("thread at line {}: a {} thread's path is not in the plan "
                                  "JSON; verify against the CL file (--cl)",
                                  p.loc.line, form));
    return std::nullopt;
  }
  constexpr ThreadKind kKinds[] = {ThreadKind::kTurn, ThreadKind::kFace, ThreadKind::kTaper};
  constexpr ThreadSide kSides[] = {ThreadSide::kExternal, ThreadSide::kInternal};
  p.kind = named(r.word(t, "kind"), kKinds, kind_name);
  p.side = named(r.word(t, "side"), kSides, side_name);
  p.pitch.set = true;
  p.pitch.pitch = r.number(t, "pitch");
  p.lead = r.number(t, "lead");
  p.pitch.starts = static_cast<int>(std::lround(r.number(t, "starts")));
  p.depth = r.number(t, "depth");
  p.option = static_cast<int>(std::lround(r.number(t, "option")));
  p.tool_angle = r.number(t, "tool_angle");
  p.cutang = r.number(t, "cutang");
  p.p1 = r.point(t, "p1");
  p.p2 = r.point(t, "p2");
  if (YAML::Node po = t["pullout"]; po && !po.IsNull()) p.pullout = r.point(t, "pullout");
  if (chain) {
    p.form = ThreadForm::kChain;
    p.points = r.points(t, "points");
  }
  p.lead_along_z = std::fabs(p.p2.z - p.p1.z) >= std::fabs(p.p2.x - p.p1.x);
  if (chain) chain_details(p);
  p.starts_by_angle = p.pitch.starts > 1 && m.start_angle_word;
  YAML::Node passes = r.need(t, "passes");
  if (!passes) return std::nullopt;
  for (const YAML::Node& q : passes) p.passes.push_back(read_pass(r, q, p, chain));
  return p;
}

}  // namespace

bool read_plan_json(std::string_view text, const Machine& m, std::vector<ThreadPlan>& plans,
                    Diagnostics& diags) {
  const YamlText lines(text);
  Reader r{lines, diags};
  YAML::Node root;
  try {
    root = YAML::Load(std::string(text));
  } catch (const YAML::Exception& e) {
    r.error(e.mark, "plan JSON: " + e.msg);
    return false;
  }
  if (root.IsSequence()) {
    r.error(root.Mark(), "plan JSON of several files: verify one program against one file's plan");
    return false;
  }
  if (!root.IsMap()) {
    r.error(root.Mark(),
            "plan JSON: not an object (expected the output of clpost plan --format json)");
    return false;
  }
  const std::string units = r.word(root, "units");
  if (r.ok && units != units_name(LengthUnit::kMm) && units != units_name(LengthUnit::kInch))
    r.error(root["units"].Mark(),
            units.empty() ? std::string("plan JSON: units empty, expected mm or in")
                          : fmt::format("plan JSON: units '{}', expected mm or in", units));
  YAML::Node threads = r.need(root, "threads");
  if (!r.ok) return false;
  for (const YAML::Node& t : threads)
    if (std::optional<ThreadPlan> p = read_thread(r, t, units, m)) plans.push_back(std::move(*p));
  return r.ok;
}

}  // namespace clpost

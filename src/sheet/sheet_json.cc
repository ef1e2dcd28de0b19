// The sheet as JSON: the same tool list, times, holes, outputs and warnings as the page, and the
// thread plans exactly as `clpost plan --format json` writes them (plan_to_json).
#include <fmt/format.h>

#include <cmath>

#include "planner/plan_format.h"
#include "sheet/sheet.h"
#include "sheet/sheet_text.h"
#include "support/json_text.h"
#include "support/number_text.h"

namespace clpost {

namespace {

std::string num(double v) {
  return std::isfinite(v) ? num_text(v) : "null";
}

template <class T, class F>
std::string array(const std::vector<T>& v, F item) {
  std::string o = "[";
  for (size_t i = 0; i < v.size(); ++i) o += (i ? ", " : "") + item(v[i]);
  return o + "]";
}

std::string tool_json(const ToolTime& t, const SheetData& d) {
  auto feed = [&](const FeedUsed& f) {
    return fmt::format("{{\"value\": {}, \"per\": \"{}\", \"text\": {}}}", num(f.value),
                       f.mode == FeedMode::kPerRev ? "rev" : "min",
                       json_string(feed_text(f, d.units)));
  };
  auto speed = [&](const SpeedUsed& s) {
    return fmt::format("{{\"value\": {}, \"css\": {}, \"text\": {}}}", num(s.value),
                       s.css ? "true" : "false", json_string(speed_text(s, d.units)));
  };
  return fmt::format(
      "    {{\"tool\": {}, \"offset\": {}, \"text\": {}, \"nose_radius\": {}, "
      "\"first_nc_line\": {}, \"last_nc_line\": {}, \"cutting_seconds\": {}, \"seconds\": {}, "
      "\"cutting_time\": {}, \"time\": {}, \"feeds\": {}, \"speeds\": {}, \"reach\": {}}}",
      t.tool < 0 ? "null" : std::to_string(t.tool),
      t.offset < 0 ? "null" : std::to_string(t.offset), json_string(t.text),
      t.nose_radius ? num(*t.nose_radius) : "null", t.first_nc_line, t.last_nc_line,
      num(t.cutting_seconds), num(t.seconds), json_string(time_text(t.cutting_seconds)),
      json_string(time_text(t.seconds)), array(t.feeds, feed), array(t.speeds, speed),
      json_string(reach_text(t, d.diameter)));
}

std::string output_json(const OutputUsed& o) {
  auto unfit = [](const Unfit& u) {
    return fmt::format("{{\"name\": {}, \"reason\": {}}}", json_string(u.name),
                       json_string(u.reason));
  };
  return fmt::format("    {{\"line\": {}, \"output\": {}, \"not_used\": {}, \"notes\": {}}}",
                     o.loc.line, json_string(o.name), array(o.unfit, unfit),
                     array(o.notes, [](const std::string& n) { return json_string(n); }));
}

// A hole: x (a radius) and z of its top, the axis it is drilled along ("z"; "x" for a radial
// hole of a live tool, r then along X too) and its C (null on the centre line).
std::string hole_json(const Hole& h) {
  return fmt::format(
      "    {{\"line\": {}, \"cycle\": {}, \"x\": {}, \"z\": {}, \"axis\": \"{}\", \"c\": {}, "
      "\"depth\": {}, \"r\": {}, \"first_peck\": {}, \"peck\": {}, \"dwell\": {}, \"feed\": {}, "
      "\"per\": \"{}\", \"tool_diameter\": {}}}",
      h.cl_line, json_string(hole_kind_name(h.kind)), num(h.radial ? h.top : h.x),
      num(h.radial ? h.z : h.top), h.radial ? "x" : "z", h.c ? num(*h.c) : std::string("null"),
      num(std::fabs(h.bottom - h.top)), num(h.r), num(h.first_peck), num(h.peck), num(h.dwell),
      num(h.feed), h.feed_mode == FeedMode::kPerRev ? "rev" : "min",
      h.tool_diameter ? num(*h.tool_diameter) : std::string("null"));
}

std::string diagnostic_json(const Diagnostic& g) {
  return fmt::format("    {{\"line\": {}, \"severity\": \"{}\", \"message\": {}}}", g.loc.line,
                     severity_name(g.severity), json_string(g.message));
}

// Items one per line, indented by the item writer.
template <class T, class F>
std::string list(const std::vector<T>& v, F item) {
  if (v.empty()) return "[]";
  std::string o = "[\n";
  for (size_t i = 0; i < v.size(); ++i) o += item(v[i]) + (i + 1 < v.size() ? ",\n" : "\n");
  return o + "  ]";
}

}  // namespace

std::string sheet_json(const SheetData& d) {
  std::vector<ToolTime> tools;
  for (const ToolTime& t : d.cycle_time.tools)
    if (listed(t)) tools.push_back(t);
  std::string o = "{\n";
  o += fmt::format("  \"program\": {},\n", json_string(d.program));
  o += fmt::format("  \"partno\": {},\n", json_string(d.partno));
  o += fmt::format("  \"nc_file\": {},\n", json_string(d.nc_file));
  o += fmt::format("  \"machine\": {},\n", json_string(d.machine));
  o += fmt::format("  \"date\": {},\n", json_string(d.date));
  o += fmt::format("  \"units\": \"{}\",\n", units_name(d.units));
  o += fmt::format("  \"cycle_seconds\": {},\n", num(d.cycle_time.total()));
  o += fmt::format("  \"cycle_time\": {},\n", json_string(time_text(d.cycle_time.total())));
  o += fmt::format("  \"tool_changes\": {},\n", tool_changes(d.cycle_time));
  o += fmt::format("  \"rapids_untimed\": {},\n", d.cycle_time.rapids_untimed ? "true" : "false");
  o += "  \"tools\": " + list(tools, [&](const ToolTime& t) { return tool_json(t, d); }) + ",\n";
  o += "  \"outputs\": " + list(d.outputs, output_json) + ",\n";
  o += "  \"holes\": " + list(d.holes, hole_json) + ",\n";
  o += fmt::format("  \"warnings\": {},\n", d.warnings);
  o += "  \"diagnostics\": " + list(d.diagnostics, diagnostic_json) + ",\n";
  std::string plan = plan_to_json(d.program, d.units, d.plans);
  while (!plan.empty() && plan.back() == '\n') plan.pop_back();
  o += "  \"plan\": " + plan + "\n";
  return o + "}\n";
}

}  // namespace clpost

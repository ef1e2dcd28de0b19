#include "compare.h"

#include <algorithm>
#include <cctype>
#include <cmath>
#include <cstdio>
#include <optional>

namespace oracle {

namespace {

constexpr double kEps = 1e-9;
constexpr double kMPerFoot = 0.3048;

struct Check {
  std::string field, detail;
};

std::string num(double v) {
  char buf[64];
  std::snprintf(buf, sizeof buf, "%.6g", v);
  return buf;
}

Check differs(std::string field, const std::string& model, const std::string& rs274) {
  return {std::move(field), "model " + model + ", rs274 " + rs274};
}

bool near(double a, double b, double tol) {
  return std::abs(a - b) <= tol + kEps;
}

// The tolerance of end points (`half`) or centres in the program's unit at `r`.
double tolerance(const Resolution& res, const Event& r, bool half) {
  const double inc = r.inch ? res.inch * kMmPerInch : res.mm;
  return std::max(kPointTolerance, half ? inc / 2 : inc);
}

std::optional<Check> geometry(const Event& m, const Event& r, const Resolution& res) {
  if (m.kind != r.kind)
    return differs("event", m.kind == Event::Kind::kDwell ? "a dwell" : "a motion",
                   r.kind == Event::Kind::kDwell ? "a dwell" : "a motion");
  if (m.kind == Event::Kind::kDwell) {
    if (!near(m.seconds, r.seconds, 5e-4))
      return differs("dwell", num(m.seconds) + " s", num(r.seconds) + " s");
    return std::nullopt;
  }
  const char* kinds[] = {"rapid", "feed", "arc", "thread"};
  auto home = [](int h) {
    return std::string(h == 0        ? "a move"
                       : h == kHomeX ? "a return in X"
                       : h == kHomeZ ? "a return in Z"
                                     : "a return in X and Z");
  };
  if (m.home != r.home) return differs("home return", home(m.home), home(r.home));
  if (m.home) return std::nullopt;  // where the reference is, neither says
  if (m.motion != r.motion)
    return differs("motion", kinds[static_cast<int>(m.motion)], kinds[static_cast<int>(r.motion)]);
  const double end = tolerance(res, r, true), centre = tolerance(res, r, false);
  if (!near(m.x, r.x, end) || !near(m.z, r.z, end))
    return differs("end point", "X" + num(m.x) + " Z" + num(m.z), "X" + num(r.x) + " Z" + num(r.z));
  if (m.motion == MotionKind::kArc) {
    if (!near(m.cx, r.cx, centre) || !near(m.cz, r.cz, centre))
      return differs("arc centre", "X" + num(m.cx) + " Z" + num(m.cz),
                     "X" + num(r.cx) + " Z" + num(r.cz));
    if (m.rotation != r.rotation) return differs("arc sense", num(m.rotation), num(r.rotation));
  }
  // A lead is an F: half its last digit (4 decimals; in an inch program 0.00127 mm).
  const double lead = r.inch ? (0.5e-4 + 0.5e-6) * kMmPerInch : kPointTolerance;
  if (m.motion == MotionKind::kThread && !near(m.lead, r.lead, lead))
    return differs("lead", num(m.lead) + " mm", num(r.lead) + " mm");
  return std::nullopt;
}

// Speeds are compared in the program's unit, to half a unit of the S word (no decimals).
std::optional<Check> spindle(const Event& m, const Event& r) {
  const Spindle &a = m.state.spindle, &b = r.state.spindle;
  if (a.on != b.on) return differs("spindle on/off", a.on ? "on" : "off", b.on ? "on" : "off");
  if (!a.on) return std::nullopt;
  if (a.dir != b.dir)
    return differs("spindle direction", a.dir == SpindleDir::kCw ? "CW" : "CCW",
                   b.dir == SpindleDir::kCw ? "CW" : "CCW");
  if (a.css != b.css) return differs("spindle mode", a.css ? "CSS" : "RPM", b.css ? "CSS" : "RPM");
  const double unit = a.css && r.inch ? kMPerFoot : 1;
  if (!near(a.speed / unit, b.speed / unit, 0.5))
    return differs("spindle speed", num(a.speed) + (a.css ? " m/min" : " rpm"),
                   num(b.speed) + (b.css ? " m/min" : " rpm") + (r.inch ? " (G20)" : ""));
  if (a.css && !near(a.limit, b.limit, 0.5))
    return differs("CSS limit", num(a.limit) + " rpm", num(b.limit) + " rpm");
  return std::nullopt;
}

// Feeds to half the last digit rs274 prints (4 decimals in the program's unit), at least 1e-4 mm.
// In inch the program's F has 6 decimals (posts/linuxcnc.yaml) and rs274 rounds that again to 4:
// half a digit of each (F2.30185 for 2.3018504 in/min, printed 2.3018).
std::optional<Check> feed(const Event& m, const Event& r) {
  if (m.kind != Event::Kind::kMotion ||
      (m.motion != MotionKind::kFeed && m.motion != MotionKind::kArc))
    return std::nullopt;
  const Modal &a = m.state, &b = r.state;
  const char* mode[] = {" mm/min", " mm/rev"};
  if (a.feed_mode != b.feed_mode)
    return differs("feed mode", mode[static_cast<int>(a.feed_mode)] + 1,
                   mode[static_cast<int>(b.feed_mode)] + 1);
  const double tol =
      std::max(kPointTolerance, r.inch ? (0.5e-4 + 0.5e-6) * kMmPerInch : 0.5e-4) + 1e-9;
  if (!b.feed_given || !near(a.feed, b.feed, tol))
    return differs("feed", num(a.feed) + mode[static_cast<int>(a.feed_mode)],
                   num(b.feed) + mode[static_cast<int>(b.feed_mode)] + (r.inch ? " (G20)" : ""));
  return std::nullopt;
}

std::optional<Check> tool(const Event& m, const Event& r) {
  const Modal &a = m.state, &b = r.state;
  if (a.tool != b.tool) return differs("tool", num(a.tool), num(b.tool));
  if (a.offset != b.offset) return differs("tool offset", num(a.offset), num(b.offset));
  return std::nullopt;
}

std::optional<Check> coolant(const Event& m, const Event& r) {
  const Coolant &a = m.state.coolant, &b = r.state.coolant;
  if (a.flood == b.flood && a.mist == b.mist) return std::nullopt;
  auto text = [](const Coolant& c) {
    return std::string(c.flood ? "flood" : "") + (c.flood && c.mist ? "+" : "") +
           (c.mist ? "mist" : "") + (!c.flood && !c.mist ? "off" : "");
  };
  return differs("coolant", text(a), text(b));
}

}  // namespace

namespace {

// A run that stopped: "rs274 error: …", "fanuc error: …" (differential.cc).
bool stops(const std::string& field) {
  return field.find(" error: ") != std::string::npos;
}

// The cause a difference in the run with block delete on is due to: a statement inside a range
// whose effect the program does not say again after it.
std::string range_cause(const std::string& field, const Event& m) {
  const Provenance& w = m.why;
  const bool stop = stops(field);
  const bool spindle = field.rfind("spindle", 0) == 0 || field == "CSS limit" ||
                       (stop && field.find("pindle") != std::string::npos);
  if ((field == "feed" || field == "feed mode" ||
       (stop && field.find("feed rate") != std::string::npos)) &&
      w.feed_in_range)
    return "FEDRAT inside an OPSKIP range";
  if (spindle && w.spindle_in_range) return "SPINDL inside an OPSKIP range";
  if (field == "coolant" && w.coolant_in_range) return "COOLNT inside an OPSKIP range";
  if (w.after_range) return "first motion after an OPSKIP range";
  return "";
}

// The one cause of a difference the model's provenance points at, or "".
std::string cause(const std::string& field, const Event& m) {
  const Provenance& w = m.why;
  const bool css = m.state.spindle.css;
  if (field == "feed mode" && w.feed_without_mode) return "FEDRAT without mode";
  if (field == "feed" && w.units_since_feed) return "after UNITS";
  if (field == "feed" && w.feed_without_mode) return "FEDRAT without mode";
  if (field == "CSS limit" && w.maxrpm_from_earlier) return "MAXRPM of an earlier SPINDL";
  if (field == "spindle speed" && css && w.units_since_spindle) return "after UNITS";
  if (field.rfind("spindle", 0) == 0 && field != "spindle on/off" && w.spindle_by_on)
    return "after SPINDL/ON";
  if (field == "CSS limit" && w.spindle_by_on) return "after SPINDL/ON";
  const bool spindle_stop =
      field == "spindle on/off" || (stops(field) && field.find("pindle") != std::string::npos);
  if (spindle_stop && w.tool_change_since_spindle) return "after a tool change";
  if (field == "tool offset" && m.state.offset != m.state.tool) return "LOADTL ADJUST";
  if (field == "lead" && w.modal_pitch && w.units_since_pitch) return "PITCH before UNITS";
  return "";
}

}  // namespace

std::string class_of(const std::string& field, const Event& m, bool block_delete) {
  std::string c = block_delete ? range_cause(field, m) : cause(field, m);
  if (block_delete && c.empty()) c = "after an OPSKIP range";
  return c.empty() ? field : field + " [" + c + "]";
}

std::string without_numbers(const std::string& text) {
  std::string out;
  for (char c : text)
    if (!std::isdigit(static_cast<unsigned char>(c)) && c != '.' && c != '-') out += c;
  return out;
}

namespace {

// Records `c`, a difference of event `i`: its class, and the first difference.
void note(Comparison& out, const Check& c, size_t i, const std::vector<Event>& model,
          const std::vector<Event>& rs274, bool block_delete) {
  const std::string klass = class_of(c.field, model[i], block_delete);
  const Difference d{true, i, c.field, klass, c.detail, true, true, model[i], rs274[i]};
  out.found.push_back({d, class_of(c.field, model[i], false)});
  if (!out.first.found) out.first = d;
}

// A run that ends early or goes on: the first event one side has and the other not.
Difference count_difference(const std::vector<Event>& model, const std::vector<Event>& rs274,
                            bool block_delete) {
  const size_t n = std::min(model.size(), rs274.size());
  Difference d;
  d.found = true;
  d.index = n;
  d.have_model = model.size() > n;
  d.have_rs274 = rs274.size() > n;
  d.field = d.have_model ? "missing event" : "extra event";
  if (d.have_model) d.model = model[n];
  if (d.have_rs274) d.rs274 = rs274[n];
  d.klass = d.have_model ? class_of(d.field, d.model, block_delete) : d.field;
  d.detail = std::to_string(model.size()) + " model events, " + std::to_string(rs274.size()) +
             " rs274 events";
  return d;
}

}  // namespace

Comparison compare_events(const std::vector<Event>& model, const std::vector<Event>& rs274,
                          bool block_delete, const Resolution& resolution) {
  Comparison out;
  const size_t n = std::min(model.size(), rs274.size());
  for (size_t i = 0; i < n; ++i) {
    if (std::optional<Check> g = geometry(model[i], rs274[i], resolution)) {
      note(out, *g, i, model, rs274, block_delete);
      out.lined_up = i;
      return out;  // the events no longer line up
    }
    if (model[i].kind != Event::Kind::kMotion) continue;
    for (auto check : {spindle, feed, tool, coolant})
      if (std::optional<Check> c = check(model[i], rs274[i]))
        note(out, *c, i, model, rs274, block_delete);
  }
  out.lined_up = n;
  if (model.size() == rs274.size()) return out;
  const Difference d = count_difference(model, rs274, block_delete);
  out.found.push_back({d, d.have_model ? class_of(d.field, d.model, false) : d.field});
  if (!out.first.found) out.first = d;
  return out;
}

}  // namespace oracle

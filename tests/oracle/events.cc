#include "events.h"

#include <cstdio>

namespace oracle {

namespace {

std::string fmt(const char* f, double v) {
  char buf[64];
  std::snprintf(buf, sizeof buf, f, v);
  return buf;
}

const char* kind_name(MotionKind k) {
  switch (k) {
    case MotionKind::kRapid:
      return "rapid";
    case MotionKind::kFeed:
      return "feed";
    case MotionKind::kArc:
      return "arc";
    case MotionKind::kThread:
      return "thread";
  }
  return "?";
}

std::string spindle_text(const Spindle& s) {
  if (!s.on) return "spindle off";
  std::string t = s.css ? fmt("CSS %.4g m/min", s.speed) + fmt(" limit %.6g rpm", s.limit)
                        : fmt("S%.6g rpm", s.speed);
  return t + (s.dir == SpindleDir::kCw ? " CW" : " CCW");
}

}  // namespace

std::string describe_state(const Modal& m, bool with_feed) {
  std::string t;
  if (with_feed) {
    t += m.feed_given
             ? fmt("F%.6g", m.feed) + (m.feed_mode == FeedMode::kPerRev ? " mm/rev" : " mm/min")
             : "no feed";
    t += " | ";
  }
  t += spindle_text(m.spindle);
  t += " | T" + std::to_string(m.tool) + " offset " + std::to_string(m.offset);
  if (m.coolant.flood) t += " | flood";
  if (m.coolant.mist) t += " | mist";
  return t;
}

std::string describe(const Event& e) {
  std::string t;
  if (e.kind == Event::Kind::kDwell) {
    t = "dwell " + fmt("%.4f s", e.seconds);
  } else if (e.home) {
    t = std::string("return to the reference position in ") + (e.home == (kHomeX | kHomeZ)
                                                                   ? "X and Z"
                                                               : e.home == kHomeX ? "X"
                                                                                  : "Z");
  } else {
    t = std::string(kind_name(e.motion)) + " to X" + fmt("%.4f", e.x) + " Z" + fmt("%.4f", e.z) +
        " (mm, X radius)";
    if (e.motion == MotionKind::kArc)
      t += fmt(" around X%.4f", e.cx) + fmt(" Z%.4f", e.cz) +
           (e.rotation > 0 ? " counter-clockwise" : " clockwise");
    if (e.motion == MotionKind::kThread) t += fmt(" lead %.6g mm", e.lead);
    t += " | " +
         describe_state(e.state, e.motion == MotionKind::kFeed || e.motion == MotionKind::kArc);
  }
  if (e.skipped) t += " | in an OPSKIP range";
  if (!e.source.empty()) t += " | " + e.source;
  return t;
}

bool spindle_coolant_m(int m, bool& on, bool& ccw, Coolant& coolant) {
  if (m == 3 || m == 4)
    on = true, ccw = m == 4;
  else if (m == 5)
    on = false;
  else if (m == 8)
    coolant.flood = true;
  else if (m == 7)
    coolant.mist = true;
  else if (m == 9)
    coolant = {};
  else
    return false;
  return true;
}

}  // namespace oracle

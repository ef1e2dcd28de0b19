#include "canon.h"

#include <cmath>
#include <cstdlib>

namespace oracle {

namespace {

constexpr double kMPerFoot = 0.3048;

struct Call {
  std::string name;
  std::vector<double> numbers;
  std::string text;
  int index = 0;  // rs274's own numbering of its calls
};

bool parse_call(std::string_view line, Call& c) {
  const size_t open = line.find('('), close = line.rfind(')');
  if (open == std::string_view::npos || close == std::string_view::npos || close < open)
    return false;
  size_t b = open;
  while (b > 0 && line[b - 1] != ' ') --b;
  c.name = std::string(line.substr(b, open - b));
  c.text = std::string(line.substr(b, close + 1 - b));
  c.index = std::atoi(std::string(line.substr(0, b)).c_str());
  std::string args(line.substr(open + 1, close - open - 1));
  for (char& ch : args)
    if (ch == ',') ch = ' ';
  const char* p = args.c_str();
  while (*p) {
    char* end = nullptr;
    const double v = std::strtod(p, &end);
    if (end == p) {
      ++p;
      continue;
    }
    c.numbers.push_back(v);
    p = end;
  }
  return true;
}

class Reader {
 public:
  void call(const Call& c);
  std::vector<Event> events;

 private:
  double len(double v) const { return inch_ ? v * kMmPerInch : v; }
  bool motion(const Call& c);
  bool spindle(const Call& c);
  bool tool_or_coolant(const Call& c);
  Modal modal() const;
  void push(Event e, const Call& c);

  bool inch_ = false;
  bool plane_xz_ = false;
  double feed_ = 0;
  bool per_rev_ = false;
  bool sync_ = false;
  double lead_ = 0;
  Spindle spindle_;
  double css_max_ = 0;
  int selected_ = 0, tool_ = 0, offset_ = 0;
  Coolant coolant_;
};

Modal Reader::modal() const {
  Modal m;
  m.feed_given = feed_ > 0;
  m.feed = len(feed_);
  m.feed_mode = per_rev_ ? FeedMode::kPerRev : FeedMode::kPerMinute;
  m.spindle = spindle_;
  m.spindle.css = css_max_ > 0;
  m.spindle.limit = m.spindle.css ? css_max_ : 0;
  if (m.spindle.css && inch_) m.spindle.speed *= kMPerFoot;
  m.tool = tool_, m.offset = offset_;
  m.coolant = coolant_;
  return m;
}

void Reader::push(Event e, const Call& c) {
  e.state = modal();
  e.inch = inch_;
  e.line = c.index;
  e.source = (plane_xz_ ? "" : "[not in the XZ plane] ") + c.text;
  events.push_back(e);
}

bool Reader::motion(const Call& c) {
  const std::vector<double>& n = c.numbers;
  Event e;
  if ((c.name == "STRAIGHT_TRAVERSE" || c.name == "STRAIGHT_FEED") && n.size() >= 3) {
    e.motion = c.name == "STRAIGHT_TRAVERSE" ? MotionKind::kRapid
               : sync_                       ? MotionKind::kThread
                                             : MotionKind::kFeed;
    e.x = len(n[0]), e.z = len(n[2]);
    e.lead = e.motion == MotionKind::kThread ? len(lead_) : 0;
  } else if (c.name == "ARC_FEED" && n.size() >= 5) {
    // XZ plane: the first axis is Z, the second X.
    e.motion = MotionKind::kArc;
    e.z = len(n[0]), e.x = len(n[1]), e.cz = len(n[2]), e.cx = len(n[3]);
    e.rotation = static_cast<int>(n[4]);
  } else if (c.name == "DWELL" && !n.empty()) {
    e.kind = Event::Kind::kDwell;
    e.seconds = n[0];
  } else {
    return false;
  }
  push(e, c);
  return true;
}

bool Reader::spindle(const Call& c) {
  const std::vector<double>& n = c.numbers;
  if (c.name == "SET_SPINDLE_SPEED" && n.size() >= 2)
    spindle_.speed = n[1];
  else if (c.name == "SET_SPINDLE_MODE" && n.size() >= 2)
    css_max_ = n[1];
  else if (c.name == "START_SPINDLE_CLOCKWISE")
    spindle_.on = true, spindle_.dir = SpindleDir::kCw;
  else if (c.name == "START_SPINDLE_COUNTERCLOCKWISE")
    spindle_.on = true, spindle_.dir = SpindleDir::kCcw;
  else if (c.name == "STOP_SPINDLE_TURNING")
    spindle_.on = false;
  else
    return false;
  return true;
}

bool Reader::tool_or_coolant(const Call& c) {
  const std::vector<double>& n = c.numbers;
  if (c.name == "SELECT_TOOL" && !n.empty()) {
    selected_ = static_cast<int>(n[0]);
  } else if (c.name == "CHANGE_TOOL") {
    tool_ = selected_;  // its argument is the pocket, not the tool
  } else if (c.name == "USE_TOOL_LENGTH_OFFSET" && n.size() >= 3) {
    const double inches = inch_ ? n[2] : n[2] / kMmPerInch;
    offset_ = static_cast<int>(std::lround(inches / kOffsetStepInch));
  } else if (c.name == "FLOOD_ON" || c.name == "FLOOD_OFF") {
    coolant_.flood = c.name == "FLOOD_ON";
  } else if (c.name == "MIST_ON" || c.name == "MIST_OFF") {
    coolant_.mist = c.name == "MIST_ON";
  } else {
    return false;
  }
  return true;
}

void Reader::call(const Call& c) {
  const std::vector<double>& n = c.numbers;
  if (motion(c) || spindle(c) || tool_or_coolant(c)) return;
  if (c.name == "USE_LENGTH_UNITS")
    inch_ = c.text.find("INCHES") != std::string::npos;
  else if (c.name == "SELECT_PLANE")
    plane_xz_ = c.text.find("CANON_PLANE_XZ") != std::string::npos;
  else if (c.name == "SET_FEED_RATE" && !n.empty())
    feed_ = n[0];
  else if (c.name == "SET_FEED_MODE" && n.size() >= 2)
    per_rev_ = n[1] == 1;
  else if (c.name == "START_SPEED_FEED_SYNC" && !n.empty())
    sync_ = true, lead_ = n[0];
  else if (c.name == "STOP_SPEED_FEED_SYNCH")
    sync_ = false;
}

}  // namespace

std::vector<Event> canon_events(std::string_view canon) {
  Reader r;
  while (!canon.empty()) {
    const size_t nl = canon.find('\n');
    Call c;
    if (parse_call(canon.substr(0, nl), c)) r.call(c);
    canon = nl == std::string_view::npos ? std::string_view() : canon.substr(nl + 1);
  }
  return r.events;
}

}  // namespace oracle

// The HEIDENHAIN DIN reader (heidenhain_reader.h). Sources, cited at each meaning:
//   [4290P]  HEIDENHAIN CNC PILOT 4290 "Pilot" (DIN PLUS quick reference), by page
//            (azmanual.top/manuals/798332, manualsdir.com/manuals/798332).
//   [4110]   HEIDENHAIN MANUALplus 4110 User's Manual, by section (easymanua.ls/heidenhain/
//            manualplus-4110; manualshelf.com, its "Operation Manual").
//   [640]    HEIDENHAIN CNC PILOT 640 "smart.Turn and DIN Programming" 12/2017, by page
//            (easymanua.ls/heidenhain/cnc-pilot-640).
//   [seed]   ../shared/reference/seeds/004_… (DIN Programming User Manual SW 54843x-03, p. 304:
//            a DIN program's blocks as HEIDENHAIN writes them).
//   [ctl]    ../shared/reference/controllers.md, "HEIDENHAIN CNC PILOT / MANUALplus DIN".
//   [none]   no stored page says it: the reader's reading, named as such (docs/cl-meaning.md).
// A meaning the manuals leave to a parameter of the control is refused with the reason.
#include "heidenhain_reader.h"

#include <cctype>
#include <cmath>
#include <cstdlib>
#include <string>
#include <vector>

#include "program_lines.h"

namespace oracle {

namespace {

struct Word {
  std::string address;  // "G", "X", "IC", "BD" …
  double value = 0;
};

struct Block {
  std::vector<Word> words;
  std::string section;    // a program section code alone on its line ("MACHINING", "END")
  bool optional = false;  // "/" first
  const Word* find(std::string_view a) const {
    for (const Word& w : words)
      if (w.address == a) return &w;
    return nullptr;
  }
  bool has_g(int code) const {
    for (const Word& w : words)
      if (w.address == "G" && w.value == code) return true;
    return false;
  }
  bool moves() const { return find("X") || find("Z"); }
};

// [seed] a block is "N 13 G1 X30 BR2": the block number N (a space may follow it), then
// addresses of one or more letters each with a number, a decimal point optional ("X30" is 30
// mm, [4290P] p. 46 "X, Z: Diameter, length to end point"); "[ … ]" is a comment, alone on its
// line or after the words ("N 18 G1 Z-100 [thread]"); a line of capitals alone is a program
// section code ("MACHINING", "AUXILIARY CONTOUR"). "/" first in a block: the block is skipped
// while block delete (the skip level) is on [none: the post's "/N …"; DIN 66025's block skip].
std::string parse(std::string_view line, Block& b) {
  size_t i = 0;
  auto space = [&] {
    while (i < line.size() && (line[i] == ' ' || line[i] == '\t' || line[i] == '\r')) ++i;
  };
  space();
  if (i < line.size() && line[i] == '/') b.optional = true, ++i;
  while (space(), i < line.size()) {
    if (line[i] == '[') {
      const size_t close = line.find(']', i);
      if (close == std::string_view::npos) return "a comment without its ']'";
      i = close + 1;
      continue;
    }
    size_t j = i;
    while (j < line.size() && std::isupper(static_cast<unsigned char>(line[j]))) ++j;
    if (j == i) return std::string("'") + line[i] + "'";
    const std::string address(line.substr(i, j - i));
    size_t k = j;
    while (k < line.size() && line[k] == ' ' && address == "N") ++k;  // "N 10"
    size_t e = k;
    if (e < line.size() && (line[e] == '-' || line[e] == '+')) ++e;
    while (e < line.size() && (std::isdigit(static_cast<unsigned char>(line[e])) || line[e] == '.'))
      ++e;
    const std::string number(line.substr(k, e - k));
    if (number.empty() || number == "-" || number == "+") {
      if (!b.words.empty() || b.optional) return "address " + address + " without a number";
      b.section += (b.section.empty() ? "" : " ") + address;
      i = j;
      continue;
    }
    if (!b.section.empty()) return "a section code with words after it";
    if (address != "N") b.words.push_back({address, std::strtod(number.c_str(), nullptr)});
    i = e;
  }
  return "";
}

class Control {
 public:
  explicit Control(std::optional<bool> unit_inch) : inch_(unit_inch) {}
  bool block(const Block& b, int line, std::string_view text);
  bool ended() const { return ended_; }
  ControlRun run;

 private:
  bool fail(const std::string& why) {
    run.error = why;
    return false;
  }
  double unit() const { return *inch_ ? kMmPerInch : 1; }
  bool section(const Block& b);
  bool known(const Block& b);
  bool modes(const Block& b);
  bool spindle_and_tool(const Block& b);
  bool mcode(int m);
  bool dwell(const Block& b);
  bool motion(const Block& b);
  bool arc(const Block& b, Event& e);
  void push(Event e);
  Modal modal() const;

  std::optional<bool> inch_;
  bool machining_ = false, ended_ = false;
  std::optional<int> motion_;  // G0, G1, G2, G3
  std::optional<bool> per_rev_;
  std::optional<double> x_, z_;  // mm, X a radius
  std::optional<double> f_;      // unknown after G33 (its F is the pitch)
  double s_ = 0;
  std::optional<double> limit_;  // G26
  bool css_ = false, s_css_ = false, on_ = false, ccw_ = false;
  int tool_ = 0;
  Coolant coolant_;
  int line_ = 0;
  std::string text_;
};

// [4110] 1.5 "Feed rate and spindle speed": feed per revolution (mm/rev) or per minute
// (mm/min); constant spindle speed (rev/min) or constant cutting speed (m/min); "if the
// constant spindle speed that you program is greater than the specified maximum spindle
// speed, the maximum speed is valid", and the maximum limits the constant cutting speed too:
// G26 S, the speed limitation, caps either mode.
Modal Control::modal() const {
  Modal m;
  m.feed_given = f_.has_value();
  m.feed = f_.value_or(0) * unit();
  m.feed_mode = per_rev_.value_or(false) ? FeedMode::kPerRev : FeedMode::kPerMinute;
  m.spindle.on = on_;
  m.spindle.dir = ccw_ ? SpindleDir::kCcw : SpindleDir::kCw;
  m.spindle.css = css_;
  // An S given in the other mode: a speed the program does not say (-1, so that it differs).
  const double s = css_ && *inch_ ? s_ * 0.3048 : s_;
  m.spindle.speed = s_css_ != css_ ? -1 : !css_ && limit_ && s_ > *limit_ ? *limit_ : s;
  m.spindle.limit = css_ ? limit_.value_or(0) : 0;
  m.tool = tool_, m.offset = tool_;
  m.coolant = coolant_;
  return m;
}

void Control::push(Event e) {
  e.state = modal();
  e.inch = *inch_;
  e.line = line_;
  e.source = text_;
  run.events.push_back(e);
}

// [4290P] p. 8 "Program section codes": "A DIN program must include the codes MACHINING and
// END"; the PROGRAM HEAD's UNIT is "metric/inches — no input: the unit set in control
// parameter 1 is used", and can be set only when the program is created: no block changes it.
// The reader runs the MACHINING section; the other sections (contours, turret) are refused.
bool Control::section(const Block& b) {
  if (b.section == "MACHINING") return machining_ = true, true;
  if (b.section == "END") return ended_ = true, true;
  return fail("section " + b.section + " is not read by the oracle");
}

// The addresses the reader knows; any other is refused, not ignored.
bool Control::known(const Block& b) {
  static const char* const kAddresses[] = {"G", "X", "Z", "I", "K", "F", "S", "T", "M"};
  for (const Word& w : b.words) {
    bool ok = false;
    for (const char* a : kAddresses) ok = ok || w.address == a;
    if (!ok) return fail("address " + w.address + " is not read by the oracle");
  }
  return true;
}

// The G functions of the block: G0 rapid, G1 linear, G2/G3 arcs ([4290P] p. 46 "Simple linear
// and circular paths"; modal, as the group is in DIN 66025 [none]); G94 feed per minute, G95 per
// revolution ([4110] 1.5; [4290P] p. 106 "G95 is a modal function"); G96 constant cutting speed,
// G97 constant speed ([4110] 1.5; [seed] "N 30 T9 G97 S1000 M3"); G26 the speed limitation, G4
// dwell, G33 a thread cut (one block). G31 (the thread cycle [ctl]) is refused: the manuals name
// its words but not where its cuts start and end.
bool Control::modes(const Block& b) {
  for (const Word& w : b.words) {
    if (w.address != "G") continue;
    const int g = static_cast<int>(w.value);
    if (g != w.value) return fail("G" + std::to_string(w.value) + " is not read by the oracle");
    if (g == 94 || g == 95)
      per_rev_ = g == 95;
    else if (g == 96 || g == 97)
      css_ = g == 96;
    else if (g >= 0 && g <= 3)
      motion_ = g;
    else if (g != 4 && g != 26 && g != 33)
      return fail("G" + std::to_string(g) + " is not read by the oracle");
  }
  return true;
}

// S: with G26 the speed limitation (rev/min), else the speed in the block's mode. G96 before any
// G26 turns up to the machine's maximum, a parameter: refused. T: the turret position; its tool's
// data (and so its offset) are the tool's own, from the TURRET section or the tool database
// ([4290P] p. 8, "T-number: position in the tool carrier"); the spindle keeps turning.
bool Control::spindle_and_tool(const Block& b) {
  if (const Word* s = b.find("S")) {
    if (b.has_g(26))
      limit_ = s->value;
    else
      s_ = s->value, s_css_ = css_;
  } else if (b.has_g(26)) {
    return fail("G26 without S");
  }
  if (css_ && !limit_) return fail("G96 before G26 (its limit is a machine parameter)");
  if (const Word* t = b.find("T")) tool_ = static_cast<int>(t->value);
  for (const Word& w : b.words)
    if (w.address == "M" && !mcode(static_cast<int>(w.value))) return false;
  return true;
}

// M0/M1 stop, M30 end of program; M3/M4 the spindle clockwise/counter-clockwise, M5 stop
// ([seed] "G97 S1000 M3"; [4110] 1.5); M8/M7/M9 flood, mist, off are the builder's codes, as
// the machine file says [none].
bool Control::mcode(int m) {
  if (spindle_coolant_m(m, on_, ccw_, coolant_)) return true;
  if (m != 0 && m != 1 && m != 30)
    return fail("M" + std::to_string(m) + " is not read by the oracle");
  return true;
}

// G4 F: a dwell of F seconds [none: the post file's "G4 F{seconds}", as Autodesk's HEIDENHAIN
// MANUALplus post writes it, "seconds - range 0.001-999"].
bool Control::dwell(const Block& b) {
  const Word* f = b.find("F");
  if (!f || b.moves()) return fail("G4 without F or with a move");
  Event e;
  e.kind = Event::Kind::kDwell;
  e.seconds = f->value;
  push(e);
  return true;
}

// G2 clockwise, G3 counter-clockwise with the X axis up and Z to the right ([4110] 1.1 "Axis
// directions"; the sense is the help graphic's [4110] 6.5), so G3 turns +Z toward +X seen from
// +Y. I, K: the centre from the start point, incremental ([4110] 6.5 "Circular path G2, G3 —
// incremental center coordinates"; G12/G13 take it absolute [640] p. 252), I a radius [none].
bool Control::arc(const Block& b, Event& e) {
  e.rotation = *motion_ == 3 ? 1 : -1;
  const Word *i = b.find("I"), *k = b.find("K");
  if (!i || !k) return fail("an arc without both I and K");
  e.cx = *x_ + i->value * unit();
  e.cz = *z_ + k->value * unit();
  return true;
}

// A block with X or Z moves in the G function in force (X a diameter, [4110] 1.1: "all X-axis
// values … are regarded as diameters"); G1, G2, G3 at F ([4290P] p. 46 "at the programmed feed
// rate"). G33 X Z F: one thread cut at the pitch F, the lead along Z (a thread whose X travel is
// larger needs the reference direction H: refused) and the spindle turning; its F is the pitch,
// so the feed after it is one the reader does not know until an F is written [none].
bool Control::motion(const Block& b) {
  const bool thread = b.has_g(33);
  std::optional<double> x = x_, z = z_;
  if (const Word* w = b.find("X")) x = w->value * unit() / 2;
  if (const Word* w = b.find("Z")) z = w->value * unit();
  if (!b.moves()) return b.find("I") || b.find("K") ? fail("an arc without its end") : true;
  if (!thread && !motion_) return fail("a move before any G0, G1, G2, G3");
  if (!x || !z || (!thread && *motion_ >= 2 && (!x_ || !z_)))
    return fail("a move from a position the program does not state");
  Event e;
  e.x = *x, e.z = *z;
  const int g = thread ? 33 : *motion_;
  e.motion = g == 0 ? MotionKind::kRapid : g == 1 ? MotionKind::kFeed : MotionKind::kArc;
  if (thread) {
    const Word* f = b.find("F");
    if (!f || !on_) return fail(f ? "G33 with the spindle stopped" : "G33 without F");
    if (std::abs(*x - *x_) > std::abs(*z - *z_)) return fail("G33 steeper than 45 degrees");
    e.motion = MotionKind::kThread, e.lead = f->value * unit();
    f_.reset();
  } else if (g != 0 && (!f_ || !per_rev_)) {
    return fail("a feed move before F, G94 or G95 (or after G33's F)");
  }
  if (e.motion == MotionKind::kArc && !arc(b, e)) return false;
  x_ = x, z_ = z;
  push(e);
  return true;
}

bool Control::block(const Block& b, int line, std::string_view text) {
  line_ = line, text_ = std::string(text);
  if (!b.section.empty()) return section(b);
  if (b.words.empty()) return true;
  if (!machining_) return fail("a block outside the MACHINING section");
  if (!inch_) return fail("no UNIT in a PROGRAM HEAD: the unit is control parameter 1");
  if (!known(b) || !modes(b)) return false;
  if (const Word* f = b.find("F"); f && !b.has_g(33) && !b.has_g(4)) f_ = f->value;
  // Whether an M function acts before or after the move of its block is the builder's: refused.
  if (b.moves() && b.find("M")) return fail("an M function in a block that moves");
  if (!spindle_and_tool(b)) return false;
  if (b.has_g(4)) return dwell(b);
  return motion(b);
}

}  // namespace

ControlRun heidenhain_events(std::string_view program, bool block_delete,
                             std::optional<bool> unit_inch) {
  Control c(unit_inch);
  read_program_lines<Block>(
      program, block_delete, c, [](std::string_view text, Block& b) { return parse(text, b); },
      [](int line, std::string_view text) {
        // "%1.nc": the program's name, its first line ([seed]'s manual; the name is the file's).
        return line == 1 && !text.empty() && text[0] == '%';
      });
  if (c.run.error.empty() && !c.ended()) c.run.error = "the program has no END";
  return std::move(c.run);
}

}  // namespace oracle

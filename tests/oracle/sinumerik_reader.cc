// The SINUMERIK reader (sinumerik_reader.h). Sources, cited at each meaning:
//   [PGA]   SINUMERIK 840D sl / SINUMERIK ONE Programming Manual Fundamentals (6FC5398-1BP…,
//           6FC5398-2EP40-0BA0, 12/2019), by the name of its section.
//   [PGI]   SINUMERIK 840Di sl Programming Manual Fundamentals 11/2006 (6FC5398-1BP10-2BA0),
//           §7.1 "Feedrate", §7.11 "Constant cutting rate".
//   [PG840] SINUMERIK 840D Programming Manual Fundamentals 10/2004 (6FC5298-7AB00-0BP1), §7.13
//           "Constant cutting rate (G96, G961, G97, G971, LIMS)".
//   [802]   SINUMERIK 802D sl Operation and Programming 06/2006, §8.2.3 "Dimensions in metric
//           units and inches: G71, G70, G710, G700".
//   [V1]    SINUMERIK 840D sl Function Manual Basic Functions, Feeds (V1) 08/2005, §2.1 "Path
//           feedrate F".
//   [ST]    SINUMERIK 840D sl Operating Manual Turning (ShopTurn) 05/2017, §10.7.12 "Programming
//           a circle with known center point" (the G code ShopTurn writes).
//   [DIN]   DIN 66025-2, the miscellaneous functions M07, M08, M09.
//   [ctl]   ../shared/reference/controllers.md, "Siemens SINUMERIK".
// None of these is in ../shared/reference/ but [ctl]; they were read on the vendors' and
// manual archives' pages (docs/cl-meaning.md names them).
#include "sinumerik_reader.h"

#include <cctype>
#include <cmath>
#include <cstdlib>
#include <optional>
#include <string>
#include <vector>

#include "program_lines.h"

namespace oracle::sinumerik_detail {

namespace {

constexpr double kMPerFoot = 0.3048;

struct Word {
  std::string name;  // "G", "X", "LIMS", "SF", "DIAMON"
  double value = 0;
};

struct Block {
  std::vector<Word> words;
  bool optional = false;  // "/" first: skip level 0
  const Word* find(std::string_view name) const {
    for (const Word& w : words)
      if (w.name == name) return &w;
    return nullptr;
  }
  bool has_g(int code) const {
    for (const Word& w : words)
      if (w.name == "G" && w.value == code) return true;
    return false;
  }
  bool moves() const { return find("X") || find("Z"); }
};

bool keyword(std::string_view name) {
  return name == "DIAMON" || name == "DIAMOF" || name == "DIAM90";
}

// A number: sign, digits, a decimal point optional ("X10" is 10 mm: a value, not a count of
// increments [PGA] "Blocks and block components": an address character and "a digit or sequence
// of digits representing an arithmetic value").
bool number(std::string_view line, size_t& i, double& v) {
  size_t j = i;
  if (j < line.size() && (line[j] == '-' || line[j] == '+')) ++j;
  bool digit = false;
  while (j < line.size() && (std::isdigit(static_cast<unsigned char>(line[j])) || line[j] == '.'))
    digit |= line[j++] != '.';
  if (!digit) return false;
  v = std::strtod(std::string(line.substr(i, j - i)).c_str(), nullptr);
  i = j;
  return true;
}

// [PGA] "Special characters": "/" block suppression (first in the block; "/0" … "/9" the skip
// levels, "/" alone level 0), ";" comment start, blank and tab separators; "N" the block number.
// Extended addresses take "=" (LIMS=, SF=); keywords (DIAMON) stand alone. A call
// (CYCLE99(…)) and any other word are refused with their name.
std::string parse(std::string_view line, Block& b) {
  line = line.substr(0, line.find(';'));
  size_t i = 0;
  auto blank = [&] {
    while (i < line.size() && (line[i] == ' ' || line[i] == '\t' || line[i] == '\r')) ++i;
  };
  blank();
  if (i < line.size() && line[i] == '/') {
    ++i;
    if (i < line.size() && std::isdigit(static_cast<unsigned char>(line[i])))
      if (line[i++] != '0') return "a skip level other than /0";
    b.optional = true;
  }
  while (blank(), i < line.size()) {
    size_t j = i;
    while (j < line.size() && std::isupper(static_cast<unsigned char>(line[j]))) ++j;
    if (j == i) return std::string("'") + line[i] + "'";
    size_t k = j;
    while (k < line.size() && (std::isalnum(static_cast<unsigned char>(line[k])) || line[k] == '_'))
      ++k;
    if (k < line.size() && line[k] == '(')
      return std::string(line.substr(i, k - i)) + "(…) (a call) is not read";
    Word w{std::string(line.substr(i, j - i)), 0};
    i = j;
    if (keyword(w.name)) {
      b.words.push_back(w);
      continue;
    }
    const bool extended = i < line.size() && line[i] == '=';
    if (extended) ++i;
    if (w.name.size() > 1 && !extended) return "the word " + w.name;
    if (!number(line, i, w.value)) return "address " + w.name + " without a number";
    if (w.name != "N") b.words.push_back(w);
  }
  return "";
}

class Control {
 public:
  bool block(const Block& b, int line, std::string_view text);
  bool ended() const { return ended_; }
  ControlRun run;

 private:
  bool fail(const std::string& why) {
    run.error = why;
    return false;
  }
  bool gcode(int g);
  bool feed_type(int g);
  bool modes(const Block& b);
  bool words(const Block& b);
  bool mcode(int m);
  bool dwell(const Block& b);
  bool motion(const Block& b);
  bool arc(const Block& b, Event& e);
  bool thread(const Block& b, Event& e);
  bool feed_ready() const;
  bool length(const Block& b, const char* name, std::optional<double>& mm);
  double unit() const { return *inch_ ? kMmPerInch : 1; }
  double rpm() const;
  Modal modal() const;
  void push(Event e);

  std::optional<bool> inch_;      // G70/G700 inch, G71/G710 mm
  bool feed_in_unit_ = false;     // G700/G710: F in the programmed unit too
  std::optional<int> motion_;     // group 1: 0, 1, 2, 3, 33
  std::optional<bool> per_rev_;   // group 15's feed type
  std::optional<bool> css_;       // group 15's spindle mode
  int spindle_code_ = 0;          // the group 15 code in force (LIMS applies to some)
  std::optional<bool> diameter_;  // DIAMON / DIAM90 (G90 only) diameter, DIAMOF radius
  bool absolute_ = false;         // G90
  std::optional<double> x_, z_;   // mm, X a radius
  double f_ = 0;                  // as written
  bool f_given_ = false, f_inch_ = false;
  double s_rpm_ = 0, s_css_ = 0;  // as written
  bool rpm_known_ = false, css_known_ = false, css_inch_ = false;
  std::optional<double> lims_;  // rev/min
  bool on_ = false, ccw_ = false;
  int tool_ = 0, offset_ = 0;
  Coolant coolant_;
  bool ended_ = false;
  int line_ = 0;
  std::string text_;
};

// Group 15, the feed type and the spindle mode in one group [PGA] "Constant cutting speed (G96/
// G961/G962, G97/G971/G972/G973, LIMS, SCC)": G96 revolutional feedrate "(as for G95)" and
// constant cutting speed, "G95 is activated automatically with G96"; G961 linear feedrate and
// constant cutting speed; G962 either feedrate, constant cutting speed; G97 "revolutional
// feedrate and constant spindle speed"; G971 linear feedrate, constant speed; G972 either
// feedrate, constant speed; G973 as G97 without LIMS. G94/G95 deselect G96 [PG840] ("The
// G96/G961 function can also be deactivated with G94 or G95"). A change of feed type deletes F
// [V1] ("The programmed F value is deleted when the system switches between the feedrate types
// G93, G94 and G95"). Leaving constant cutting speed without an S, the spindle keeps the speed
// it has ([PGA]: "the last speed set with G96 … is retained"): a speed the program does not say.
bool Control::feed_type(int g) {
  std::optional<bool> rev = per_rev_;
  bool css = false;
  if (g == 94 || g == 971)
    rev = false;
  else if (g == 95 || g == 97 || g == 973)
    rev = true;
  else if (g == 96 || g == 961)
    rev = g == 96, css = true;
  else if (g == 962)
    css = true;
  else if (g != 972)
    return false;
  if (rev != per_rev_) f_given_ = false;
  if (css_.value_or(false) && !css) rpm_known_ = false;
  per_rev_ = rev, css_ = css, spindle_code_ = g;
  return true;
}

// The G codes of the block. Group 1 G0, G1, G2, G3, G33 [PGA] "Rapid traverse movement (G0)",
// "Linear interpolation (G1)", "Circular interpolation types", "Thread cutting with constant
// lead (G33)"; group 13 G70/G71/G700/G710 [PGI] §7.1, [802] §8.2.3; group 6 G18 (ZX plane);
// group 7 G40 (no tool radius compensation); group 14 G90 (absolute); group 2 G4 (dwell, one
// block). Anything else is refused.
bool Control::gcode(int g) {
  if (g == 0 || g == 1 || g == 2 || g == 3 || g == 33)
    motion_ = g;
  else if (g == 70 || g == 71 || g == 700 || g == 710)
    inch_ = g == 70 || g == 700, feed_in_unit_ = g >= 700;
  else if (g == 90)
    absolute_ = true;
  else if (g != 4 && g != 18 && g != 40 && !feed_type(g))
    return fail("G" + std::to_string(g) + " is not read by the oracle");
  return true;
}

// DIAMON: diameter for absolute and incremental dimensions; DIAM90: diameter for G90, radius
// for G91; DIAMOF: radius [PGA] "Dimensions for turning and grinding (DIAMON, DIAM90, DIAMOF)".
bool Control::modes(const Block& b) {
  for (const Word& w : b.words) {
    if (w.name == "DIAMON" || w.name == "DIAM90")
      diameter_ = true;
    else if (w.name == "DIAMOF")
      diameter_ = false;
    if (w.name != "G") continue;
    const int g = static_cast<int>(w.value);
    if (g != w.value) return fail("G" + std::to_string(w.value) + " is not read by the oracle");
    if (!gcode(g)) return false;
  }
  if (!inch_ && b.words.size() > 0 && (b.moves() || b.find("F") || b.find("S")))
    return fail("a length before G70, G71, G700 or G710 (the basic system is MD10240)");
  return true;
}

// F: with G70/G71 "feedrate functions are not affected by G70/G71" ([PGI] §7.1): the F is read in
// the basic system, machine data MD10240 SCALING_SYSTEM_IS_METRIC: refused; "with G700/G710,
// feedrate values F are interpreted as geometrical parameters in the measuring system set by G
// function (G700: [inch/min]; G710: [mm/min])" [PGI], "(inch/min, inch/rev. or mm/min,
// mm/rev.)" [802]. S: a speed in rev/min, or under constant cutting speed a cutting speed "m/min
// (for G71/G710) or ft/min (for G70/G700)" [PGA]; LIMS= the upper limit in rev/min [PGA].
// T: the tool (with MD22550 = 0 the T word changes it: the reader's premise, sinumerik_reader.h),
// D: its offset (cutting edge) number; after T alone the edge is MD20270 CUTTING_EDGE_DEFAULT.
bool Control::words(const Block& b) {
  if (const Word* f = b.find("F")) {
    if (!feed_in_unit_) return fail("F under G70 or G71 (read in the basic system, MD10240)");
    f_ = f->value, f_given_ = true, f_inch_ = *inch_;
  }
  if (const Word* s = b.find("S")) {
    if (!css_) return fail("S before G94-G97 (a speed or a cutting speed: MD20150)");
    if (*css_)
      s_css_ = s->value, css_known_ = true, css_inch_ = *inch_;
    else
      s_rpm_ = s->value, rpm_known_ = true;
  }
  if (const Word* l = b.find("LIMS")) lims_ = l->value;
  if (const Word* t = b.find("T")) {
    if (!b.find("D")) return fail("T without D (the edge is MD20270 CUTTING_EDGE_DEFAULT)");
    tool_ = static_cast<int>(t->value);
  }
  if (const Word* d = b.find("D")) offset_ = static_cast<int>(d->value);
  for (const Word& w : b.words)
    if (w.name == "M" && !mcode(static_cast<int>(w.value))) return false;
  return true;
}

// M3/M4/M5 spindle clockwise, counter-clockwise, stop [PGA] "Spindle motion (M3, M4, M5)";
// M0, M1 stop, M2, M30 end of program [PGA] "Program end (M2, M30)"; M7, M8, M9 coolant 2, coolant
// 1, coolant off [DIN] (the builder's, as the machine file says).
bool Control::mcode(int m) {
  if (spindle_coolant_m(m, on_, ccw_, coolant_)) return true;
  if (m == 2 || m == 30)
    ended_ = true;
  else if (m != 0 && m != 1)
    return fail("M" + std::to_string(m) + " is not read by the oracle");
  return true;
}

// The speed the spindle turns at outside constant cutting speed: S, limited by a LIMS the
// program gave under G97 ("LIMS: speed limitation for the master spindle (only applied if
// G96/G961/G97 active)" [PGA]; "the speed limitation is active if G96, G961 and G97 are active"
// [PGI] §7.11); -1 when the program does not say it.
double Control::rpm() const {
  if (!rpm_known_) return -1;
  if (spindle_code_ == 97 && lims_ && s_rpm_ > *lims_) return *lims_;
  return s_rpm_;
}

Modal Control::modal() const {
  Modal m;
  m.feed_given = f_given_;
  m.feed = f_ * (f_inch_ ? kMmPerInch : 1);
  m.feed_mode = per_rev_.value_or(false) ? FeedMode::kPerRev : FeedMode::kPerMinute;
  m.spindle.on = on_;
  m.spindle.dir = ccw_ ? SpindleDir::kCcw : SpindleDir::kCw;
  m.spindle.css = css_.value_or(false);
  m.spindle.speed = !m.spindle.css ? rpm() : css_known_ ? s_css_ * (css_inch_ ? kMPerFoot : 1) : -1;
  m.spindle.limit = m.spindle.css && lims_ ? *lims_ : 0;
  m.tool = tool_, m.offset = offset_;
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

// G4 F<seconds> or G4 S<revolutions of the master spindle>, in a block of its own; the F and S
// of the G4 block are for the dwell only, the F and S programmed before stay [PGA] "Dwell time
// (G4)".
bool Control::dwell(const Block& b) {
  const Word *f = b.find("F"), *s = b.find("S");
  if (b.words.size() != 2 || (f == nullptr) == (s == nullptr))
    return fail("G4 with other words than one F or S");
  Event e;
  e.kind = Event::Kind::kDwell;
  if (f) {
    e.seconds = f->value;
  } else {
    if (!on_ || css_.value_or(true) || rpm() <= 0)
      return fail("G4 S at a spindle speed the program does not say");
    e.seconds = 60 * s->value / rpm();
  }
  push(e);
  return true;
}

// X (DIAMON: a diameter) and Z, absolute (G90) [PGA] "Absolute dimensions (G90, AC)".
bool Control::length(const Block& b, const char* name, std::optional<double>& mm) {
  const Word* w = b.find(name);
  if (!w) return true;
  if (!absolute_) return fail("a position before G90 (the power-on G code is MD20150)");
  const bool x = name[0] == 'X';
  if (x && !diameter_) return fail("X before DIAMON, DIAM90 or DIAMOF (MD20150)");
  mm = w->value * unit() / (x && *diameter_ ? 2 : 1);
  return true;
}

// G2 clockwise, G3 counter-clockwise "viewed from the positive direction of the axis
// perpendicular to the plane" (Y for G18: in (Z, X) G3 turns +Z toward +X); I, K the centre
// from the start point, incremental by default, I a radius: ShopTurn's circle writes "I circle
// center point I ∅ (abs) or circle center point I (inc)" [ST] — the diameter is an absolute
// centre's only [PGA] "Circular interpolation with center and end point (G2/G3, X… Y… Z…, I… J…
// K…)". CR= (a radius) is not read.
bool Control::arc(const Block& b, Event& e) {
  if (b.find("CR")) return fail("CR= is not read by the oracle");
  if (!x_ || !z_) return fail("an arc from a position the program does not state");
  const Word *i = b.find("I"), *k = b.find("K");
  if (!i && !k) return fail("G2/G3 without I or K");
  e.rotation = *motion_ == 3 ? 1 : -1;
  e.cx = *x_ + (i ? i->value * unit() : 0);
  e.cz = *z_ + (k ? k->value * unit() : 0);
  return true;
}

// G33 Z… K<lead> (I<lead> where the X travel is the longer: the lead's axis), SF= the start
// angle (not in the events) [ctl] "G33 loop", [PGA] "Thread cutting with constant lead (G33)"
// ("Interpolation parameters I, J, K (also thread pitch)" are read in G70/G71's unit [802]);
// the spindle must turn.
bool Control::thread(const Block& b, Event& e) {
  const Word *i = b.find("I"), *k = b.find("K");
  if ((i != nullptr) == (k != nullptr)) return fail("G33 without one lead, I or K");
  if (!on_) return fail("G33 with the spindle stopped");
  e.lead = (k ? k->value : i->value) * unit();
  return true;
}

bool Control::feed_ready() const {
  return f_given_ && per_rev_ && f_inch_ == *inch_;
}

// A block with X or Z moves in the group 1 code in force. A feed needs F and a feed type (their
// power-on state is MD20150: refused); an F given in the other unit is refused (whether a
// G700/G710 switch keeps its number or its speed is not documented); so is a cutting speed the
// spindle turns at.
bool Control::motion(const Block& b) {
  std::optional<double> x = x_, z = z_;
  if (!length(b, "X", x) || !length(b, "Z", z)) return false;
  if (!b.moves())
    return b.find("I") || b.find("K") || b.find("SF") ? fail("an arc or a thread without its end")
                                                      : true;
  if (!motion_) return fail("a move before G0, G1, G2, G3 or G33 (MD20150)");
  if (!x || !z) return fail("a move from a position the program does not state");
  const int g = *motion_;
  Event e;
  e.x = *x, e.z = *z;
  e.motion = g == 0    ? MotionKind::kRapid
             : g == 1  ? MotionKind::kFeed
             : g == 33 ? MotionKind::kThread
                       : MotionKind::kArc;
  if (b.find("SF") && g != 33) return fail("SF= outside G33");
  if ((g == 1 || g == 2 || g == 3) && !feed_ready())
    return fail("a feed move without an F in its unit and a feed type (alarm 10860)");
  if (g != 0 && on_ && css_.value_or(false) && css_known_ && css_inch_ != *inch_)
    return fail("a cutting speed given in the other unit");
  // Constant cutting speed before any LIMS: the limit is setting datum SD43230.
  if (on_ && css_.value_or(false) && !lims_)
    return fail("constant cutting speed without LIMS (the limit is SD43230)");
  if (e.motion == MotionKind::kArc && !arc(b, e)) return false;
  if (e.motion == MotionKind::kThread && !thread(b, e)) return false;
  if (e.motion != MotionKind::kArc && e.motion != MotionKind::kThread &&
      (b.find("I") || b.find("K")))
    return fail("I or K outside G2, G3, G33");
  x_ = x, z_ = z;
  push(e);
  return true;
}

// The words the reader knows; any other is refused, not ignored.
bool known(const Word& w) {
  static const char* const kNames[] = {"G", "X", "Z",    "I",  "K",      "F",      "S",     "M",
                                       "T", "D", "LIMS", "SF", "DIAMON", "DIAMOF", "DIAM90"};
  for (const char* n : kNames)
    if (w.name == n) return true;
  return false;
}

// Whether an M code in a block that moves acts before, during or after the move is machine
// data (MD22200 AUXFU_M_SYNC_TYPE): refused.
bool Control::block(const Block& b, int line, std::string_view text) {
  line_ = line, text_ = std::string(text);
  if (b.words.empty()) return true;
  for (const Word& w : b.words)
    if (!known(w)) return fail("address " + w.name + " is not read by the oracle");
  if (!modes(b)) return false;
  if (b.has_g(4)) return dwell(b);
  if (b.moves() && b.find("M")) return fail("an M code in a block that moves (MD22200)");
  if (!words(b)) return false;
  return motion(b);
}

}  // namespace

}  // namespace oracle::sinumerik_detail

namespace oracle {

ControlRun sinumerik_events(std::string_view program, bool block_delete) {
  using sinumerik_detail::Block;
  sinumerik_detail::Control c;
  read_program_lines<sinumerik_detail::Block>(
      program, block_delete, c,
      [](std::string_view text, sinumerik_detail::Block& b) {
        return sinumerik_detail::parse(text, b);
      },
      [](int, std::string_view) { return false; });
  return std::move(c.run);
}

}  // namespace oracle

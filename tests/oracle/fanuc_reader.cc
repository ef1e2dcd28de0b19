// The Fanuc/Haas reader (fanuc_reader.h). Sources, cited at each meaning:
//   [0i-T]  Fanuc Series 0i-TC/0i-TF Operator's Manual (lathe system, G-code system A), by the
//           name of its section; not in ../shared/reference/ (no public copy found there).
//   [ctl]   ../shared/reference/controllers.md, "Fanuc (system A lathe)" and "Haas lathe".
//   [Haas]  Haas Lathe Operator's Manual, G-code and M-code chapters, by code.
//   [cl]    docs/cl-meaning.md (what the oracle compares; the inch least increments).
//   NCT's sources ([99M], [seed 002], [ISO]) are named at the head of nct_thread.cc.
// Where a meaning is a parameter or a setting of the control (a number without a decimal point,
// the power-on modes), the reader refuses the program rather than guess.
#include <algorithm>
#include <cctype>
#include <cmath>
#include <cstdlib>

#include "fanuc_reader_impl.h"
#include "program_lines.h"

namespace oracle::fanuc_detail {

namespace {

constexpr double kMPerFoot = 0.3048;

// [0i-T] "Program configuration": a block is words, each an address letter and a number; "%"
// starts and ends the program, "O" numbers it, "( … )" is a comment, "/" first in a block is
// optional block skip (block delete). "N" is the sequence number.
std::string parse(std::string_view line, Block& b) {
  size_t i = 0;
  auto skip_space = [&] {
    while (i < line.size() && (line[i] == ' ' || line[i] == '\r' || line[i] == '\t')) ++i;
  };
  skip_space();
  if (i < line.size() && line[i] == '/') b.optional = true, ++i;
  while (skip_space(), i < line.size()) {
    const char c = line[i];
    if (c == '%') return b.words.empty() && !b.optional ? "" : "% inside a block";
    if (c == '(') {
      const size_t close = line.find(')', i);
      if (close == std::string_view::npos) return "a comment without its ')'";
      i = close + 1;
      continue;
    }
    if (!std::isupper(static_cast<unsigned char>(c))) return std::string("'") + c + "'";
    size_t j = ++i;
    if (j < line.size() && (line[j] == '-' || line[j] == '+')) ++j;
    while (j < line.size() && (std::isdigit(static_cast<unsigned char>(line[j])) || line[j] == '.'))
      ++j;
    const std::string number(line.substr(i, j - i));
    if (number.empty() || number == "-" || number == "+")
      return std::string("address ") + c + " without a number";
    Word w{c, std::strtod(number.c_str(), nullptr), number.find('.') != std::string::npos};
    if (c != 'N' && c != 'O') b.words.push_back(w);
    i = j;
  }
  return "";
}

// The words the reader knows; any other is refused, not ignored. Q (a start angle, G76's cut
// depths) only in a thread's or a threading cycle's block, D and A only in Haas's G76. NCT: E
// and Q only in G33's blocks [seed 002]; U, W and P are not read (an NCT lathe's incremental
// axes and a dwell by P are not in the NCT sources found).
bool known(char letter, const Block& b, bool cycle, Dialect d) {
  static constexpr std::string_view kLetters = "GXZUWIKRFSTMP";
  if (d == Dialect::kNct)
    return letter == 'E' || letter == 'Q'
               ? cycle
               : std::string_view("GXZIKRFSTM").find(letter) != std::string_view::npos;
  if (letter == 'Q') return cycle;
  if (letter == 'D' || letter == 'A') return d == Dialect::kHaas && b.has_g(76);
  return kLetters.find(letter) != std::string_view::npos;
}

}  // namespace

Modal Control::modal() const {
  Modal m;
  // [0i-T] "Inch/metric conversion": F, positions and G96's S are read in the unit in force; a
  // number already given is kept and read in the new unit [cl, "How the oracle reads rs274"].
  m.feed_given = f_given_;
  m.feed = f_ * unit();
  m.feed_mode = per_rev_.value_or(false) ? FeedMode::kPerRev : FeedMode::kPerMinute;
  m.spindle.on = on_;
  m.spindle.dir = ccw_ ? SpindleDir::kCcw : SpindleDir::kCw;
  m.spindle.css = css_;
  // An S given in the other mode (G96's surface speed under G97): the control turns at a speed
  // the program does not say; -1 so that it differs.
  m.spindle.speed = s_css_ != css_ ? -1 : css_ && *inch_ ? s_ * kMPerFoot : s_;
  m.spindle.limit = css_ ? clamp_ : 0;
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

// X, Z (absolute) or U, W (incremental): X and U are diameters [0i-T] "Diameter and radius
// programming". A number without a decimal point is read in the least input increment or in
// whole units by parameter 3401#0 (DPI) [0i-T] "Decimal point programming", and by setting 77
// for F on Haas [Haas] "Setting 77": refused.
bool Control::length(const Block& b, char letter, std::optional<double>& mm) {
  const char inc = letter == 'X' ? 'U' : 'W';
  const Word *a = b.find(letter), *r = b.find(inc);
  if (!a && !r) return true;
  if (a && r) return fail(std::string(1, letter) + " and " + inc + " in one block");
  const Word& w = a ? *a : *r;
  // NCT: "X325 means e.g. 325 mm" [99M] "Specification and Value Range of Coordinate Data".
  if (!w.point && d_ != Dialect::kNct)
    return fail(std::string(1, w.letter) + " without a decimal point");
  const double v = w.value * unit() / (letter == 'X' ? 2 : 1);
  if (a) return mm = v, true;
  if (!mm) return fail(std::string(1, inc) + " from a position the program does not know");
  return mm = *mm + v, true;
}

// A G code of the block: its modal effect, false when the reader does not know it. Group 06
// G20/G21 [0i-T] "Inch/metric conversion"; group 02 G96/G97 [0i-T] "Constant surface speed
// control"; group 05 G98/G99 [0i-T] "Feed per minute, feed per revolution"; group 01 G0, G1,
// G2, G3, G32, G92 [0i-T] "Positioning", "Linear interpolation", "Circular interpolation",
// "Threading", "Single repetitive cycle" [ctl] "G32", "G92"; G76 one-shot (group 00) [ctl] "G76
// two-block". G18 (ZX plane), G40 (no tool-nose compensation) and G80 (no canned cycle) are the
// program's only state besides; Haas G187 sets the smoothness of the path, not the path [Haas]
// "G187". NCT: G94/G95 the feed modes, G33 the thread (not G32, G92), G92 S the CSS clamp (not
// G50), G90 absolute data (nct_thread.cc's sources).
bool Control::code(int g) {
  const bool nct = d_ == Dialect::kNct;
  const int per_minute = nct ? 94 : 98;
  if (g == 20 || g == 21)
    inch_ = g == 20;
  else if (g == 96 || g == 97)
    css_ = g == 96;
  else if (g == per_minute || g == per_minute + 1)
    per_rev_ = g == per_minute + 1;
  else if (g == 0 || g == 1 || g == 2 || g == 3 || g == (nct ? 33 : 32) || (!nct && g == 92))
    motion_ = g;
  else if (nct)
    return g == 4 || g == 18 || g == 40 || g == 90 || g == 92;
  else
    return g == 4 || g == 18 || g == 28 || g == 40 || g == 50 || g == 76 || g == 80 ||
           (g == 187 && d_ == Dialect::kHaas);
  return true;
}

bool Control::modes(const Block& b) {
  for (const Word& w : b.words) {
    if (w.letter != 'G') continue;
    const int g = static_cast<int>(w.value);
    if (g != w.value || !code(g))
      return fail("G" + (g != w.value ? std::to_string(w.value) : std::to_string(g)) +
                  " is not read by the oracle");
  }
  for (const Word& w : b.words)
    if (w.letter != 'G' && !inch_)
      return fail("a block before G20 or G21 (the power-on unit is a parameter)");
  return true;
}

// S: with G50 the highest speed of constant surface speed [0i-T] "Constant surface speed
// control" ("G50 S_: clamp of the maximum spindle speed"), else the speed in the mode of the
// block (rev/min under G97, m/min or ft/min under G96). T: tool and offset, the first two digits
// and the last two of T□□○○ [0i-T] "Tool function (T function)"; a turret lathe's tool change
// does not stop the spindle. Haas reads T the same way [Haas] "Tool Functions". NCT: G92 S the
// clamp [99M] "Constant Surface Speed Clamp (G92)"; T as Fanuc's (an assumption: the NCT lathe
// manual's T function was not found, docs/cl-meaning.md).
bool Control::spindle_and_tool(const Block& b) {
  const std::string clamp = "G" + std::to_string(clamp_code());
  if (const Word* s = b.find('S')) {
    if (b.has_g(clamp_code()))
      clamp_ = s->value;
    else
      s_ = s->value, s_css_ = css_;
  } else if (b.has_g(clamp_code())) {
    return fail(clamp + " without S (a coordinate system setting is not read by the oracle)");
  }
  if (const Word* t = b.find('T')) {
    const int v = static_cast<int>(t->value);
    tool_ = v / 100, offset_ = v % 100;
  }
  for (const Word& w : b.words)
    if (w.letter == 'M' && !mcode(static_cast<int>(w.value))) return false;
  return true;
}

// [0i-T] "Miscellaneous function": M0, M1, M2, M30 are the control's; M3/M4/M5 spindle
// clockwise, counter-clockwise, stop and M8/M9 (M7 mist) coolant are the builder's, as on every
// Fanuc and Haas lathe ([Haas] "M03/M04/M05", "M08/M09"; the machines' files say the same).
bool Control::mcode(int m) {
  if (spindle_coolant_m(m, on_, ccw_, coolant_)) return true;
  if (m == 30 || m == 2)
    ended_ = true;
  else if (m != 0 && m != 1)
    return fail("M" + std::to_string(m) + " is not read by the oracle");
  return true;
}

// G4: Fanuc X or U in seconds, P in milliseconds without a decimal point [0i-T] "Dwell";
// (in G99 a dwell in revolutions is parameter 3405#1, DWL, off by default). Haas: P only, in
// seconds with a decimal point, in milliseconds without [Haas] "G04 Dwell".
bool Control::dwell(const Block& b) {
  Event e;
  e.kind = Event::Kind::kDwell;
  const Word* p = b.find('P');
  const Word* x = d_ == Dialect::kHaas ? nullptr : b.find('X');
  if (!x && d_ == Dialect::kFanuc) x = b.find('U');
  if (d_ == Dialect::kHaas && (b.find('X') || b.find('U')))
    return fail("Haas G04 takes the time in P, not X or U");
  if ((p != nullptr) == (x != nullptr)) return fail("G04 needs one time word");
  if (x && !x->point) return fail("G04 X without a decimal point");
  if (p && p->point && d_ == Dialect::kFanuc) return fail("G04 P with a decimal point");
  e.seconds = x ? x->value : p->point ? p->value : p->value / 1000;
  push(e);
  return true;
}

// G28: the reference return, through the intermediate point the axis words give; U0./W0. (an
// incremental 0) is the point the axis is at [0i-T] "Reference position return"; G28 alone moves
// no axis on Fanuc, every axis on Haas [Haas] "G28 Return to Machine Zero". Consecutive G28
// blocks, each of another axis, are one return (the machine's home, GOHOME); the axes it returns
// are where the program no longer knows. G28 is one-shot: the motion code in force stays.
bool Control::home(const Block& b) {
  const Word *u = b.find('U'), *w = b.find('W');
  if (b.find('X') || b.find('Z') || (u && u->value != 0) || (w && w->value != 0))
    return fail("G28 through an intermediate point is not read by the oracle");
  const bool all = !u && !w && d_ == Dialect::kHaas;
  const bool x = u || all, z = w || all;
  if (!x && !z) return true;
  if ((x && home_x_) || (z && home_z_) || (!home_x_ && !home_z_)) {
    home_x_ = home_z_ = false;
    push(Event{});
  }
  run.events.back().home |= (x ? kHomeX : 0) | (z ? kHomeZ : 0);
  if (x) x_.reset(), home_x_ = true;
  if (z) z_.reset(), home_z_ = true;
  return true;
}

// [0i-T] "Circular interpolation": G2 clockwise, G3 counter-clockwise, seen from the positive
// side of the axis normal to the plane (Y for G18, so in (Z, X) from +Z toward +X for G3); I
// and K the centre from the start point, incremental, I a radius also in diameter programming;
// or R the radius of an arc of at most 180 degrees (the lathe system has no R for more).
bool Control::arc(const Block& b, Event& e) {
  e.rotation = *motion_ == 3 ? 1 : -1;
  const Word *i = b.find('I'), *k = b.find('K'), *r = b.find('R');
  for (const Word* w : {i, k, r})
    if (w && !w->point && d_ != Dialect::kNct)
      return fail(std::string(1, w->letter) + " without a decimal point");
  if (r && (i || k)) return fail("R with I or K");
  if (!r) {
    e.cx = *x_ + (i ? i->value * unit() : 0);
    e.cz = *z_ + (k ? k->value * unit() : 0);
    return true;
  }
  const double rad = r->value * unit(), dx = e.x - *x_, dz = e.z - *z_;
  const double d = std::hypot(dx, dz);
  if (rad <= 0 || d == 0 || d / 2 > rad + 1e-9) return fail("G2/G3 R that no arc has");
  // The centre on the chord's bisector, on the left of the chord for G3, the right for G2.
  const double h = std::sqrt(std::max(0.0, rad * rad - d * d / 4));
  e.cz = (*z_ + e.z) / 2 - e.rotation * h * dx / d;
  e.cx = (*x_ + e.x) / 2 + e.rotation * h * dz / d;
  return true;
}

// A block with X, Z, U or W moves in the group 01 code in force: G0 a rapid, G1 a feed at F,
// G2/G3 an arc at F, G32 a thread cut at the lead F, a length per revolution in either feed mode
// [ctl] "G32 X/Z F<lead>: one synchronized move". The feed mode's power-on state is parameter
// 3402#4 (FPM), so a feed before G98/G99 is refused; G32 with the spindle stopped waits for the
// one-revolution signal for ever [0i-T] "Threading".
bool Control::motion(const Block& b) {
  std::optional<double> x = x_, z = z_;
  if (!length(b, 'X', x) || !length(b, 'Z', z)) return false;
  const bool moves = b.find('X') || b.find('U') || b.find('Z') || b.find('W');
  if (!moves)
    return b.find('I') || b.find('K') || b.find('R') ? fail("an arc without its end") : true;
  if (!motion_) return fail("a move before any G0, G1, G2, G3, G32 (parameter 3402#0)");
  if (!x || !z) return fail("a move from a reference position the program does not state");
  if ((*motion_ == 2 || *motion_ == 3) && (!x_ || !z_))
    return fail("an arc from a reference position the program does not state");
  Event e;
  e.x = *x, e.z = *z;
  const int g = *motion_;
  e.motion = g == 0               ? MotionKind::kRapid
             : g == 1             ? MotionKind::kFeed
             : g == 32 || g == 33 ? MotionKind::kThread
                                  : MotionKind::kArc;
  if ((g == 32 || g == 33) && !on_)
    return fail("G" + std::to_string(g) + " with the spindle stopped");
  if (g == 32) e.lead = f_ * unit();
  if (g == 33 && !nct_lead(b, e)) return false;
  // G32 Q: the start angle in 0.001 degree, a decimal point not allowed [0i-T] "Threading".
  if (const Word* q = b.find('Q'); q && q->point && g == 32) return fail("Q with a decimal point");
  if ((g == 1 || g == 2 || g == 3) && (!f_given_ || !per_rev_))
    return fail(d_ == Dialect::kNct ? "a feed move before F, G94 or G95"
                                    : "a feed move before F, G98 or G99");
  if ((g == 1 || g == 2 || g == 3) && f_is_lead_)
    return fail("a feed move after G33's F without its own F (not documented for NCT)");
  if (e.motion == MotionKind::kArc && !arc(b, e)) return false;
  x_ = x, z_ = z;
  push(e);
  return true;
}

bool Control::block(const Block& b, int line, std::string_view text) {
  line_ = line, text_ = std::string(text);
  if (b.words.empty()) return true;
  if (!modes(b)) return false;
  const bool cycle = b.has_g(76) || motion_ == 92 || motion_ == 32 || motion_ == 33;
  for (const Word& w : b.words)
    if (!known(w.letter, b, cycle, d_))
      return fail(std::string("address ") + w.letter + " is not read");
  const bool moves = b.find('X') || b.find('U') || b.find('Z') || b.find('W');
  if (motion_ != 33 || !moves) thread_chain_ = false;
  if (const Word* f = b.find('F')) {
    if (!f->point) return fail("F without a decimal point");
    if (d_ == Dialect::kNct && !nct_feed(*f)) return false;
    if (d_ != Dialect::kNct) f_ = f->value, f_given_ = true;
  }
  // Whether an M code in a block that moves acts before or after the move is the builder's
  // [0i-T] "Miscellaneous function": refused.
  if (moves && b.find('M') && !b.has_g(4)) return fail("an M code in a block that moves");
  if (!spindle_and_tool(b)) return false;
  if (b.has_g(28)) return home(b);
  home_x_ = home_z_ = false;
  if (b.has_g(4)) return dwell(b);
  // G50 (NCT: G92) with an axis sets the coordinate system [0i-T] "Coordinate system setting".
  if (b.has_g(clamp_code()))
    return moves ? fail("a coordinate system setting is not read by the oracle") : true;
  if (b.has_g(76)) return g76(b);
  if (motion_ == 92 && moves) return g92(b);  // a block without them cuts no pass
  return motion(b);
}

}  // namespace oracle::fanuc_detail

namespace oracle {

ControlRun fanuc_events(std::string_view program, Dialect dialect, bool block_delete) {
  using fanuc_detail::Block;
  fanuc_detail::Control c(dialect);
  read_program_lines<fanuc_detail::Block>(
      program, block_delete, c,
      [](std::string_view text, fanuc_detail::Block& b) { return fanuc_detail::parse(text, b); },
      [](int, std::string_view) { return false; });
  return std::move(c.run);
}

}  // namespace oracle

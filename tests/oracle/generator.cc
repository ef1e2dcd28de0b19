#include "generator.h"

#include <algorithm>
#include <cmath>
#include <cstdio>
#include <random>
#include <vector>

namespace oracle {

namespace {

constexpr double kPi = 3.14159265358979323846;

class Gen {
 public:
  Gen(uint32_t seed, bool nct) : rng_(seed), nct_(nct) {}
  std::string program();

 private:
  int irange(int lo, int hi) { return std::uniform_int_distribution<int>(lo, hi)(rng_); }
  bool chance(double p) { return std::uniform_real_distribution<double>(0, 1)(rng_) < p; }
  double uniform(double lo, double hi) {
    return std::uniform_real_distribution<double>(lo, hi)(rng_);
  }
  double grid(double lo, double hi);
  double s() const { return inch_ ? 1 / 25.4 : 1; }  // CL units per mm
  void line(const std::string& l) { out_ += l + "\n"; }
  std::string point(double x, double z) const;
  void target(double& x, double& z);
  void moved(bool arc);
  bool can_feed() const;

  bool item(bool in_range);
  bool move();
  bool arc();
  bool fedrat();
  bool spindl(bool first);
  bool loadtl();
  bool units_switch();
  bool delay();
  bool gohome();
  bool opskip();
  bool thread();
  void couple(double p, bool modal);
  bool coolant();
  bool pitch();

  std::mt19937 rng_;
  bool nct_;
  std::string out_;
  bool inch_ = false;
  double x_ = 0, z_ = 0;  // CL units
  bool on_grid_ = false;  // the position is one the CL wrote in the current unit
  bool feed_given_ = false, per_rev_ = false;
  bool spindle_on_ = false, css_ = false, speed_given_ = false;
  bool pitch_given_ = false;
  double rpm_ = 0, pitch_mm_ = 0;  // a thread stays under the machine's 5000 mm/min
  bool in_range_ = false, range_moved_ = false;
  bool arc_blocked_ = true;  // no arc until a straight move has put the tool where the CL says
};

// A number with up to 4 decimals, as written: "12.34", "-5", "0.0125".
std::string num(double v) {
  char buf[64];
  std::snprintf(buf, sizeof buf, "%.4f", std::round(v * 1e4) / 1e4 + 0.0);
  std::string t = buf;
  while (t.back() == '0') t.pop_back();
  if (t.back() == '.') t.pop_back();
  return t == "-0" ? "0" : t;
}

// A value in [lo, hi] with 0 to 4 decimals: on the 1e-4 grid.
double Gen::grid(double lo, double hi) {
  const double step = std::pow(10.0, -irange(0, 4));
  const double v = std::round(uniform(lo, hi) / step) * step;
  return std::round(std::clamp(v, lo, hi) * 1e4) / 1e4;
}

std::string Gen::point(double x, double z) const {
  return num(x) + ",0," + num(z);
}

// A new point on the grid, at least 0.05 mm from the tool; along one axis now and then.
void Gen::target(double& x, double& z) {
  do {
    x = grid(2 * s(), 40 * s());
    z = grid(-60 * s(), 5 * s());
    if (on_grid_ && chance(0.3)) {
      if (chance(0.5))
        x = x_;
      else
        z = z_;
    }
  } while (std::hypot(x - x_, z - z_) < 0.05 * s());
}

void Gen::moved(bool arc) {
  if (in_range_) range_moved_ = true;
  if (!in_range_ && !arc) arc_blocked_ = false;
}

// Whether a feed move can be cut: a feed given, and per revolution only with the spindle turning.
bool Gen::can_feed() const {
  return feed_given_ && (!per_rev_ || spindle_on_);
}

bool Gen::move() {
  if (!can_feed() || chance(0.3)) line("RAPID");
  double x, z;
  target(x, z);
  if (on_grid_ && chance(0.25)) {
    const double dx = std::round((x - x_) * 1e4) / 1e4, dz = std::round((z - z_) * 1e4) / 1e4;
    line(dx == 0 && chance(0.5) ? "GODLTA/" + num(dz) : "GODLTA/" + point(dx, dz));
    x = x_ + dx, z = z_ + dz;
  } else {
    line("GOTO/" + point(x, z));
    on_grid_ = true;
  }
  x_ = x, z_ = z;
  moved(false);
  return true;
}

// An arc from the tool around a centre on the grid, 10 to 300 degrees either way.
bool Gen::arc() {
  if (!can_feed() || !on_grid_ || arc_blocked_) return false;
  for (int attempt = 0; attempt < 10; ++attempt) {
    const double r0 = uniform(0.5, 8) * s(), phi = uniform(0, 2 * kPi);
    const double cx = std::round((x_ + r0 * std::sin(phi)) * 1e4) / 1e4;
    const double cz = std::round((z_ + r0 * std::cos(phi)) * 1e4) / 1e4;
    const double r = std::hypot(x_ - cx, z_ - cz);
    if (cx - r < 0.5 * s() || r < 0.2 * s()) continue;
    const int sense = chance(0.5) ? 1 : -1;  // +1: from +Z toward +X, axis +Y
    const double end = std::atan2(x_ - cx, z_ - cz) + sense * uniform(10, 300) * kPi / 180;
    const double ex = std::round((cx + r * std::sin(end)) * 1e4) / 1e4;
    const double ez = std::round((cz + r * std::cos(end)) * 1e4) / 1e4;
    if (std::hypot(ex - x_, ez - z_) < 0.05 * s()) continue;
    char radius[32];
    std::snprintf(radius, sizeof radius, "%.6f", r);
    line("CIRCLE/" + point(cx, cz) + ",0," + std::to_string(sense) + ",0," + radius);
    if (spindle_on_ && chance(0.1)) fedrat();
    line("GOTO/" + point(ex, ez));
    x_ = ex, z_ = ez;
    moved(true);
    return true;
  }
  return false;
}

bool Gen::opskip() {
  if (in_range_) return false;
  line("OPSKIP/ON");
  in_range_ = true, range_moved_ = false;
  for (int n = irange(1, 4); n > 0;)
    if (item(true)) --n;
  line("OPSKIP/OFF");
  in_range_ = false;
  if (range_moved_) arc_blocked_ = true;
  return true;
}

// One statement (or a few that belong together) of the kind drawn by weight.
bool Gen::item(bool in_range) {
  static const std::vector<int> kWeights = {30, 12, 8, 10, 4, 5, 5, 3, 6, 4, 4, 2};
  const int kind = std::discrete_distribution<int>(kWeights.begin(), kWeights.end())(rng_);
  const bool anywhere = kind <= 3 || kind == 6 || kind == 7 || kind == 10;
  if (in_range && !anywhere) return false;
  switch (kind) {
    case 0:
      return move();
    case 1:
      return arc();
    case 2:
      return fedrat();
    case 3:
      return spindl(false);
    case 4:
      return loadtl();
    case 5:
      return units_switch();
    case 6:
      return delay();
    case 7:
      return gohome();
    case 8:
      return opskip();
    case 9:
      return thread();
    case 10:
      return coolant();
    default:
      return pitch();
  }
}

// FEDRAT with a mode word (in the file's unit or the other), or without one (the current mode,
// in CL units); the word first now and then.
bool Gen::fedrat() {
  const bool with_mode = !feed_given_ || chance(0.6);
  bool inch = inch_;
  if (with_mode) {
    per_rev_ = chance(0.6);
    if (chance(0.15)) inch = !inch;
  }
  const double v = per_rev_ ? (inch ? grid(0.002, 0.016) : grid(0.05, 0.4))
                            : (inch ? grid(1.5, 60) : grid(40, 1500));
  if (!(v > 0)) return false;
  std::string text = num(v);
  if (with_mode) {
    const char* word = per_rev_ ? (inch ? "IPR" : "MMPR") : (inch ? "IPM" : "MMPM");
    text = chance(0.2) ? std::string(word) + "," + text : text + "," + word;
  }
  line("FEDRAT/" + text);
  feed_given_ = true;
  return true;
}

bool Gen::spindl(bool first) {
  const std::string dir = first || chance(0.6) ? (chance(0.7) ? ",CLW" : ",CCLW") : std::string();
  const int kind = first ? irange(0, 1) : irange(0, 3);
  if (kind == 0) {
    const std::string n = std::to_string(irange(10, 300) * 10);
    line(chance(0.2) ? "SPINDL/RPM," + n + dir : "SPINDL/" + n + ",RPM" + dir);
    css_ = false;
    rpm_ = std::stod(n);
  } else if (kind == 1) {
    const int v = inch_ ? irange(150, 1000) : irange(50, 300);
    const std::string limit = chance(0.6) ? ",MAXRPM," + std::to_string(irange(8, 30) * 100) : "";
    line("SPINDL/" + std::to_string(v) + (inch_ ? ",SFM" : ",SMM") + limit + dir);
    css_ = true;
  } else if (kind == 2) {
    line("SPINDL/OFF");
    spindle_on_ = false;
    return true;
  } else {
    if (!speed_given_) return false;
    line("SPINDL/ON");
  }
  spindle_on_ = speed_given_ = true;
  return true;
}

bool Gen::loadtl() {
  const std::string tool = std::to_string(irange(1, 20));
  line(chance(0.4) ? "LOADTL/" + tool + ",ADJUST," + std::to_string(irange(1, 99))
                   : "LOADTL/" + tool);
  return true;
}

bool Gen::units_switch() {
  if (chance(0.1)) {  // the unit in force, said again
    line(inch_ ? "UNITS/INCHES" : "UNITS/MM");
    return true;
  }
  inch_ = !inch_;
  line(inch_ ? "UNITS/INCHES" : "UNITS/MM");
  const double f = inch_ ? 1 / 25.4 : 25.4;
  x_ *= f, z_ *= f;
  on_grid_ = false;
  return true;
}

bool Gen::delay() {
  if (spindle_on_ && !css_ && chance(0.4)) {
    const std::string n = std::to_string(irange(1, 10));
    line(chance(0.25) ? "DELAY/" + n + ",REV" : "DELAY/REV," + n);
  } else {
    line("DELAY/" + num(irange(1, 30) / 10.0) + (chance(0.15) ? ",SEC" : ""));
  }
  return true;
}

// GOHOME to a point, after RAPID now and then, followed now and then by a feed move (which the
// RAPID must not reach).
bool Gen::gohome() {
  if (chance(0.5)) line("RAPID");
  double x, z;
  target(x, z);
  line("GOHOME/" + point(x, z));
  x_ = x, z_ = z, on_grid_ = true;
  moved(false);
  if (can_feed() && chance(0.6)) {
    target(x, z);
    line("GOTO/" + point(x, z));
    x_ = x, z_ = z;
  }
  return true;
}

// THREAD/TURN (its own pitch, or PITCH's), the start by an ordinary move, the cut, a retract.
bool Gen::thread() {
  if (!spindle_on_ || css_ || in_range_) return false;
  static const double kMm[] = {0.5, 0.75, 1, 1.25, 1.5, 2};
  static const double kIn[] = {0.04, 0.05, 0.0625, 0.1};
  const double p = inch_ ? kIn[irange(0, 3)] : kMm[irange(0, 5)];
  const bool modal = pitch_given_ && chance(0.5);
  if ((modal ? pitch_mm_ : p * (inch_ ? 25.4 : 1)) * rpm_ > 4500) return false;
  if (nct_ && chance(0.4)) {
    couple(p, modal);
    return true;
  }
  line(modal ? "THREAD/TURN" : "THREAD/TURN," + num(p));
  double xs, zs;
  do {
    xs = grid(3 * s(), 30 * s()), zs = grid(-10 * s(), 5 * s());
  } while (std::hypot(xs - x_, zs - z_) < 0.05 * s());
  const double ze = std::round((zs - grid(5 * s(), 30 * s())) * 1e4) / 1e4;
  if (!can_feed() || chance(0.6)) line("RAPID");
  line("GOTO/" + point(xs, zs));
  line("GOTO/" + point(xs, ze));
  x_ = std::round((xs + grid(0.5 * s(), 2 * s())) * 1e4) / 1e4, z_ = ze, on_grid_ = true;
  line("RAPID");
  line("GOTO/" + point(x_, z_));
  moved(false);
  return true;
}

// COUPLE/ON (its own pitch in the file's unit, or PITCH's) after an ordinary move to the start,
// the cut and now and then a pull-out outward (each a synchronized move, one continuous thread),
// COUPLE/OFF, a retract.
void Gen::couple(double p, bool modal) {
  double xs, zs;
  do {
    xs = grid(3 * s(), 30 * s()), zs = grid(-10 * s(), 5 * s());
  } while (std::hypot(xs - x_, zs - z_) < 0.05 * s());
  if (!can_feed() || chance(0.6)) line("RAPID");
  line("GOTO/" + point(xs, zs));
  line(modal ? "COUPLE/ON" : std::string("COUPLE/ON,") + (inch_ ? "IPR," : "MMPR,") + num(p));
  z_ = std::round((zs - grid(5 * s(), 30 * s())) * 1e4) / 1e4, x_ = xs;
  line("GOTO/" + point(x_, z_));
  if (chance(0.6)) {
    x_ = std::round((x_ + grid(0.5 * s(), 2 * s())) * 1e4) / 1e4;
    z_ = std::round((z_ - grid(0.5 * s(), 2 * s())) * 1e4) / 1e4;
    line("GOTO/" + point(x_, z_));
  }
  line("COUPLE/OFF");
  x_ = std::round((x_ + grid(0.5 * s(), 2 * s())) * 1e4) / 1e4, on_grid_ = true;
  line("RAPID");
  line("GOTO/" + point(x_, z_));
  moved(false);
}

bool Gen::coolant() {
  static const char* kWords[] = {"ON", "FLOOD", "MIST", "OFF"};
  line(std::string("COOLNT/") + kWords[irange(0, 3)]);
  return true;
}

bool Gen::pitch() {
  static const char* kPitches[] = {"1.5,MMPR",   "2,MMPR", "0.75,MMPR", "0.05,IPR",
                                   "0.0625,IPR", "16,TPI", "11.5,TPI"};
  static const double kMm[] = {1.5, 2, 0.75, 1.27, 1.5875, 25.4 / 16, 25.4 / 11.5};
  const int i = irange(0, nct_ ? 6 : 4);
  line(std::string("PITCH/") + kPitches[i]);
  pitch_mm_ = kMm[i];
  pitch_given_ = true;
  return true;
}

std::string Gen::program() {
  if (chance(0.8)) {
    inch_ = chance(0.35);
    line(inch_ ? "UNITS/INCHES" : "UNITS/MM");
  }
  if (chance(0.15)) {
    double x, z;
    target(x, z);
    x_ = x, z_ = z;
    line("FROM/" + point(x_, z_));
    on_grid_ = true;
  }
  loadtl();
  if (chance(0.85)) spindl(true);
  if (chance(0.85)) fedrat();
  move();
  for (int n = irange(8, 40); n > 0;)
    if (item(false)) --n;
  line("FINI");
  return out_;
}

}  // namespace

std::string generate_program(uint32_t seed, bool nct) {
  return Gen(seed, nct).program();
}

}  // namespace oracle

#include "controls/linuxcnc/linuxcnc_law.h"

#include <cmath>
#include <numbers>

namespace clpost {

namespace {

// What convert_threading_cycle() works out from the words before its first pass, in the radius
// frame (I, J, K halved in G7 diameter mode).
struct Threading {
  bool boring = false;               // I > 0: an internal thread, the cuts move away from the axis
  double safe_x = 0;                 // the drive line, where the tool starts
  double start_z = 0;                // the thread start
  double full_dia_depth = 0;         // |I|: the crest (or bore) line below the drive line
  double cut_increment = 0;          // |J|
  double full_threadheight = 0;      // |K|
  double end_depth = 0;              // |I| + |K|: the full depth from the drive line
  double degression = 1;             // R, counted as 1 below 1
  double angle = 0;                  // Q in radians, its sign the cutting direction's
  double taper = 0;                  // E, its sign the cutting direction's
  bool entry = false, exit = false;  // L & 1, L & 2
  double target_z = 0;               // Z + K·tan(Q): where the unshifted passes end
};

// The cycle's setup from the block's words and the tool's start (`start`, the drive line).
Threading threading_setup(const LinuxcncG76& w, Vec2 start, bool diameter_mode) {
  double i = w.i, j = w.j, k = w.k;
  if (diameter_mode) {
    i /= 2;
    j /= 2;
    k /= 2;
  }
  Threading g;
  g.boring = i > 0;
  g.safe_x = start.x;
  g.start_z = start.z;
  g.full_dia_depth = std::fabs(i);
  g.cut_increment = std::fabs(j);
  g.full_threadheight = std::fabs(k);
  g.end_depth = std::fabs(k) + std::fabs(i);

  double angle = w.q == -1 ? 0 : w.q;
  angle *= std::numbers::pi / 180.0;
  if (w.z > start.z) angle = -angle;
  g.angle = angle;
  g.degression = w.r < 1.0 ? 1.0 : w.r;
  g.taper = w.e < 0 ? 0 : w.e;
  if (w.z > start.z) g.taper = -g.taper;
  const int flags = w.l < 0 ? 0 : w.l;
  g.entry = (flags & 1) != 0;
  g.exit = (flags & 2) != 0;
  g.target_z = w.z + std::fabs(k) * std::tan(angle);
  return g;
}

// The depths of the passes from the drive line, in the control's order: |I| + J·n^(1/R) while
// below |I| + K, then H + 1 passes at |I| + K.
std::vector<double> pass_depths(const Threading& g, int h) {
  std::vector<double> depths;
  int n = 1;
  double depth = g.full_dia_depth + g.cut_increment;  // start_depth
  // The control has no pass limit; a J tiny against K would loop for a long time: stop at a
  // count no plan can have (the comparison then reports the extra passes).
  while (depth < g.end_depth && n <= 10000) {
    depths.push_back(depth);
    depth = g.full_dia_depth + g.cut_increment * std::pow(++n, 1.0 / g.degression);
  }
  for (int s = 0; s < h + 1; ++s) depths.push_back(g.end_depth);
  return depths;
}

// One pass at `depth` from the drive line, as threading_pass() cuts it: shifted by its depth
// below the crest times tan(Q), with the entry and exit tapers L asks for.
Cut threading_pass(const Threading& g, double depth) {
  const double zoff = (depth - g.full_dia_depth) * std::tan(g.angle);
  const double x_cut = g.boring ? g.safe_x + depth : g.safe_x - depth;
  const double x_high =
      g.boring ? g.safe_x + depth - g.full_threadheight : g.safe_x - depth + g.full_threadheight;
  Cut c;
  c.depth = depth - g.full_dia_depth;
  c.from =
      (g.taper != 0 && g.entry) ? Vec2{x_high, g.start_z - zoff} : Vec2{x_cut, g.start_z - zoff};
  if (g.taper != 0 && g.exit) {
    c.to = {x_cut, g.target_z - zoff + g.taper};
    c.end = {x_high, g.target_z - zoff};
  } else {
    c.to = {x_cut, g.target_z - zoff};
    c.end = c.to;
  }
  return c;
}

}  // namespace

std::vector<Cut> expand_linuxcnc_g76(const LinuxcncG76& w, Vec2 start, bool diameter_mode,
                                     std::string* error) {
  auto refuse = [&](const char* msg) {
    if (error) *error = msg;
    return std::vector<Cut>{};
  };
  // The control's checks, in its order and words.
  if (w.i == 0) return refuse("In G76, I must not be 0");
  if (w.j <= 0) return refuse("In G76, J must be greater than 0");
  if (w.k <= w.j) return refuse("In G76, K must be greater than J");

  const Threading g = threading_setup(w, start, diameter_mode);
  std::vector<Cut> out;
  for (double depth : pass_depths(g, w.h)) out.push_back(threading_pass(g, depth));
  return out;
}

}  // namespace clpost

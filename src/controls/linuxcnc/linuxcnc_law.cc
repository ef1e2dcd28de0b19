#include "controls/linuxcnc/linuxcnc_law.h"

#include <cmath>

namespace clpost {

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

  double i = w.i, j = w.j, k = w.k;
  if (diameter_mode) {
    i /= 2;
    j /= 2;
    k /= 2;
  }
  const bool boring = i > 0;
  const double safe_x = start.x;
  const double full_dia_depth = std::fabs(i);
  const double cut_increment = std::fabs(j);
  const double full_threadheight = std::fabs(k);
  const double end_depth = std::fabs(k) + std::fabs(i);

  double angle = w.q == -1 ? 0 : w.q;
  angle *= 3.14159265358979323846 / 180.0;
  if (w.z > start.z) angle = -angle;
  const double degression = w.r < 1.0 ? 1.0 : w.r;
  double taper = w.e < 0 ? 0 : w.e;
  if (w.z > start.z) taper = -taper;
  const int flags = w.l < 0 ? 0 : w.l;
  const bool entry = (flags & 1) != 0;
  const bool exit = (flags & 2) != 0;
  const double target_z = w.z + std::fabs(k) * std::tan(angle);

  std::vector<Cut> out;
  auto pass = [&](double depth) {
    const double zoff = (depth - full_dia_depth) * std::tan(angle);
    const double x_cut = boring ? safe_x + depth : safe_x - depth;
    const double x_high =
        boring ? safe_x + depth - full_threadheight : safe_x - depth + full_threadheight;
    Cut c;
    c.depth = depth - full_dia_depth;
    c.from = (taper != 0 && entry) ? Vec2{x_high, start.z - zoff} : Vec2{x_cut, start.z - zoff};
    if (taper != 0 && exit) {
      c.to = {x_cut, target_z - zoff + taper};
      c.end = {x_high, target_z - zoff};
    } else {
      c.to = {x_cut, target_z - zoff};
      c.end = c.to;
    }
    out.push_back(c);
  };

  int n = 1;
  double depth = full_dia_depth + cut_increment;  // start_depth
  // The control has no pass limit; a J tiny against K would loop for a long time: stop at a
  // count no plan can have (the comparison then reports the extra passes).
  while (depth < end_depth && n <= 10000) {
    pass(depth);
    depth = full_dia_depth + cut_increment * std::pow(++n, 1.0 / degression);
  }
  for (int s = 0; s < w.h + 1; ++s) pass(end_depth);
  return out;
}

}  // namespace clpost

#pragma once
// NCL's cutter record as APT: NCL keeps its own cutter parameters in a 6000 record (diameter,
// corner radius, height, side angle, …), and writes them in its APT source as APT's
// CUTTER/d,r,e,f,a,b,h. The rules are NCL's APT source writer's (src/nclf/aptsrc.f, ascutr, in
// NCL's public sources): with up to four parameters d,r,h,a — e = d/2 - r and f = r when there
// is a corner radius, and a cone (0 < a < 90) or bell (-90 < a < 0) cutter's diameter measured
// where APT measures it; with five to seven, the parameters in APT's order.
#include <array>
#include <span>

namespace clpost::cldata {

std::array<double, 7> ncl_apt_cutter(std::span<const double> ncl);

}  // namespace clpost::cldata

// Pull-out and return of a multi-pass thread: threading.md section 7 (pullout.h).
#include "planner/pullout.h"

#include <fmt/format.h>

#include <algorithm>
#include <cmath>
#include <limits>
#include <string>
#include <utility>

#include "planner/multi_sites.h"
#include "support/angles.h"
#include "support/number_text.h"
#include "support/vec2_math.h"

namespace clpost {

using namespace vec2_math;
using namespace plan_report;

namespace {

// pitch/(2 tan 30): the full depth of a 60 degree thread, the default pull-out and return height.
double default_height(double pitch) {
  return pitch / (2 * std::tan(radians(30)));
}

// One way to define the pull-out, with where it was given (for the "more than one" error).
struct PulloutSource {
  std::string name;  // "the third GOTO", "ATANGL", "CHAMFR"
  Site site;
};

std::string loc_text(SourceLoc l) {
  return fmt::format("line {}, column {}", l.line, l.col);
}

bool before(SourceLoc a, SourceLoc b) {
  return a.line < b.line || (a.line == b.line && a.col < b.col);
}

// At most one of a third GOTO, ATANGL and CHAMFR: each later one is reported.
bool check_one_pullout(const MultiThreadInput& in, Reporter& r) {
  const ThreadWords& w = in.words;
  std::vector<PulloutSource> sources;
  if (w.atangl.set) sources.push_back({"ATANGL", word_site(in, w.atangl.loc)});
  if (w.chamfr.set && w.chamfr.length != 0)
    sources.push_back({"CHAMFR", word_site(in, w.chamfr.loc)});
  if (sources.size() == 2 && before(sources[1].site.loc, sources[0].site.loc))
    std::swap(sources[0], sources[1]);
  if (in.gotos.size() == 3) sources.push_back({"the third GOTO", goto_site(in, 2)});
  if (sources.size() <= 1) return true;
  for (size_t k = 1; k < sources.size(); ++k) {
    r.error(sources[k].site,
            fmt::format("{} defines a second pull-out: {} at {} already defines it; give only "
                        "one of a third GOTO, ATANGL and CHAMFR",
                        sources[k].name, sources[0].name, loc_text(sources[0].site.loc)));
  }
  if (sources.back().name == "the third GOTO") note_sequence_start(in, r);
  return false;
}

// The third GOTO P3: delta = P3 - P2, none when it repeats P2 (warned). False, reported, when it
// moves into the material.
bool third_goto_pullout(const MultiThreadInput& in, const MultiGeometry& g, Pullout& out,
                        Reporter& r) {
  const Vec2 p3 = in.gotos[2].point;
  const Vec2 d = p3 - g.p2;
  if (length(d) <= kLengthEps) {
    r.warning(goto_site(in, 2), fmt::format("the third GOTO {} repeats the thread end: no "
                                            "pull-out",
                                            pt(p3)));
  } else if (dot(d, g.out_dir) < -kLengthEps) {
    r.error(goto_site(in, 2),
            fmt::format("the chamfer end {} is {} on the material side of the thread line: "
                        "the pull-out must move out of the thread",
                        pt(p3), num_text(-dot(d, g.out_dir))));
    note_sequence_start(in, r);
    return false;
  } else {
    out.delta = d;
  }
  return true;
}

// ATANGL,alpha[,h]: h outward and h tan(alpha) along the thread. CHAMFR,L[,beta]: |L| along the
// thread and |L| tan(beta) outward; a negative L shortens every pass by |L|.
void word_pullout(const ThreadWords& w, const MultiGeometry& g, double pitch, Pullout& out) {
  if (w.atangl.set) {
    const double h = w.atangl.height > 0 ? w.atangl.height : default_height(pitch);
    out.delta = h * g.out_dir + (h * std::tan(radians(w.atangl.angle))) * g.t;
  } else if (w.chamfr.set && w.chamfr.length != 0) {
    const double l = std::fabs(w.chamfr.length);
    out.delta = l * g.t + (l * std::tan(radians(w.chamfr.angle))) * g.out_dir;
    if (w.chamfr.length < 0) out.shorten = l;
  }
}

// RETURN without a height: clear to the initial point's X (turn, taper) or Z (face). False,
// reported at RETURN, when that is not outside the thread end.
bool initial_point_height(const MultiThreadInput& in, const MultiGeometry& g, double& out,
                          Reporter& r) {
  const bool along_x = g.lead_along_z;
  const double p0 = along_x ? g.p0.x : g.p0.z;
  out = (p0 - (along_x ? g.p2.x : g.p2.z)) / (along_x ? g.out_dir.x : g.out_dir.z);
  if (out > kLengthEps) return true;
  return r.error(word_site(in, in.words.ret.loc),
                 fmt::format("RETURN without a height clears to the initial point's {} {}, "
                             "which is not outside the thread end {}; give RETURN,h",
                             along_x ? "X" : "Z", num_text(p0), pt(g.p2)));
}

// RETURN[,h]: its height, raised (warned) to the pull-out end `top` when that is higher.
bool return_height(const MultiThreadInput& in, const MultiGeometry& g, double top, double& out,
                   Reporter& r) {
  const ReturnParam& ret = in.words.ret;
  if (ret.height_given) {
    out = ret.height;
  } else if (!initial_point_height(in, g, out, r)) {
    return false;
  }
  if (top > out + kLengthEps) {
    r.warning(word_site(in, ret.loc),
              fmt::format("the return height {} is below the pull-out end ({} above the "
                          "thread line): the tool clears to {}",
                          num_text(out), num_text(top), num_text(top)));
    out = top;
  }
  return true;
}

}  // namespace

bool make_pullout(const MultiThreadInput& in, const MultiGeometry& g, double pitch, Pullout& out,
                  Reporter& r) {
  if (!check_one_pullout(in, r)) return false;
  Pullout p;
  if (in.gotos.size() == 3) {
    if (!third_goto_pullout(in, g, p, r)) return false;
  } else {
    word_pullout(in.words, g, pitch, p);
  }
  if (p.delta) {
    const double chamfer_angle = degrees(std::atan2(dot(*p.delta, g.out_dir), dot(*p.delta, g.t)));
    p.linear = chamfer_angle < 30 - kAngleEps || chamfer_angle > 60 + kAngleEps;
  }
  out = p;
  return true;
}

bool clearance_height(const MultiThreadInput& in, const MultiGeometry& g, double pitch,
                      const Pullout& pullout, double shallowest, double& out, Reporter& r) {
  const std::optional<Vec2>& delta = pullout.delta;
  // The highest pull-out end over all passes (the shallowest pass), above the thread line.
  const double top =
      delta ? dot(*delta, g.out_dir) - shallowest : -std::numeric_limits<double>::infinity();
  if (in.words.ret.set) return return_height(in, g, top, out, r);
  out = std::max(default_height(pitch), top);
  return true;
}

}  // namespace clpost

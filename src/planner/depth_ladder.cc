#include "planner/depth_ladder.h"

#include <fmt/format.h>

#include <algorithm>
#include <cmath>
#include <string>
#include <utility>

#include "support/number_text.h"

namespace clpost {

std::vector<double> option_ladder_by_count(int option, double roughing, int count) {
  std::vector<double> d;
  if (count < 1) return d;
  d.reserve(static_cast<size_t>(count));
  const double c = count;
  for (int k = 1; k <= count; ++k) {
    const double i = k;
    if (option == 0) {
      d.push_back(roughing * i * (2 * c - i + 1) / (c * (c + 1)));
    } else if (option == 1 || option == 2) {
      d.push_back(roughing * std::sqrt(i / c));
    } else {
      d.push_back(roughing * i / c);
    }
  }
  d.back() = roughing;
  return d;
}

double option_count_for_first_step(int option, double roughing, double first_step) {
  const double R = roughing;
  const double s = first_step;
  double c = 1;
  if (option == 0) {
    c = std::max(1.0, std::ceil(2 * R / s - 1));
    // The last step of c passes is (2R - s*c)/c.
    if (c > 1 && (2 * R - s * c) / c < kRemainderTolerance) c -= 1;
  } else if (option == 1 || option == 2) {
    c = std::max(1.0, std::ceil((R / s) * (R / s)));
    if (c > 1 && R - s * std::sqrt(c - 1) < kRemainderTolerance) c -= 1;
  } else {
    c = std::max(1.0, std::ceil(R / s));
    if (c > 1 && R - s * (c - 1) < kRemainderTolerance) c -= 1;
  }
  return c;
}

std::vector<double> option_ladder_by_first_step(int option, double roughing, double first_step,
                                                int count) {
  std::vector<double> d;
  if (count < 1) return d;
  d.reserve(static_cast<size_t>(count));
  const double R = roughing;
  const double s = first_step;
  const double c = count;
  if (option == 0) {
    const double delta = count > 1 ? 2 * (s * c - R) / (c * (c - 1)) : 0;
    double sum = 0;
    for (int k = 1; k <= count; ++k) {
      sum += s - (k - 1) * delta;
      d.push_back(std::min(R, sum));
    }
  } else {
    for (int k = 1; k <= count; ++k) {
      const double v = (option == 1 || option == 2) ? s * std::sqrt(double(k)) : s * k;
      d.push_back(std::min(R, v));
    }
  }
  d.back() = R;
  return d;
}

namespace {

// "CUTS 4 x STEP 0.5", "CUTS 4 x 0.5", "CUTS 2 x 0.5 + 3 x 0.2".
std::string steps_text(const std::vector<CutSteps>& steps, bool step_word) {
  std::string s = "CUTS ";
  for (size_t k = 0; k < steps.size(); ++k) {
    if (k > 0) s += " + ";
    s +=
        fmt::format("{} x {}{}", steps[k].count, step_word ? "STEP " : "", num_text(steps[k].step));
  }
  return s;
}

// The words a ladder is built from and where its errors go.
struct LadderWords {
  const ThreadWords& w;
  int option;
  const SavedLines& lines;
  SourceLoc on_loc;
  std::string_view on_word;
  Diagnostics& diags;
  double allowance;  // f: FINCUT dist, else 0
  int finishing;     // m: FINCUT count, else 0

  // Reports at `loc` (on the THREAD/ON statement) and returns false.
  bool error(SourceLoc loc, std::string message) const {
    diags.error(loc, lines.text(loc.line), std::move(message));
    return false;
  }

  // At most kMaxPasses passes with `roughing` roughing passes; else reported at the word that
  // decided the count.
  bool check_total(double roughing) const {
    if (roughing + finishing <= kMaxPasses) return true;
    const SourceLoc count_loc = w.cuts.set    ? w.cuts.loc
                                : w.step.set  ? w.step.loc
                                : w.depth.set ? w.depth.loc
                                              : on_loc;
    return error(
        count_loc,
        fmt::format("the thread needs {} passes ({} roughing + {} finish); at most {} "
                    "are allowed",
                    num_text(roughing + finishing), num_text(roughing), finishing, kMaxPasses));
  }
};

// The steps the CL gives (CUTS,c,s or couplets, or CUTS,c with STEP,s), empty when it gives none.
// False, reported, when it gives them twice.
bool given_steps(const LadderWords& lw, std::vector<CutSteps>& steps, bool& step_word) {
  const ThreadWords& w = lw.w;
  if (w.cuts.set && !w.cuts.steps.empty()) {
    if (w.step.set) {
      return lw.error(w.step.loc,
                      fmt::format("STEP {} conflicts with the steps given by {}: give the step "
                                  "either with CUTS,c,s or with CUTS,c,STEP,s",
                                  num_text(w.step.value), steps_text(w.cuts.steps, false)));
    }
    steps = w.cuts.steps;
  } else if (w.cuts.set && w.step.set) {
    steps.push_back(CutSteps{w.cuts.count, w.step.value, w.cuts.loc});
    step_word = true;
  }
  return true;
}

// Constant steps or couplets: the ladder is given; DEPTH, if any, verifies it.
bool ladder_of_steps(const LadderWords& lw, const std::vector<CutSteps>& steps, bool step_word,
                     DepthLadder& l) {
  const ThreadWords& w = lw.w;
  const double f = lw.allowance;
  double sum = 0;
  int count = 0;
  for (const CutSteps& s : steps) {
    sum += s.count * s.step;
    count += s.count;
  }
  if (!lw.check_total(count)) return false;
  if (w.depth.set) {
    if (std::fabs(sum + f - w.depth.value) > kDepthTolerance) {
      return lw.error(
          w.depth.loc,
          fmt::format("DEPTH {} does not match {}{} = {}", num_text(w.depth.value),
                      steps_text(steps, step_word),
                      f > 0 ? fmt::format(" + FINCUT {}", num_text(f)) : "", num_text(sum + f)));
    }
    l.depth = w.depth.value;
  } else {
    l.depth = sum + f;
  }
  l.roughing_depth = l.depth - f;
  double d = 0;
  for (const CutSteps& s : steps) {
    for (int k = 0; k < s.count; ++k) {
      d += s.step;
      l.depths.push_back(d);
    }
  }
  l.depths.back() = l.roughing_depth;
  l.roughing = count;
  return true;
}

// DEPTH with CUTS (a count), STEP (the first step) or alone (one pass): the OPTION law.
bool ladder_of_depth(const LadderWords& lw, DepthLadder& l) {
  const ThreadWords& w = lw.w;
  const double f = lw.allowance;
  l.depth = w.depth.value;
  if (f >= l.depth) {
    return lw.error(w.fincut.loc, fmt::format("FINCUT allowance {} must be less than DEPTH {}",
                                              num_text(f), num_text(l.depth)));
  }
  l.roughing_depth = l.depth - f;
  if (w.cuts.set) {
    if (!lw.check_total(w.cuts.count)) return false;
    l.depths = option_ladder_by_count(lw.option, l.roughing_depth, w.cuts.count);
  } else if (w.step.set) {
    const double c = option_count_for_first_step(lw.option, l.roughing_depth, w.step.value);
    if (!lw.check_total(c)) return false;
    l.depths =
        option_ladder_by_first_step(lw.option, l.roughing_depth, w.step.value, static_cast<int>(c));
  } else {
    if (!lw.check_total(1)) return false;
    l.depths.push_back(l.roughing_depth);
  }
  l.roughing = static_cast<int>(l.depths.size());
  return true;
}

// CUTS without DEPTH or steps: CUTS,1 is one pass on the contour (depth 0).
bool ladder_of_count(const LadderWords& lw, DepthLadder& l) {
  const ThreadWords& w = lw.w;
  if (w.cuts.count > 1) {
    return lw.error(w.cuts.loc, fmt::format("CUTS {} needs a depth or a step: give DEPTH,d, "
                                            "STEP,s or CUTS,{},s",
                                            w.cuts.count, w.cuts.count));
  }
  if (lw.allowance > 0) {
    return lw.error(w.fincut.loc, fmt::format("FINCUT allowance {} needs DEPTH: CUTS 1 without "
                                              "DEPTH cuts on the contour (depth 0)",
                                              num_text(lw.allowance)));
  }
  if (!lw.check_total(1)) return false;
  l.depth = 0;
  l.roughing_depth = 0;
  l.depths.push_back(0);
  l.roughing = 1;
  return true;
}

// The roughing passes of whichever form the words give.
bool roughing_ladder(const LadderWords& lw, DepthLadder& l) {
  const ThreadWords& w = lw.w;
  std::vector<CutSteps> steps;
  bool step_word = false;
  if (!given_steps(lw, steps, step_word)) return false;
  if (!steps.empty()) return ladder_of_steps(lw, steps, step_word, l);
  if (w.depth.set) return ladder_of_depth(lw, l);
  if (w.cuts.set) return ladder_of_count(lw, l);
  if (w.step.set) {
    return lw.error(w.step.loc, fmt::format("STEP {} needs DEPTH or CUTS: give DEPTH,d or CUTS,c "
                                            "with it",
                                            num_text(w.step.value)));
  }
  return lw.error(
      lw.on_loc, fmt::format("{} gives no thread depth: expected DEPTH, CUTS or STEP", lw.on_word));
}

}  // namespace

bool make_depth_ladder(const ThreadWords& w, int option, const SavedLines& lines, SourceLoc on_loc,
                       std::string_view on_word, DepthLadder& out, Diagnostics& diags) {
  const LadderWords lw{.w = w,
                       .option = option,
                       .lines = lines,
                       .on_loc = on_loc,
                       .on_word = on_word,
                       .diags = diags,
                       .allowance = w.fincut.set ? w.fincut.dist : 0,
                       .finishing = w.fincut.set ? w.fincut.count : 0};
  DepthLadder l;
  l.allowance = lw.allowance;
  l.finishing = lw.finishing;
  if (!roughing_ladder(lw, l)) return false;
  // The FINCUT passes at D: the first removes the allowance (a finish pass), the others spring.
  l.kinds.assign(l.depths.size(), PassKind::kRough);
  for (int k = 0; k < lw.finishing; ++k) {
    l.depths.push_back(l.depth);
    l.kinds.push_back(k == 0 && lw.allowance > 0 ? PassKind::kFinish : PassKind::kSpring);
  }
  out = std::move(l);
  return true;
}

}  // namespace clpost

// Single-pass threads (THREAD/TURN|FACE|TAPER and two GOTOs) and coupled motion (COUPLE/ON ...
// COUPLE/OFF): threading.md section 3. Both are a path of synchronized moves from where the tool
// is; CouplePlanner builds it one GOTO at a time.
#include <fmt/format.h>

#include <cmath>

#include "planner/plan_report.h"
#include "planner/planner.h"
#include "support/number_text.h"
#include "support/vec2_math.h"

namespace clpost {

using namespace vec2_math;
using namespace plan_report;

bool CouplePlanner::begin(const CoupleInput& in, const PlannerSettings& settings,
                          Diagnostics& diags) {
  Reporter r(diags);
  lines_ = in.lines;
  loc_ = in.loc;
  word_ = in.word;
  const Site site{loc_, &lines_};
  if (!check_pitch(in.pitch, site, in.word, settings, r)) return false;
  plan_ = ThreadPlan{};
  plan_.loc = in.loc;
  plan_.form = ThreadForm::kCouple;
  plan_.units = in.units;
  plan_.pitch = in.pitch;
  plan_.lead = in.pitch.starts * in.pitch.pitch;
  plan_.option = 0;
  plan_.tool_angle = settings.default_tool_angle;  // the CL gives none: drawn with the default
  plan_.cutang = 0;
  plan_.p0 = in.start;
  plan_.side = ThreadSide::kExternal;
  plan_.path.assign(1, in.start);
  at_ = in.start;
  count_ = 0;
  if (in.pitch.starts > 1) {
    r.warning(site, fmt::format("MULTRD {} on {}: the path is cut once, at lead {} (start 0); "
                                "program the other starts as their own moves",
                                in.pitch.starts, in.word, num_text(plan_.lead)));
  }
  return true;
}

const ThreadPass* CouplePlanner::add(Vec2 point, SourceLoc loc, std::string_view line,
                                     Diagnostics& diags) {
  if (length(point - at_) <= kLengthEps) {
    diags.warning(
        loc, line,
        fmt::format("this GOTO {} does not move the tool: no synchronized move", pt(point)));
    return nullptr;
  }
  ThreadPass& p = last_;
  p = ThreadPass{};
  p.n = static_cast<int>(++count_);
  p.approach = p.from = at_;
  p.to = p.pullout_end = p.clear = point;
  if (count_ == 1) {
    // The first move is the thread proper; later ones are usually its pull-out.
    const Vec2 first = point - at_;
    plan_.kind = kind_of(first);
    plan_.lead_along_z = std::fabs(first.z) >= std::fabs(first.x);
    plan_.p1 = at_;
  }
  if (plan_.passes.size() < kMaxKeptPasses) {
    plan_.passes.push_back(p);
    plan_.path.push_back(point);
  } else {
    ++plan_.passes_not_kept;
  }
  plan_.p2 = plan_.end_position = at_ = point;
  return &last_;
}

bool CouplePlanner::finish(ThreadPlan& out, Diagnostics& diags) {
  if (count_ == 0) {
    Reporter r(diags);
    return r.error(
        Site{loc_, &lines_},
        fmt::format("{} has no synchronized move: expected a GOTO that moves the tool", word_));
  }
  out = std::move(plan_);
  plan_ = ThreadPlan{};
  return true;
}

bool plan_couple(const CoupleInput& in, const PlannerSettings& settings, ThreadPlan& out,
                 Diagnostics& diags) {
  CouplePlanner c;
  if (!c.begin(in, settings, diags)) return false;
  for (const ThreadGoto& g : in.gotos) c.add(g.point, g.loc, g.lines.text(g.loc.line), diags);
  return c.finish(out, diags);
}

bool plan_single_thread(const SingleThreadInput& in, const PlannerSettings& settings,
                        ThreadPlan& out, Diagnostics& diags) {
  Reporter r(diags);
  const Site site{in.loc, &in.lines};
  const size_t n = in.gotos.size();
  if (n < 2) {
    return r.error(site, fmt::format("{} needs exactly 2 GOTOs (thread start, thread end); "
                                     "found {}",
                                     in.word, n));
  }
  if (n > 2) {
    r.error(Site{in.gotos[2].loc, &in.gotos[2].lines},
            fmt::format("{} takes exactly 2 GOTOs (thread start, thread end); this is GOTO 3 "
                        "of {} (use THREAD/ON for a chamfer pull-out)",
                        in.word, n));
    r.note(site, "the thread starts here");
    return false;
  }
  const ThreadGoto& a = in.gotos[0];
  const ThreadGoto& b = in.gotos[1];
  if (length(b.point - a.point) <= kLengthEps) {
    r.error(Site{b.loc, &b.lines},
            fmt::format("the thread end {} is the thread start: the thread has no length",
                        pt(b.point)));
    r.note(site, "the thread starts here");
    return false;
  }
  CoupleInput header;
  header.loc = in.loc;
  header.lines = in.lines;
  header.word = in.word;
  header.pitch = in.pitch;
  header.units = in.units;
  header.start = a.point;
  CouplePlanner c;
  if (!c.begin(header, settings, diags)) return false;
  c.add(b.point, b.loc, b.lines.text(b.loc.line), diags);
  if (!c.finish(out, diags)) return false;
  out.form = ThreadForm::kSingle;
  out.p0 = in.p0;
  return true;
}

}  // namespace clpost

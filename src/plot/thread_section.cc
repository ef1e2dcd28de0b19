#include "plot/thread_section.h"

#include <fmt/format.h>

#include <utility>

#include "planner/number_text.h"

namespace clpost {

ThreadSection section_from_plan(const ThreadPlan& plan, std::string title) {
  ThreadSection s;
  if (title.empty()) {
    title = fmt::format("thread at line {} - pitch {}, depth {}", plan.loc.line,
                        num_text(plan.pitch.pitch), num_text(plan.depth));
    if (plan.form == ThreadForm::kMulti || plan.form == ThreadForm::kChain)
      title += fmt::format(", OPTION {}", plan.option);
  }
  s.title = std::move(title);
  s.units = plan.units;
  s.side = plan.side;
  s.pitch = plan.pitch.pitch;
  s.lead = plan.lead;
  s.starts = plan.pitch.starts;
  s.depth = plan.depth;
  s.tool_angle = plan.tool_angle;
  s.passes.reserve(plan.passes.size());
  for (const ThreadPass& p : plan.passes) {
    SectionPass q;
    q.n = p.n;
    q.start = p.start;
    q.depth = p.depth;
    q.shift = p.shift;
    q.kind = p.kind;
    s.passes.push_back(q);
  }
  return s;
}

}  // namespace clpost

// One section per thread, identical threads once (named together): the plan as `clpost plan`
// prints it (same numbers, num_text), the output that wrote it (or the fallback and why), the
// run-in and run-out, every pass's depth, and its cross-section as `clpost plot` draws it.
#include <fmt/format.h>

#include <algorithm>

#include "planner/plan_format.h"
#include "planner/run_in.h"
#include "plot/svg_writer.h"
#include "plot/thread_section.h"
#include "plot/thread_section_svg.h"
#include "sheet/html_text.h"
#include "sheet/sheet_parts.h"
#include "sheet/sheet_text.h"
#include "support/number_text.h"

namespace clpost {

namespace {

bool has_infeed(const ThreadPlan& p) {
  return p.form == ThreadForm::kMulti || p.form == ThreadForm::kChain;
}

// The run-in, run-out and where the lead is right (planner/run_in.h), as facts rows.
std::string lead_facts(const ThreadPlan& p, const char* u) {
  const LeadSpan s = lead_span(p);
  if (!s.known) return fact("Run-in, run-out", "not known (no spindle speed)");
  std::string o = fact("Spindle speed", fmt::format("{} rpm", num_text(p.rpm)));
  o += fact("Run-in", fmt::format("{} {}{}", num_text(p.run_in), u,
                                  p.run_in_added ? " (added before the thread start)" : ""));
  o += fact("Run-out", fmt::format("{} {}", num_text(p.run_out), u));
  const char* axis = s.along_z ? "Z" : "X";
  o += fact("Lead right",
            s.any ? fmt::format("from {} {} to {} {}", axis, num_text(s.from), axis, num_text(s.to))
                  : std::string("no length has the right lead"));
  return o;
}

std::string output_facts(const SheetData& d, const ThreadPlan& p) {
  const OutputUsed* o = output_at(d.outputs, p.loc.line);
  if (!o) return fact("Output", "-");
  std::string r = fact("Output", o->name);
  if (!o->unfit.empty()) r += fact("Fallback", fallback_text(*o));
  for (const std::string& n : o->notes) r += fact("Note", n);
  return r;
}

std::string facts(const SheetData& d, const ThreadPlan& p) {
  const char* u = units_name(p.units);
  std::string o = "<table class=\"facts\">\n<tbody>\n";
  o += fact("Form", fmt::format("{} {} thread, {}", form_name(p.form), kind_name(p.kind),
                                side_name(p.side)));
  std::string pitch = fmt::format("{} {}", num_text(p.pitch.pitch), u);
  if (p.pitch.from_tpi) pitch += fmt::format(" ({} TPI)", num_text(p.pitch.tpi));
  o += fact("Pitch", pitch);
  o += fact("Lead", fmt::format("{} {}", num_text(p.lead), u));
  o += fact("Starts", std::to_string(p.pitch.starts));
  o += fact("Depth", fmt::format("{} {}", num_text(p.depth), u));
  if (has_infeed(p)) {
    o += fact("Infeed", fmt::format("option {}, tool angle {}, cutang {}", p.option,
                                    num_text(p.tool_angle), num_text(p.cutang)));
  }
  o += fact("Passes", std::to_string(p.passes.size()));
  o += output_facts(d, p);
  o += lead_facts(p, u);
  return o + "</tbody>\n</table>\n";
}

std::string passes_table(const ThreadPlan& p) {
  std::string o = "<table class=\"passes\">\n";
  o += head_row({"Pass", "Start", "Depth", "Step", "Shift", "Kind"});
  o += "<tbody>\n";
  const std::vector<double> steps = pass_steps(p);
  for (size_t i = 0; i < p.passes.size(); ++i) {
    const ThreadPass& s = p.passes[i];
    o += row({{std::to_string(s.n), true},
              {std::to_string(s.start), true},
              {num_text(s.depth), true},
              {num_text(steps[i]), true},
              {num_text(s.shift), true},
              {pass_kind_name(s.kind)}});
  }
  return o + "</tbody>\n</table>\n";
}

// The plan's cross-sections, each its own inline SVG with ids unique on the page; without their
// titles (which name the CL line) when `titled` is false, to compare threads.
std::string section_figures(const ThreadPlan& p, const std::string& ids, bool titled = true) {
  std::string o;
  size_t j = 0;
  for (ThreadSection& s : sections_from_plan(p)) {
    if (!titled) s.title.clear();
    const SvgSize size = thread_section_size(s);
    SvgWriter w(size.width, size.height);
    draw_thread_section(w, s, fmt::format("{}{}-", ids, ++j));
    o += "<figure class=\"section\">\n" + inline_svg(w.finish()) + "<figcaption>" + esc(s.title) +
         "</figcaption>\n</figure>\n";
  }
  return o;
}

// Threads whose sections would read the same (facts, passes, pictures) share one: a file of
// 3000 identical threads gives one section that names them, not 3000.
struct ThreadGroup {
  std::string key;  // the section's text, pictures drawn with a fixed id prefix
  std::vector<size_t> members;
};

std::string thread_body(const SheetData& d, const ThreadPlan& p, const std::string& ids,
                        bool titled = true) {
  return "<div class=\"side-by-side\">\n" + facts(d, p) + passes_table(p) + "</div>\n" +
         section_figures(p, ids, titled);
}

std::vector<ThreadGroup> thread_groups(const SheetData& d) {
  std::vector<ThreadGroup> groups;
  for (size_t k = 0; k < d.plans.size(); ++k) {
    std::string key = thread_body(d, d.plans[k], "same-", false);
    auto g = std::find_if(groups.begin(), groups.end(),
                          [&](const ThreadGroup& x) { return x.key == key; });
    if (g == groups.end())
      groups.push_back({std::move(key), {k}});
    else
      g->members.push_back(k);
  }
  return groups;
}

// "Thread 2 of 5: CL line 53", or for a group "Threads 1, 3, 4 of 5 (3 identical): CL lines 53,
// 70, 88", the lists cut after kListed with how many more.
std::string group_heading(const SheetData& d, const std::vector<size_t>& ks) {
  constexpr size_t kListed = 12;
  std::string numbers, lines;
  for (size_t i = 0; i < std::min(ks.size(), kListed); ++i) {
    numbers += fmt::format("{}{}", i ? ", " : "", ks[i] + 1);
    lines += fmt::format("{}{}", i ? ", " : "", d.plans[ks[i]].loc.line);
  }
  if (ks.size() > kListed) {
    numbers += fmt::format(" and {} more", ks.size() - kListed);
    lines += fmt::format(" and {} more", ks.size() - kListed);
  }
  if (ks.size() == 1)
    return fmt::format("Thread {} of {}: CL line {}", numbers, d.plans.size(), lines);
  return fmt::format("Threads {} of {} ({} identical): CL lines {}", numbers, d.plans.size(),
                     ks.size(), lines);
}

}  // namespace

std::string threads_sections(const SheetData& d) {
  std::string o;
  for (const ThreadGroup& g : thread_groups(d)) {
    const size_t k = g.members.front() + 1;
    // No class "thread": the inline backplot's <style> has one, and it would apply here.
    o += fmt::format("<section class=\"page\" id=\"thread-{}\">\n", k);
    o += "<h2>" + esc(group_heading(d, g.members)) + "</h2>\n";
    o += thread_body(d, d.plans[g.members.front()], fmt::format("t{}-", k));
    o += "</section>\n";
  }
  return o;
}

}  // namespace clpost

#include "cli/plot_command.h"

#include <fmt/format.h>

#include <cerrno>
#include <cstdio>
#include <cstring>
#include <filesystem>

#include "cli/batch.h"
#include "cli/post_file.h"
#include "plot/backplot_svg.h"
#include "plot/thread_section.h"
#include "plot/thread_section_svg.h"
#include "simulator/control_sim.h"
#include "support/input_file.h"
#include "support/output_file.h"
#include "verify/verify.h"

namespace clpost {

namespace {

struct Plans {
  bool ok = false;
  std::vector<ThreadPlan> plans;
  std::string program;
  std::string diagnostics;
};

Plans plans_of_cl(const std::string& cl, const Machine& m) {
  Plans p;
  PostOutcome r = plans_of(cl, m, p.plans, &p.program);
  p.ok = r.ok;
  p.diagnostics = r.diagnostics;
  return p;
}

bool simulate_text(std::string_view text, const std::string& name, const Machine& m,
                   Simulation& sim, std::string& diagnostics) {
  Diagnostics d(name);
  reader::LineSource src(text);
  const bool ok = simulate_nc(src, m, d, sim);
  diagnostics += d.render_all();
  return ok;
}

bool simulate_file(const std::string& path, const Machine& m, Simulation& sim,
                   std::string& diagnostics) {
  InputFile f;
  std::string error;
  if (!f.open(path, error)) {
    diagnostics += fmt::format("{}: error: {}\n", path, error);
    return false;
  }
  Diagnostics d(display_name(path));
  reader::LineSource src(f.get());
  const bool ok = simulate_nc(src, m, d, sim);
  diagnostics += d.render_all();
  return ok;
}

}  // namespace

PlotOutcome plot_file(const PlotRequest& req) {
  PlotOutcome out;
  const Machine& m = *req.machine;
  Simulation sim;
  std::vector<ThreadSection> sections;
  std::string title;
  if (is_cl_file_name(req.input)) {
    Plans p = plans_of_cl(req.input, m);
    out.diagnostics += p.diagnostics;
    if (!p.ok) return out;
    if (!simulate_text(p.program, "<program of " + display_name(req.input) + ">", m, sim,
                       out.diagnostics))
      return out;
    for (const ThreadPlan& t : p.plans)
      for (ThreadSection& s : sections_from_plan(t)) sections.push_back(std::move(s));
    title = fmt::format("{} posted on {}", display_name(req.input), m.name);
  } else {
    if (!simulate_file(req.input, m, sim, out.diagnostics)) return out;
    title = fmt::format("{} on {}", display_name(req.input), m.name);
    if (!req.cl.empty()) {
      Plans p = plans_of_cl(req.cl, m);
      out.diagnostics += p.diagnostics;
      if (!p.ok) return out;
      Diagnostics d(display_name(req.input));
      VerifyOptions vo;
      vo.plan_name = display_name(req.cl);
      VerifyReport report;
      verify_cuts(p.plans, sim, m, vo, d, report);  // differences show in the pictures
      for (const ThreadVerdict& v : report.threads) {
        const ThreadPlan& t = p.plans[v.plan];
        ThreadSection s = section_from_plan(
            t, fmt::format("thread at {}:{} as {} cuts it",
                           std::filesystem::path(req.cl).filename().string(), t.loc.line,
                           std::filesystem::path(req.input).filename().string()));
        s.passes = v.program_passes;
        sections.push_back(std::move(s));
      }
    } else if (req.thread > 0) {
      out.diagnostics +=
          "clpost: error: the sections of a program are measured against its plan: give --cl\n";
      return out;
    }
  }
  out.threads = sections.size();
  out.moves = sim.path.moves.size();
  std::string svg;
  if (req.thread > 0) {
    if (static_cast<size_t>(req.thread) > sections.size()) {
      out.diagnostics +=
          fmt::format("clpost: error: --thread {}: {} has {} thread{}\n", req.thread,
                      display_name(req.input), sections.size(), sections.size() == 1 ? "" : "s");
      return out;
    }
    svg = thread_section_svg(sections[static_cast<size_t>(req.thread - 1)]);
  } else {
    svg = backplot_svg(sim.path, &sections, title);
  }
  OutputFile file;
  std::string err;
  if (!file.open(req.output, err)) {
    out.diagnostics += fmt::format("clpost: error: {}\n", err);
    return out;
  }
  file.write(svg);
  if (!file.commit(err)) {
    out.diagnostics += fmt::format("clpost: error: {}\n", err);
    return out;
  }
  out.ok = true;
  return out;
}

}  // namespace clpost

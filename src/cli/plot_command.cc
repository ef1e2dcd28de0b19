#include "cli/plot_command.h"

#include <fmt/format.h>

#include <cerrno>
#include <cstdio>
#include <cstring>
#include <filesystem>
#include <memory>

#include "cli/batch.h"
#include "cli/post_file.h"
#include "plot/backplot_svg.h"
#include "plot/path_thinner.h"
#include "plot/thread_section.h"
#include "plot/thread_section_svg.h"
#include "simulator/control_sim.h"
#include "support/input_file.h"
#include "support/output_file.h"
#include "support/sink.h"
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

// What a plot draws: the simulated program, its threads' sections, the picture's title; unless
// --full, the moves go to `thinner` as they are made instead of into sim.path.
struct Drawing {
  Simulation sim;
  std::vector<ThreadSection> sections;
  std::string title;
  bool full = true;
  PathThinner thinner;
  std::unique_ptr<MillViews> mill;  // a machine with C: its face and peripheral views
  size_t milling = 0;               // moves left to them (MillViews::side_move), unless --full
  std::vector<bool> side_draws;     // --full with C: side_move's answer for each move, in order
  // Unless --full: no moves kept; each that goes somewhere (not the entries from an unknown
  // position, which are not drawn) streams into the thinner. With C, the moves in X, Y, Z and C
  // stream into `mill` (not kept), and the side view's moves too (the turned stock); the side
  // view leaves out the C-axis work.
  SimOptions options() {
    SimOptions o;
    if (mill) o.on_mill_move = [this](const SimMillMove& m) { mill->mill_move(m); };
    if (full) {
      if (mill)
        o.on_move = [this](const Move& m, const CutState& s) {
          side_draws.push_back(mill->side_move(m, s));
        };
      return o;
    }
    o.keep_moves = false;
    o.on_move = [this](const Move& m, const CutState& s) {
      const bool draws = !mill || mill->side_move(m, s);
      if (m.from.x == m.to.x && m.from.z == m.to.z) return;
      draws ? thinner.add(m) : void(++milling);
    };
    return o;
  }
  // --full: the kept moves the side view draws. Every move was handed to on_move in order, the
  // entries from an unknown position (Toolpath::entries, not kept) among them before the kept
  // move at their index.
  void leave_out_c_work() {
    if (side_draws.empty()) return;
    std::vector<Move> kept;
    size_t call = 0, entry = 0;
    const std::vector<Move>& moves = sim.path.moves;
    for (size_t k = 0; k < moves.size(); ++k, ++call) {
      for (; entry < sim.path.entries.size() && sim.path.entries[entry].before == k; ++entry)
        ++call;
      if (call >= side_draws.size() || side_draws[call]) {
        kept.push_back(moves[k]);
      } else if (moves[k].from.x != moves[k].to.x || moves[k].from.z != moves[k].to.z) {
        ++milling;  // as the thinner counts: moves in X or Z
      }
    }
    sim.path.moves = std::move(kept);
  }
  // The C-axis work's views (none without C).
  MillViewsDrawn mill_views() {
    return mill ? mill->finish(sim.holes, sim.units) : MillViewsDrawn{};
  }
};

bool simulate_file(const std::string& path, const Machine& m, Drawing& dr,
                   std::string& diagnostics) {
  InputFile f;
  std::string error;
  if (!f.open(path, error)) {
    diagnostics += fmt::format("{}: error: {}\n", path, error);
    return false;
  }
  Diagnostics d(display_name(path));
  reader::LineSource src(f.get());
  const bool ok = simulate_nc(src, m, d, dr.sim, dr.options());
  diagnostics += d.render_all();
  return ok;
}

// A sink into a temporary file (the program of a CL file, read back by the simulation).
class TempFileSink : public Sink {
 public:
  TempFileSink() : f_(std::tmpfile()) {}
  ~TempFileSink() override {
    if (f_ != nullptr) std::fclose(f_);
  }
  TempFileSink(const TempFileSink&) = delete;
  TempFileSink& operator=(const TempFileSink&) = delete;
  std::FILE* get() const { return f_; }
  bool ok() const { return f_ != nullptr && !failed_; }

 private:
  void overflow(std::string_view text) override {
    failed_ =
        failed_ || f_ == nullptr || std::fwrite(text.data(), 1, text.size(), f_) != text.size();
  }
  std::FILE* f_;
  bool failed_ = false;
};

// A CL file drawn in bounded memory: posted into a temporary file (nothing kept but the
// sections), its program simulated from there, its moves streamed into the thinner.
bool draw_cl_streaming(const PlotRequest& req, Drawing& d, std::string& diagnostics) {
  const Machine& m = *req.machine;
  TempFileSink program;
  PostRequest pr{req.input, "", &m, PostOptions{}, [&](const ThreadPlan& t) {
                   for (ThreadSection& s : sections_from_plan(t))
                     d.sections.push_back(std::move(s));
                 }};
  pr.program_sink = &program;
  PostOutcome r = post_file(pr);
  diagnostics += r.diagnostics;
  if (!r.ok) return false;
  if (!program.ok() || std::fflush(program.get()) != 0 ||
      std::fseek(program.get(), 0, SEEK_SET) != 0) {
    diagnostics +=
        fmt::format("clpost: error: cannot write a temporary file: {}\n", std::strerror(errno));
    return false;
  }
  Diagnostics diags("<program of " + display_name(req.input) + ">");
  reader::LineSource src(program.get());
  const bool ok = simulate_nc(src, m, diags, d.sim, d.options());
  diagnostics += diags.render_all();
  d.title = fmt::format("{} posted on {}", display_name(req.input), m.name);
  return ok;
}

// A CL file: posted, its program simulated, its threads' sections as planned.
bool draw_cl(const PlotRequest& req, Drawing& d, std::string& diagnostics) {
  const Machine& m = *req.machine;
  Plans p = plans_of_cl(req.input, m);
  diagnostics += p.diagnostics;
  if (!p.ok) return false;
  if (!simulate_text(p.program, "<program of " + display_name(req.input) + ">", m, d.sim,
                     diagnostics, d.options()))
    return false;
  for (const ThreadPlan& t : p.plans)
    for (ThreadSection& s : sections_from_plan(t)) d.sections.push_back(std::move(s));
  d.title = fmt::format("{} posted on {}", display_name(req.input), m.name);
  return true;
}

// --cl: the program's threads, their passes measured against the CL file's plan (verify_cuts).
bool sections_as_cut(const PlotRequest& req, Drawing& d, std::string& diagnostics) {
  const Machine& m = *req.machine;
  Plans p = plans_of_cl(req.cl, m);
  diagnostics += p.diagnostics;
  if (!p.ok) return false;
  Diagnostics diags(display_name(req.input));
  VerifyOptions vo;
  vo.plan_name = display_name(req.cl);
  VerifyReport report;
  verify_cuts(p.plans, d.sim, m, vo, diags, report);  // differences show in the pictures
  for (const ThreadVerdict& v : report.threads) {
    const ThreadPlan& t = p.plans[v.plan];
    ThreadSection s = section_from_plan(
        t, fmt::format("thread at {}:{} as {} cuts it",
                       std::filesystem::path(req.cl).filename().string(), t.loc.line,
                       std::filesystem::path(req.input).filename().string()));
    s.passes = v.program_passes;
    d.sections.push_back(std::move(s));
  }
  return true;
}

// An NC program: simulated; its threads' sections only with --cl, which they are measured by.
bool draw_program(const PlotRequest& req, Drawing& d, std::string& diagnostics) {
  const Machine& m = *req.machine;
  if (!simulate_file(req.input, m, d, diagnostics)) return false;
  d.title = fmt::format("{} on {}", display_name(req.input), m.name);
  if (!req.cl.empty()) return sections_as_cut(req, d, diagnostics);
  if (req.thread > 0) {
    diagnostics +=
        "clpost: error: the sections of a program are measured against its plan: give --cl\n";
    return false;
  }
  return true;
}

// The backplot of the thinned path, identical sections once with their count, and a note on
// what was simplified.
std::string simplified_backplot(Drawing& d) {
  const ThinnedPath path = d.thinner.finish(d.sim.units);
  SectionGroups groups;
  for (const ThreadSection& s : d.sections) groups.add(s);
  const std::vector<ThreadSection> drawn = groups.drawn();
  std::string note = simplified_note(path);
  if (const std::string m = milling_note(d.milling); !m.empty())
    note += (note.empty() ? "" : "; ") + m;
  if (drawn.size() < groups.total()) {
    std::string more = fmt::format("{} threads drawn as {} section{}", groups.total(), drawn.size(),
                                   drawn.size() == 1 ? "" : "s");
    if (groups.left_out() > 0)
      more += fmt::format(", {} more not drawn (--thread N)", groups.left_out());
    note += (note.empty() ? "" : "; ") + more;
  }
  const MillViewsDrawn mill = d.mill_views();
  return backplot_svg(path, &drawn, d.title, note, &mill);
}

// The picture: thread N's section (--thread N), else the backplot with every section.
bool render_svg(const PlotRequest& req, Drawing& d, std::string& svg, std::string& diagnostics) {
  if (req.thread <= 0 && d.full) {
    const MillViewsDrawn mill = d.mill_views();
    d.leave_out_c_work();
    svg = backplot_svg(d.sim.path, &d.sections, d.title, &mill, milling_note(d.milling));
    return true;
  }
  if (req.thread <= 0) {
    svg = simplified_backplot(d);
    return true;
  }
  if (static_cast<size_t>(req.thread) > d.sections.size()) {
    diagnostics +=
        fmt::format("clpost: error: --thread {}: {} has {} thread{}\n", req.thread,
                    display_name(req.input), d.sections.size(), d.sections.size() == 1 ? "" : "s");
    return false;
  }
  svg = thread_section_svg(d.sections[static_cast<size_t>(req.thread - 1)]);
  return true;
}

bool write_svg(const std::string& path, const std::string& svg, std::string& diagnostics) {
  OutputFile file;
  std::string err;
  if (!file.open(path, err)) {
    diagnostics += fmt::format("clpost: error: {}\n", err);
    return false;
  }
  file.write(svg);
  if (!file.commit(err)) {
    diagnostics += fmt::format("clpost: error: {}\n", err);
    return false;
  }
  return true;
}

}  // namespace

bool simulate_text(std::string_view text, const std::string& name, const Machine& m,
                   Simulation& sim, std::string& diagnostics, const SimOptions& options) {
  Diagnostics d(name);
  reader::LineSource src(text);
  const bool ok = simulate_nc(src, m, d, sim, options);
  diagnostics += d.render_all();
  return ok;
}

PlotOutcome plot_file(const PlotRequest& req) {
  PlotOutcome out;
  Drawing d;
  d.full = req.full;
  if (req.machine->c_axis)
    d.mill = std::make_unique<MillViews>(req.machine->c_rotation == CRotation::kRollover,
                                         req.machine->y_axis);
  const bool cl = is_cl_file_name(req.input);
  const bool drawn = cl ? (req.full ? draw_cl(req, d, out.diagnostics)
                                    : draw_cl_streaming(req, d, out.diagnostics))
                        : draw_program(req, d, out.diagnostics);
  if (!drawn) return out;
  out.threads = d.sections.size();
  out.moves = d.full ? d.sim.path.moves.size() : d.thinner.moves();
  std::string svg;
  if (!render_svg(req, d, svg, out.diagnostics) || !write_svg(req.output, svg, out.diagnostics))
    return out;
  out.ok = true;
  return out;
}

}  // namespace clpost

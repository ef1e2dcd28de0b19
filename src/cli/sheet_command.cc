#include "cli/sheet_command.h"

#include <fmt/format.h>

#include <filesystem>

#include "cli/plot_command.h"
#include "emitters/hole_output.h"
#include "plot/path_thinner.h"
#include "sheet/sheet.h"
#include "sheet/sheet_text.h"
#include "support/output_file.h"

namespace clpost {

void sheet_request(PostRequest& req, SheetCapture& capture) {
  auto chained = req.on_thread;
  req.on_thread = [&capture, chained](const ThreadPlan& p) {
    if (chained) chained(p);
    capture.plans.push_back(p);
  };
  req.program = &capture.program;
}

namespace {

SheetData sheet_data(const std::string& input, const PostOutcome& r, SheetCapture& capture,
                     const Machine& m, const SheetInfo& info) {
  SheetData d;
  d.program = display_name(input);
  d.partno = r.partno;
  d.nc_file = info.nc_file;
  d.machine = m.name;
  d.machine_description = m.description;
  d.date = info.date;
  d.units = r.units;
  d.diameter = m.diameter_output;
  d.cycle_time = r.cycle_time;
  d.plans = std::move(capture.plans);
  d.holes = r.holes;
  d.outputs = r.outputs;
  for (const Hole& h : d.holes) {
    const OutputUsed* o = output_at(d.outputs, h.cl_line);
    d.hole_outputs.push_back(o ? hole_output_text(m, h, o->name) : "-");
  }
  for (const Diagnostic& g : r.kept)
    if (g.severity != Severity::kError) d.diagnostics.push_back(g);
  d.warnings = r.warnings;
  return d;
}

}  // namespace

bool sheet_text(const std::string& input, const PostOutcome& r, SheetCapture& capture,
                const Machine& m, const SheetInfo& info, std::string& text,
                std::string& diagnostics) {
  SheetData d = sheet_data(input, r, capture, m, info);
  if (info.format == SheetFormat::kJson) {
    text = sheet_json(d);
    return true;
  }
  // The backplot as `clpost plot` draws it: the moves thinned as they stream (path_thinner.h).
  PathThinner thinner;
  SimOptions options;
  options.keep_moves = false;
  options.on_move = [&thinner](const Move& mv, const CutState&) {
    if (!(mv.from.x == mv.to.x && mv.from.z == mv.to.z)) thinner.add(mv);
  };
  Simulation sim;
  if (!simulate_text(capture.program, "<program of " + d.program + ">", m, sim, diagnostics,
                     options))
    return false;
  d.toolpath = thinner.finish(sim.units);
  text = sheet_html(d);
  return true;
}

bool write_text_file(const std::string& path, const std::string& text, std::string& diagnostics) {
  OutputFile file;
  std::string err;
  if (!file.open(path, err) || (file.write(text), !file.commit(err))) {
    diagnostics += fmt::format("clpost: error: {}\n", err);
    return false;
  }
  return true;
}

std::string sheet_path_in(const std::string& dir, const std::string& input, SheetFormat f) {
  std::filesystem::path p(input);
  p.replace_extension(f == SheetFormat::kJson ? ".json" : ".html");
  return (std::filesystem::path(dir) / p.filename()).string();
}

SheetOutcome sheet_file(const SheetRequest& req) {
  SheetOutcome out;
  SheetCapture capture;
  PostRequest post{req.input, "", req.machine, PostOptions{}, nullptr};
  sheet_request(post, capture);
  const PostOutcome r = post_file(post);
  out.diagnostics = r.diagnostics;
  if (!r.ok) return out;
  std::string text;
  if (!sheet_text(req.input, r, capture, *req.machine, req.info, text, out.diagnostics) ||
      !write_text_file(req.output, text, out.diagnostics))
    return out;
  out.ok = true;
  return out;
}

}  // namespace clpost

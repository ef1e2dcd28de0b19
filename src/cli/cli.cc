#include "cli/cli.h"

#include <fmt/format.h>
#include <unistd.h>

#include <CLI/CLI.hpp>
#include <algorithm>
#include <cerrno>
#include <chrono>
#include <cstdio>
#include <cstdlib>
#include <cstring>
#include <filesystem>
#include <memory>
#include <string>
#include <thread>
#include <vector>

#include "cli/batch.h"
#include "cli/batch_report.h"
#include "cli/cl2apt_command.h"
#include "cli/data_dirs.h"
#include "cli/machines_command.h"
#include "cli/plot_command.h"
#include "cli/post_file.h"
#include "cli/schema_command.h"
#include "cli/sheet_command.h"
#include "cli/verify_command.h"
#include "controls/registry.h"
#include "emitters/emitter.h"
#include "machine/machine_loader.h"
#include "planner/plan_format.h"
#include "sheet/sheet.h"
#include "support/output_file.h"

#ifndef CLPOST_VERSION
#define CLPOST_VERSION "0"
#endif

namespace clpost {

namespace {

constexpr int kExitOk = 0;
constexpr int kExitInput = 1;
constexpr int kExitUsage = 2;

void print_err(std::string_view s) {
  if (!s.empty()) std::fwrite(s.data(), 1, s.size(), stderr);
}
void print_out(std::string_view s) {
  if (!s.empty()) std::fwrite(s.data(), 1, s.size(), stdout);
}

constexpr const char* kFooter = R"(Examples:
  clpost part.cl                          post on generic-lathe, NC to standard output
  clpost -m linuxcnc-lathe -o part.ngc part.cl
  clpost -m my-machines/lathe5.yaml part.cl     a machine file of your own
  clpost -m generic-lathe --set block_numbers.enabled=false part.cl
  clpost check *.cl                       parse and validate, write nothing
  clpost plan --format json thread.cl     the thread pass plan
  clpost -m generic-lathe -d out/ -j 4 --keep-going *.cl   batch: out/<stem>.nc for each
  clpost -d out/ -r cl-files/ --report report.json          a directory tree, with a report
  clpost machines                         list the shipped machines
  clpost machines show fanuc-0i-t --origin   every key as loaded, and where it came from
  clpost machines diff fanuc-0i-t haas-st    the keys whose values differ
  clpost schema > clpost-machine.schema.json  the JSON Schema of machine and post files
  clpost -m fanuc-0i-t --verify -o part.nc part.cl     post, then check the program cuts the plan
  clpost verify -m fanuc-0i-t part.nc --cl part.cl     check a program (edited by hand?)
  clpost plot -o part.svg part.cl         backplot and every thread's cross-section, as SVG
  clpost sheet -m fanuc-0i-t -o part.html part.cl   the setup sheet: tools, times, threads
  clpost -m fanuc-0i-t -o part.nc --sheet sheets/ part.cl   post, and sheets/part.html
  clpost -m fanuc-0i-t -d out/ --sheets --report r.json *.cl   out/<stem>.html beside each
  clpost plot -m fanuc-0i-t --cl part.cl --thread 2 -o t2.svg part.nc   a program's passes
  clpost cl2apt -o part.apt part.cl       a binary CL file (ISO 3592 CLDATA) as APT text

Exit status: 0 ok, 1 errors in the input, 2 usage or machine-file errors.
A batch (-d) exits 1 when any file failed, 2 when it could not start (duplicate output names,
an output directory that cannot be written).)";

struct MachineOpts {
  std::string machine = "generic-lathe";
  std::vector<std::string> sets;
};

void add_machine_opts(CLI::App& app, MachineOpts& o) {
  app.add_option("-m,--machine", o.machine,
                 "Shipped machine name or path to a machine YAML file (default: generic-lathe)");
  app.add_option("--set", o.sets, "Override a machine key: --set threading.strategy=loop")
      ->type_name("KEY=VALUE")
      ->allow_extra_args(false);
}

bool load(const MachineOpts& o, Machine& m) {
  std::string errors;
  if (load_machine(o.machine, data_dirs(), o.sets, shipped_controls(), m, errors)) return true;
  print_err(errors);
  return false;
}

struct BatchOpts {
  std::string out_dir;
  bool recursive = false;
  unsigned jobs = 0;  // 0: the machine's cores
  bool keep_going = false;
  bool quiet = false;
  std::string report;
  bool sheets = false;

  bool used(const CLI::App& app) const {
    for (const char* name : {"-r", "-j", "--keep-going", "--quiet", "--report", "--sheets"})
      if (app.count(name) > 0) return true;
    return false;
  }
};

void add_batch_opts(CLI::App& app, BatchOpts& b) {
  app.add_option("-d,--output-dir", b.out_dir,
                 "Batch: post every input to OUTDIR/<stem><machine extension>")
      ->type_name("OUTDIR");
  app.add_flag("-r,--recursive", b.recursive,
               "Batch: post the CL files in directories, recursively");
  app.add_option("-j,--jobs", b.jobs, "Batch: files posted at once (default: the machine's cores)")
      ->check(CLI::Range(1u, 1024u));
  app.add_flag("--keep-going", b.keep_going,
               "Batch: post every file even after a failure (exit status 1 all the same)");
  app.add_flag("-q,--quiet", b.quiet, "Batch: print only the failed files");
  app.add_option("--report", b.report, "Batch: write per-file results as JSON")
      ->type_name("FILE.json");
  app.add_flag("--sheets", b.sheets,
               "Batch: write each program's setup sheet beside it, OUTDIR/<stem>.html (the "
               "report links it)");
}

// The date the sheets show: --date, else SOURCE_DATE_EPOCH, else now. False (reported) for a
// SOURCE_DATE_EPOCH that is not a number.
bool resolve_sheet_date(const std::string& given, std::string& date) {
  std::string err;
  if (sheet_date(given, std::getenv("SOURCE_DATE_EPOCH"), date, err)) return true;
  print_err(fmt::format("clpost: error: {}\n", err));
  return false;
}

// The batch's output directory, created when missing; false (reported) when it cannot be
// written to.
bool make_output_dir(const std::string& dir) {
  namespace fs = std::filesystem;
  std::error_code ec;
  fs::create_directories(dir, ec);
  if (ec || !fs::is_directory(dir, ec)) {
    print_err(fmt::format("clpost: error: cannot create the output directory '{}': {}\n", dir,
                          ec ? ec.message() : "not a directory"));
    return false;
  }
  if (::access(dir.c_str(), W_OK | X_OK) != 0) {
    print_err(fmt::format("clpost: error: cannot write to the output directory '{}': {}\n", dir,
                          std::strerror(errno)));
    return false;
  }
  return true;
}

// The batch's --report; false (reported) when it cannot be written.
bool write_report(const std::string& path, const std::string& json) {
  std::string err;
  OutputFile report;
  if (!report.open(path, err) || (report.write(json), !report.commit(err))) {
    print_err(fmt::format("clpost: error: cannot write the report: {}\n", err));
    return false;
  }
  return true;
}

// Problems found before anything is posted (usage, the output directory) exit 2; failed files
// exit 1.
int run_batch_command(const MachineOpts& mo, const BatchOpts& b, bool strict, bool verify,
                      const std::string& sheet_date, const std::vector<std::string>& args) {
  const auto t0 = std::chrono::steady_clock::now();
  Machine m;
  if (!load(mo, m)) return kExitUsage;
  std::vector<std::string> files;
  std::vector<BatchItem> items;
  std::string err;
  if (!collect_inputs(args, b.recursive, files, err) ||
      !plan_outputs(files, b.out_dir, m.extension, items, err)) {
    print_err(fmt::format("clpost: error: {}\n", err));
    return kExitUsage;
  }
  if (!make_output_dir(b.out_dir)) return kExitUsage;

  BatchSettings settings;
  settings.jobs = b.jobs != 0 ? b.jobs : std::max(1u, std::thread::hardware_concurrency());
  settings.keep_going = b.keep_going;
  settings.post = PostOptions{strict};
  settings.verify = verify;
  settings.sheets = b.sheets;
  settings.sheet_date = sheet_date;
  const bool bar = !b.quiet && ::isatty(STDERR_FILENO) == 1;
  size_t done = 0, failed = 0;
  auto on_result = [&](const FileResult& r) {
    ++done;
    if (r.status == FileStatus::kError) ++failed;
    std::string text;
    if (bar) text += "\r\033[K";
    if (!b.quiet || r.status == FileStatus::kError) text += file_line(r);
    if (bar) text += progress_bar(done, items.size(), failed);
    print_err(text);
  };
  std::vector<FileResult> results = run_batch(items, m, settings, on_result);
  const double seconds =
      std::chrono::duration<double>(std::chrono::steady_clock::now() - t0).count();
  const BatchSummary summary = summarize(results, seconds);
  if (bar) print_err("\r\033[K");
  if (!b.quiet) print_err(summary_line(summary));
  int rc = summary.failed > 0 ? kExitInput : kExitOk;
  if (!b.report.empty() &&
      !write_report(b.report, batch_report_json(BatchReportInfo{m.name, b.out_dir, settings.jobs},
                                                summary, results)))
    rc = kExitInput;
  return rc;
}

int print_command_output(const CommandOutput& r) {
  print_out(r.out);
  print_err(r.err);
  return r.exit_code;
}

// The main command: post one file, or a batch (-d).
struct PostCommand {
  MachineOpts machine;
  std::vector<std::string> inputs;
  std::string output;
  bool strict = false;
  BatchOpts batch;
  bool verify = false;
  std::string sheet_dir;
  std::string date;
};

void add_sheet_date_opt(CLI::App& app, std::string& date) {
  app.add_option("--date", date,
                 "The date a setup sheet shows (default: SOURCE_DATE_EPOCH, else now, UTC)")
      ->type_name("TEXT");
}

void add_post_command(CLI::App& app, PostCommand& c) {
  add_machine_opts(app, c.machine);
  app.add_option("-o,--output", c.output, "Output file (default: standard output)");
  app.add_flag("--strict", c.strict, "Unknown CL statements are errors, not warnings");
  add_batch_opts(app, c.batch);
  app.add_flag("--verify", c.verify,
               "Read the program back through the control's laws and check it cuts the plan; "
               "a program that does not is an error (nothing written)");
  app.add_option("--sheet", c.sheet_dir,
                 "Also write the program's setup sheet, DIR/<stem>.html (clpost sheet)")
      ->type_name("DIR");
  add_sheet_date_opt(app, c.date);
  app.add_option("inputs", c.inputs,
                 "CL file to post ('-' for standard input); with -d: files and directories");
}

// --sheet DIR: the sheet of the post just made, DIR/<stem>.html. False (reported) when it
// cannot be written.
bool write_post_sheet(const PostCommand& c, const PostOutcome& r, SheetCapture& capture,
                      const Machine& m, const std::string& date) {
  if (!make_output_dir(c.sheet_dir)) return false;
  const SheetInfo info{c.output.empty() || c.output == "-" ? "" : c.output, date,
                       SheetFormat::kHtml};
  std::string text, diagnostics;
  const bool ok = sheet_text(c.inputs[0], r, capture, m, info, text, diagnostics) &&
                  write_text_file(sheet_path_in(c.sheet_dir, c.inputs[0], SheetFormat::kHtml), text,
                                  diagnostics);
  print_err(diagnostics);
  return ok;
}

// One file: its program to -o (standard output), its sheet with --sheet DIR.
int post_one_file(const PostCommand& c) {
  const bool sheet = !c.sheet_dir.empty();
  if (sheet && c.inputs[0] == "-") {
    print_err("clpost: error: --sheet names the sheet after the input: not with '-'\n");
    return kExitUsage;
  }
  std::string date;
  if (sheet && !resolve_sheet_date(c.date, date)) return kExitUsage;
  Machine m;
  if (!load(c.machine, m)) return kExitUsage;
  PostRequest req{c.inputs[0], c.output.empty() ? "-" : c.output, &m, PostOptions{c.strict},
                  nullptr};
  req.verify = c.verify;
  SheetCapture capture;
  std::unique_ptr<OutputFile> held;  // --sheet: a program file waits for its sheet
  if (sheet) {
    sheet_request(req, capture);
    req.publish_later = [&held](std::unique_ptr<OutputFile> f) { held = std::move(f); };
  }
  PostOutcome r = post_file(req);
  print_err(r.verify_report);
  print_err(r.diagnostics);
  if (!r.ok) return kExitInput;
  if (sheet && !write_post_sheet(c, r, capture, m, date)) {
    if (held) held->abort();  // no program without its sheet, as in a batch
    return kExitInput;
  }
  std::string err;
  if (held && !held->publish(err)) {
    print_err(fmt::format("clpost: error: {}\n", err));
    return kExitInput;
  }
  return kExitOk;
}

int run_post_command(const CLI::App& app, const PostCommand& c) {
  if (c.inputs.empty()) {
    print_err(app.help());
    print_err("\nclpost: error: no input file (use '-' for standard input)\n");
    return kExitUsage;
  }
  if (!c.batch.out_dir.empty() || c.batch.used(app)) {
    if (c.batch.out_dir.empty()) {
      print_err("clpost: error: -r, -j, --keep-going, --quiet and --report need -d OUTDIR\n");
      return kExitUsage;
    }
    if (!c.output.empty()) {
      print_err("clpost: error: -o and -d cannot be used together\n");
      return kExitUsage;
    }
    if (!c.sheet_dir.empty()) {
      print_err("clpost: error: in a batch, --sheets writes the sheets beside the programs\n");
      return kExitUsage;
    }
    std::string date;
    if (c.batch.sheets && !resolve_sheet_date(c.date, date)) return kExitUsage;
    return run_batch_command(c.machine, c.batch, c.strict, c.verify, date, c.inputs);
  }
  if (c.inputs.size() > 1) {
    print_err("clpost: error: several inputs need an output directory: -d OUTDIR\n");
    return kExitUsage;
  }
  return post_one_file(c);
}

// `clpost machines`, `machines show`, `machines diff`.
struct MachinesCommand {
  CLI::App* list = nullptr;
  CLI::App* show = nullptr;
  CLI::App* diff = nullptr;
  MachineOpts show_machine;
  bool show_origin = false;
  std::string diff_a, diff_b;
};

void add_machines_command(CLI::App& app, MachinesCommand& c) {
  c.list = app.add_subcommand("machines", "List the shipped machines");
  c.show = c.list->add_subcommand("show", "A machine exactly as loaded: every key");
  c.show->add_option("machine", c.show_machine.machine, "Shipped machine name or machine file")
      ->required();
  c.show->add_option("--set", c.show_machine.sets, "Override a machine key")
      ->type_name("KEY=VALUE");
  c.show->add_flag("--origin", c.show_origin,
                   "Where each value came from (file:line, --set, default)");
  c.diff = c.list->add_subcommand("diff", "The keys whose values differ");
  c.diff->add_option("a", c.diff_a, "Machine name or file")->required();
  c.diff->add_option("b", c.diff_b, "Machine name or file")->required();
}

// Each machine is loaded in full, so a broken file shows here rather than mid-batch.
int list_machines_command() {
  int rc = kExitOk;
  for (const MachineInfo& mi : list_machines(data_dirs())) {
    Machine m;
    std::string errors;
    if (!load_machine(mi.path, data_dirs(), {}, shipped_controls(), m, errors)) {
      print_out(fmt::format("{:<18} {:<5} {}\n", mi.name, "?", "(does not load, see below)"));
      print_err(errors);
      rc = kExitUsage;
      continue;
    }
    print_out(fmt::format("{:<18} {:<5} {:<40} {}\n", mi.name, m.extension, threading_summary(m),
                          m.description));
  }
  return rc;
}

int run_machines_command(const MachinesCommand& c) {
  if (*c.show)
    return print_command_output(
        machines_show(c.show_machine.machine, c.show_machine.sets, c.show_origin, data_dirs()));
  if (*c.diff) return print_command_output(machines_diff(c.diff_a, c.diff_b, data_dirs()));
  return list_machines_command();
}

// `clpost check`: post without writing, a line per file.
struct CheckCommand {
  MachineOpts machine;
  std::vector<std::string> inputs;
  bool strict = false;
};

CLI::App* add_check_command(CLI::App& app, CheckCommand& c) {
  CLI::App* check = app.add_subcommand("check", "Parse and validate CL files without writing");
  add_machine_opts(*check, c.machine);
  check->add_flag("--strict", c.strict, "Unknown CL statements are errors");
  check->add_option("inputs", c.inputs, "CL files")->required();
  return check;
}

int run_check_command(const CheckCommand& c) {
  Machine m;
  if (!load(c.machine, m)) return kExitUsage;
  int rc = kExitOk;
  for (const std::string& in : c.inputs) {
    PostRequest req{in, "", &m, PostOptions{c.strict}, nullptr};
    PostOutcome r = post_file(req);
    print_err(r.diagnostics);
    if (!r.ok) rc = kExitInput;
    print_err(fmt::format("{}: {} ({} errors, {} warnings, {} statements, {} threads)\n",
                          display_name(in), r.ok ? "ok" : "failed", r.errors, r.warnings,
                          r.stats.statements, r.stats.threads));
    if (r.ok)
      for (const std::string& l : cycle_time_lines(r.cycle_time, r.units, m.diameter_output))
        print_err("  " + l + "\n");
  }
  return rc;
}

// `clpost plan`: the thread pass plans, as text or JSON.
struct PlanCommand {
  MachineOpts machine;
  std::vector<std::string> inputs;
  std::string format = "text";
};

CLI::App* add_plan_command(CLI::App& app, PlanCommand& c) {
  CLI::App* plan = app.add_subcommand("plan", "Print the thread pass plans of CL files");
  add_machine_opts(*plan, c.machine);
  plan->add_option("--format", c.format, "text or json")->check(CLI::IsMember({"text", "json"}));
  plan->add_option("inputs", c.inputs, "CL files")->required();
  return plan;
}

int run_plan_command(const PlanCommand& c) {
  Machine m;
  if (!load(c.machine, m)) return kExitUsage;
  int rc = kExitOk;
  std::string out;
  bool json = c.format == "json";
  if (json && c.inputs.size() > 1) out += "[\n";
  for (size_t i = 0; i < c.inputs.size(); ++i) {
    std::vector<ThreadPlan> plans;
    PostRequest req{c.inputs[i], "", &m, PostOptions{},
                    [&](const ThreadPlan& p) { plans.push_back(p); }};
    PostOutcome r = post_file(req);
    print_err(r.diagnostics);
    if (!r.ok) {
      rc = kExitInput;
      continue;
    }
    std::string name = display_name(c.inputs[i]);
    if (json) {
      if (i > 0 && c.inputs.size() > 1 && out.size() > 2) out += ",\n";
      out += plan_to_json(name, r.units, plans);
    } else {
      out += plan_to_text(name, r.units, plans);
    }
  }
  if (json && c.inputs.size() > 1) out += "\n]\n";
  print_out(out);
  return rc;
}

// `clpost sheet`: the setup sheet of a CL file, as HTML or JSON.
struct SheetCommand {
  MachineOpts machine;
  SheetRequest req;
  std::string format = "html";
  std::string date;
};

CLI::App* add_sheet_command(CLI::App& app, SheetCommand& c) {
  CLI::App* sheet = app.add_subcommand(
      "sheet", "The setup sheet of a CL file: one self-contained HTML page (or JSON)");
  add_machine_opts(*sheet, c.machine);
  sheet->add_option("input", c.req.input, "CL file")->required();
  sheet->add_option("-o,--output", c.req.output, "Sheet file (default: standard output)");
  sheet->add_option("--format", c.format, "html or json")->check(CLI::IsMember({"html", "json"}));
  sheet->add_option("--nc", c.req.info.nc_file, "The NC program's name the sheet shows")
      ->type_name("FILE");
  add_sheet_date_opt(*sheet, c.date);
  return sheet;
}

int run_sheet_command(const SheetCommand& c) {
  SheetRequest req = c.req;
  req.info.format = c.format == "json" ? SheetFormat::kJson : SheetFormat::kHtml;
  if (!resolve_sheet_date(c.date, req.info.date)) return kExitUsage;
  Machine m;
  if (!load(c.machine, m)) return kExitUsage;
  req.machine = &m;
  SheetOutcome r = sheet_file(req);
  print_err(r.diagnostics);
  return r.ok ? kExitOk : kExitInput;
}

// `clpost verify`: a program against the plan of a CL file or of a plan JSON.
struct VerifyCommand {
  MachineOpts machine;
  std::string nc, cl, plan;
  double tolerance = 0;
};

CLI::App* add_verify_command(CLI::App& app, VerifyCommand& c) {
  CLI::App* verify =
      app.add_subcommand("verify", "Check that an NC program cuts the thread plan of a CL file");
  add_machine_opts(*verify, c.machine);
  verify->add_option("program", c.nc, "NC program in the machine's dialect ('-': stdin)")
      ->required();
  CLI::Option* cl_opt = verify->add_option("--cl", c.cl, "The CL file the plan comes from");
  CLI::Option* plan_opt = verify->add_option(
      "--plan", c.plan, "The plan as `clpost plan --format json` wrote it (instead of --cl)");
  cl_opt->excludes(plan_opt);
  verify
      ->add_option("--tolerance", c.tolerance,
                   "Largest difference that counts as equal (default: the machine's "
                   "threading.tolerance, else one least increment of Z)")
      ->check(CLI::PositiveNumber);
  return verify;
}

int run_verify_command(const VerifyCommand& c) {
  Machine m;
  if (!load(c.machine, m)) return kExitUsage;
  if (c.cl.empty() && c.plan.empty()) {
    print_err("clpost verify: error: give the plan: --cl INPUT.cl or --plan PLAN.json\n");
    return kExitUsage;
  }
  VerifyOutcome v = verify_files(c.nc, c.cl, c.plan, m, c.tolerance);
  print_out(v.report);
  print_err(v.diagnostics);
  return v.ok ? kExitOk : kExitInput;
}

// `clpost plot`: the SVG backplot and thread sections.
struct PlotCommand {
  MachineOpts machine;
  PlotRequest req;
};

CLI::App* add_plot_command(CLI::App& app, PlotCommand& c) {
  CLI::App* plot = app.add_subcommand(
      "plot", "SVG pictures: the backplot of a program and the cross-section of every thread");
  c.req.output = "-";
  add_machine_opts(*plot, c.machine);
  plot->add_option("input", c.req.input,
                   "A CL file (its plan, posted on the machine) or an NC program")
      ->required();
  plot->add_option("--cl", c.req.cl,
                   "With an NC program: the CL file of its plan (for the thread sections)");
  plot->add_option("-o,--output", c.req.output, "SVG file (default: standard output)");
  plot->add_option("--thread", c.req.thread, "Only thread N's cross-section (1 = the first)")
      ->check(CLI::PositiveNumber);
  plot->add_flag("--full", c.req.full,
                 "Draw every move and every thread's section (by default moves shorter than the "
                 "picture can show are merged and identical threads drawn once)");
  return plot;
}

int run_plot_command(const PlotCommand& c) {
  Machine m;
  if (!load(c.machine, m)) return kExitUsage;
  PlotRequest req = c.req;
  req.machine = &m;
  PlotOutcome r = plot_file(req);
  print_err(r.diagnostics);
  return r.ok ? kExitOk : kExitInput;
}

}  // namespace

int run_cli(int argc, char** argv) {
  CLI::App app{"clpost: APT/CL to NC post-processor for CNC lathes, built for threading", "clpost"};
  app.footer(kFooter);
  app.set_version_flag("--version", std::string("clpost ") + CLPOST_VERSION);
  app.require_subcommand(0, 1);

  PostCommand post;
  add_post_command(app, post);
  MachinesCommand machines;
  add_machines_command(app, machines);
  CLI::App* schema =
      app.add_subcommand("schema", "The JSON Schema of machine and post files (draft 2020-12)");
  bool schema_md = false;
  schema->add_flag("--markdown", schema_md, "The key tables of docs/machines.md instead");
  CheckCommand check_cmd;
  CLI::App* check = add_check_command(app, check_cmd);
  PlanCommand plan_cmd;
  CLI::App* plan = add_plan_command(app, plan_cmd);
  VerifyCommand verify_cmd;
  CLI::App* verify = add_verify_command(app, verify_cmd);
  PlotCommand plot_cmd;
  CLI::App* plot = add_plot_command(app, plot_cmd);
  SheetCommand sheet_cmd;
  CLI::App* sheet = add_sheet_command(app, sheet_cmd);
  Cl2AptRequest cl2apt_req;
  CLI::App* cl2apt = add_cl2apt_command(app, cl2apt_req);

  try {
    app.parse(argc, argv);
  } catch (const CLI::ParseError& e) {
    int code = app.exit(e);
    return code == 0 ? kExitOk : kExitUsage;
  }

  if (*machines.list) return run_machines_command(machines);
  if (*schema) return print_command_output(schema_command(schema_md));
  if (*cl2apt) return run_cl2apt_command(cl2apt_req);
  if (*verify) return run_verify_command(verify_cmd);
  if (*plot) return run_plot_command(plot_cmd);
  if (*sheet) return run_sheet_command(sheet_cmd);
  if (*check) return run_check_command(check_cmd);
  if (*plan) return run_plan_command(plan_cmd);
  return run_post_command(app, post);
}

}  // namespace clpost

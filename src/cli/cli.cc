#include "cli/cli.h"

#include <fmt/format.h>
#include <unistd.h>

#include <CLI/CLI.hpp>
#include <algorithm>
#include <cerrno>
#include <chrono>
#include <cstdio>
#include <cstring>
#include <filesystem>
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
#include "cli/verify_command.h"
#include "emitters/emitter.h"
#include "machine/machine_loader.h"
#include "planner/plan_format.h"
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
  if (load_machine(o.machine, data_dirs(), o.sets, m, errors)) return true;
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

  bool used(const CLI::App& app) const {
    for (const char* name : {"-r", "-j", "--keep-going", "--quiet", "--report"})
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
}

// Problems found before anything is posted (usage, the output directory) exit 2; failed files
// exit 1.
int run_batch_command(const MachineOpts& mo, const BatchOpts& b, bool strict, bool verify,
                      const std::vector<std::string>& args) {
  namespace fs = std::filesystem;
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
  std::error_code ec;
  fs::create_directories(b.out_dir, ec);
  if (ec || !fs::is_directory(b.out_dir, ec)) {
    print_err(fmt::format("clpost: error: cannot create the output directory '{}': {}\n", b.out_dir,
                          ec ? ec.message() : "not a directory"));
    return kExitUsage;
  }
  if (::access(b.out_dir.c_str(), W_OK | X_OK) != 0) {
    print_err(fmt::format("clpost: error: cannot write to the output directory '{}': {}\n",
                          b.out_dir, std::strerror(errno)));
    return kExitUsage;
  }

  BatchSettings settings;
  settings.jobs = b.jobs != 0 ? b.jobs : std::max(1u, std::thread::hardware_concurrency());
  settings.keep_going = b.keep_going;
  settings.post = PostOptions{strict};
  settings.verify = verify;
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
  if (!b.report.empty()) {
    const std::string json =
        batch_report_json(BatchReportInfo{m.name, b.out_dir, settings.jobs}, summary, results);
    OutputFile report;
    if (!report.open(b.report, err) || (report.write(json), !report.commit(err))) {
      print_err(fmt::format("clpost: error: cannot write the report: {}\n", err));
      rc = kExitInput;
    }
  }
  return rc;
}

}  // namespace

int run_cli(int argc, char** argv) {
  CLI::App app{"clpost: APT/CL to NC post-processor for CNC lathes, built for threading", "clpost"};
  app.footer(kFooter);
  app.set_version_flag("--version", std::string("clpost ") + CLPOST_VERSION);
  app.require_subcommand(0, 1);

  MachineOpts post_opts;
  std::vector<std::string> inputs;
  std::string output;
  bool strict = false;
  BatchOpts batch;
  add_machine_opts(app, post_opts);
  app.add_option("-o,--output", output, "Output file (default: standard output)");
  app.add_flag("--strict", strict, "Unknown CL statements are errors, not warnings");
  add_batch_opts(app, batch);
  bool verify_post = false;
  app.add_flag("--verify", verify_post,
               "Read the program back through the control's laws and check it cuts the plan; "
               "a program that does not is an error (nothing written)");
  app.add_option("inputs", inputs,
                 "CL file to post ('-' for standard input); with -d: files and directories");

  CLI::App* machines = app.add_subcommand("machines", "List the shipped machines");
  CLI::App* show = machines->add_subcommand("show", "A machine exactly as loaded: every key");
  MachineOpts show_opts;
  bool show_origin = false;
  show->add_option("machine", show_opts.machine, "Shipped machine name or machine file")
      ->required();
  show->add_option("--set", show_opts.sets, "Override a machine key")->type_name("KEY=VALUE");
  show->add_flag("--origin", show_origin, "Where each value came from (file:line, --set, default)");
  CLI::App* diff = machines->add_subcommand("diff", "The keys whose values differ");
  std::string diff_a, diff_b;
  diff->add_option("a", diff_a, "Machine name or file")->required();
  diff->add_option("b", diff_b, "Machine name or file")->required();

  CLI::App* schema =
      app.add_subcommand("schema", "The JSON Schema of machine and post files (draft 2020-12)");
  bool schema_md = false;
  schema->add_flag("--markdown", schema_md, "The key tables of docs/machines.md instead");

  CLI::App* check = app.add_subcommand("check", "Parse and validate CL files without writing");
  MachineOpts check_opts;
  std::vector<std::string> check_inputs;
  bool check_strict = false;
  add_machine_opts(*check, check_opts);
  check->add_flag("--strict", check_strict, "Unknown CL statements are errors");
  check->add_option("inputs", check_inputs, "CL files")->required();

  CLI::App* plan = app.add_subcommand("plan", "Print the thread pass plans of CL files");
  MachineOpts plan_opts;
  std::vector<std::string> plan_inputs;
  std::string plan_format = "text";
  add_machine_opts(*plan, plan_opts);
  plan->add_option("--format", plan_format, "text or json")->check(CLI::IsMember({"text", "json"}));
  plan->add_option("inputs", plan_inputs, "CL files")->required();

  CLI::App* verify =
      app.add_subcommand("verify", "Check that an NC program cuts the thread plan of a CL file");
  MachineOpts verify_opts;
  std::string verify_nc, verify_cl, verify_plan;
  double verify_tolerance = 0;
  add_machine_opts(*verify, verify_opts);
  verify->add_option("program", verify_nc, "NC program in the machine's dialect ('-': stdin)")
      ->required();
  CLI::Option* cl_opt = verify->add_option("--cl", verify_cl, "The CL file the plan comes from");
  CLI::Option* plan_opt = verify->add_option(
      "--plan", verify_plan, "The plan as `clpost plan --format json` wrote it (instead of --cl)");
  cl_opt->excludes(plan_opt);
  verify
      ->add_option("--tolerance", verify_tolerance,
                   "Largest difference that counts as equal (default: the machine's "
                   "threading.tolerance, else one least increment of Z)")
      ->check(CLI::PositiveNumber);

  CLI::App* plot = app.add_subcommand(
      "plot", "SVG pictures: the backplot of a program and the cross-section of every thread");
  MachineOpts plot_opts;
  PlotRequest plot_req;
  plot_req.output = "-";
  add_machine_opts(*plot, plot_opts);
  plot->add_option("input", plot_req.input,
                   "A CL file (its plan, posted on the machine) or an NC program")
      ->required();
  plot->add_option("--cl", plot_req.cl,
                   "With an NC program: the CL file of its plan (for the thread sections)");
  plot->add_option("-o,--output", plot_req.output, "SVG file (default: standard output)");
  plot->add_option("--thread", plot_req.thread, "Only thread N's cross-section (1 = the first)")
      ->check(CLI::PositiveNumber);

  Cl2AptRequest cl2apt_req;
  CLI::App* cl2apt = add_cl2apt_command(app, cl2apt_req);

  try {
    app.parse(argc, argv);
  } catch (const CLI::ParseError& e) {
    int code = app.exit(e);
    return code == 0 ? kExitOk : kExitUsage;
  }

  if (*show) {
    CommandOutput r = machines_show(show_opts.machine, show_opts.sets, show_origin, data_dirs());
    print_out(r.out);
    print_err(r.err);
    return r.exit_code;
  }
  if (*diff) {
    CommandOutput r = machines_diff(diff_a, diff_b, data_dirs());
    print_out(r.out);
    print_err(r.err);
    return r.exit_code;
  }
  if (*machines) {
    // Each machine is loaded in full, so a broken file shows here rather than mid-batch.
    int rc = kExitOk;
    for (const MachineInfo& mi : list_machines(data_dirs())) {
      Machine m;
      std::string errors;
      if (!load_machine(mi.path, data_dirs(), {}, m, errors)) {
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

  if (*schema) {
    CommandOutput r = schema_command(schema_md);
    print_out(r.out);
    print_err(r.err);
    return r.exit_code;
  }

  if (*cl2apt) return run_cl2apt_command(cl2apt_req);

  if (*verify) {
    Machine m;
    if (!load(verify_opts, m)) return kExitUsage;
    if (verify_cl.empty() && verify_plan.empty()) {
      print_err("clpost verify: error: give the plan: --cl INPUT.cl or --plan PLAN.json\n");
      return kExitUsage;
    }
    VerifyOutcome v = verify_files(verify_nc, verify_cl, verify_plan, m, verify_tolerance);
    print_out(v.report);
    print_err(v.diagnostics);
    return v.ok ? kExitOk : kExitInput;
  }

  if (*plot) {
    Machine m;
    if (!load(plot_opts, m)) return kExitUsage;
    plot_req.machine = &m;
    PlotOutcome r = plot_file(plot_req);
    print_err(r.diagnostics);
    return r.ok ? kExitOk : kExitInput;
  }

  if (*check) {
    Machine m;
    if (!load(check_opts, m)) return kExitUsage;
    int rc = kExitOk;
    for (const std::string& in : check_inputs) {
      PostRequest req{in, "", &m, PostOptions{check_strict}, nullptr};
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

  if (*plan) {
    Machine m;
    if (!load(plan_opts, m)) return kExitUsage;
    int rc = kExitOk;
    std::string out;
    bool json = plan_format == "json";
    if (json && plan_inputs.size() > 1) out += "[\n";
    for (size_t i = 0; i < plan_inputs.size(); ++i) {
      std::vector<ThreadPlan> plans;
      PostRequest req{plan_inputs[i], "", &m, PostOptions{},
                      [&](const ThreadPlan& p) { plans.push_back(p); }};
      PostOutcome r = post_file(req);
      print_err(r.diagnostics);
      if (!r.ok) {
        rc = kExitInput;
        continue;
      }
      std::string name = display_name(plan_inputs[i]);
      if (json) {
        if (i > 0 && plan_inputs.size() > 1 && out.size() > 2) out += ",\n";
        out += plan_to_json(name, r.units, plans);
      } else {
        out += plan_to_text(name, r.units, plans);
      }
    }
    if (json && plan_inputs.size() > 1) out += "\n]\n";
    print_out(out);
    return rc;
  }

  if (inputs.empty()) {
    print_err(app.help());
    print_err("\nclpost: error: no input file (use '-' for standard input)\n");
    return kExitUsage;
  }
  if (!batch.out_dir.empty() || batch.used(app)) {
    if (batch.out_dir.empty()) {
      print_err("clpost: error: -r, -j, --keep-going, --quiet and --report need -d OUTDIR\n");
      return kExitUsage;
    }
    if (!output.empty()) {
      print_err("clpost: error: -o and -d cannot be used together\n");
      return kExitUsage;
    }
    return run_batch_command(post_opts, batch, strict, verify_post, inputs);
  }
  if (inputs.size() > 1) {
    print_err("clpost: error: several inputs need an output directory: -d OUTDIR\n");
    return kExitUsage;
  }
  Machine m;
  if (!load(post_opts, m)) return kExitUsage;
  PostRequest req{inputs[0], output.empty() ? "-" : output, &m, PostOptions{strict}, nullptr};
  req.verify = verify_post;
  PostOutcome r = post_file(req);
  print_err(r.verify_report);
  print_err(r.diagnostics);
  return r.ok ? kExitOk : kExitInput;
}

}  // namespace clpost

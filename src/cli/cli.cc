#include "cli/cli.h"

#include <fmt/format.h>
#include <unistd.h>

#include <CLI/CLI.hpp>
#include <cstdio>
#include <string>
#include <vector>

#include "cli/data_dirs.h"
#include "cli/post_file.h"
#include "emitters/emitter.h"
#include "machine/machine_loader.h"
#include "planner/plan_format.h"

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
  clpost machines                         list the shipped machines

Exit status: 0 ok, 1 errors in the input, 2 usage or machine-file errors.)";

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

}  // namespace

int run_cli(int argc, char** argv) {
  CLI::App app{"clpost: APT/CL to NC post-processor for CNC lathes, built for threading", "clpost"};
  app.footer(kFooter);
  app.set_version_flag("--version", std::string("clpost ") + CLPOST_VERSION);
  app.require_subcommand(0, 1);

  MachineOpts post_opts;
  std::string input, output;
  bool strict = false;
  add_machine_opts(app, post_opts);
  app.add_option("-o,--output", output, "Output file (default: standard output)");
  app.add_flag("--strict", strict, "Unknown CL statements are errors, not warnings");
  app.add_option("input", input, "CL file to post ('-' for standard input)");

  CLI::App* machines = app.add_subcommand("machines", "List the shipped machines");

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

  try {
    app.parse(argc, argv);
  } catch (const CLI::ParseError& e) {
    int code = app.exit(e);
    return code == 0 ? kExitOk : kExitUsage;
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
      print_out(fmt::format("{:<18} {:<5} {:<34} {}\n", mi.name, m.extension, threading_summary(m),
                            m.description));
    }
    return rc;
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

  if (input.empty()) {
    print_err(app.help());
    print_err("\nclpost: error: no input file (use '-' for standard input)\n");
    return kExitUsage;
  }
  Machine m;
  if (!load(post_opts, m)) return kExitUsage;
  PostRequest req{input, output.empty() ? "-" : output, &m, PostOptions{strict}, nullptr};
  PostOutcome r = post_file(req);
  print_err(r.diagnostics);
  return r.ok ? kExitOk : kExitInput;
}

}  // namespace clpost

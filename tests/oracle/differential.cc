#include "differential.h"

#include <fcntl.h>
#include <stdlib.h>
#include <sys/file.h>
#include <sys/wait.h>
#include <unistd.h>

#include <algorithm>
#include <chrono>
#include <cstdio>
#include <filesystem>
#include <fstream>
#include <sstream>

#include "canon.h"
#include "controls/registry.h"
#include "fanuc_reader.h"
#include "generator.h"
#include "heidenhain_reader.h"
#include "interpreter/post.h"
#include "machine/machine_loader.h"
#include "model.h"
#include "sinumerik_reader.h"

namespace oracle {

namespace {

std::string read_text(const std::string& path) {
  std::ifstream in(path, std::ios::binary);
  std::ostringstream ss;
  ss << in.rdbuf();
  return ss.str();
}

struct Output {
  int exit_code = -1;
  std::string out, err;
};

// rs274 crashes when two run at once: every rs274 on this machine runs under one lock,
// /tmp/clpost-rs274.lock (tests/test_util.h; by hand, `flock /tmp/clpost-rs274.lock rs274 …`),
// which the oracle takes for each run and no longer.
class Rs274Lock {
 public:
  Rs274Lock() : fd_(::open("/tmp/clpost-rs274.lock", O_RDWR | O_CREAT | O_CLOEXEC, 0666)) {
    if (fd_ >= 0) ::flock(fd_, LOCK_EX);
  }
  ~Rs274Lock() {
    if (fd_ >= 0) ::close(fd_);
  }
  Rs274Lock(const Rs274Lock&) = delete;
  Rs274Lock& operator=(const Rs274Lock&) = delete;

 private:
  int fd_;
};

// `rs274 -t table [-b] -g ngc` in `dir`, its output and errors collected in files there.
Output rs274(const std::string& dir, const std::string& table, const std::string& ngc, bool bd) {
  const std::string out = dir + "/canon.out", err = dir + "/canon.err";
  Output r;
  {
    Rs274Lock lock;
    const pid_t pid = ::fork();
    if (pid == 0) {
      const int in = ::open("/dev/null", O_RDONLY);
      const int o = ::open(out.c_str(), O_WRONLY | O_CREAT | O_TRUNC, 0644);
      const int e = ::open(err.c_str(), O_WRONLY | O_CREAT | O_TRUNC, 0644);
      if (in < 0 || o < 0 || e < 0 || ::chdir(dir.c_str()) != 0) ::_exit(126);
      ::dup2(in, 0), ::dup2(o, 1), ::dup2(e, 2);
      if (bd)
        ::execlp("rs274", "rs274", "-t", table.c_str(), "-b", "-g", ngc.c_str(), nullptr);
      else
        ::execlp("rs274", "rs274", "-t", table.c_str(), "-g", ngc.c_str(), nullptr);
      ::_exit(127);
    }
    int status = 0;
    if (pid > 0 && ::waitpid(pid, &status, 0) == pid)
      r.exit_code = WIFEXITED(status) ? WEXITSTATUS(status) : 128 + WTERMSIG(status);
  }
  r.out = read_text(out);
  r.err = read_text(err);
  return r;
}

// The first line of rs274's errors that says something ("executing" is its banner).
std::string first_error(const std::string& err) {
  std::istringstream in(err);
  std::string line;
  while (std::getline(in, line))
    if (!line.empty() && line != "executing") return line;
  return "no message";
}

// The message of clpost's first error.
std::string first_post_error(const std::string& diags) {
  const size_t at = diags.find("error: ");
  if (at == std::string::npos) return "no message";
  const size_t end = diags.find('\n', at);
  return diags.substr(at + 7, end == std::string::npos ? std::string::npos : end - at - 7);
}

}  // namespace

bool rs274_installed() {
  return std::system("command -v rs274 >/dev/null 2>&1") == 0;
}

bool control_named(const std::string& name, Control& c) {
  for (Control k : {Control::kLinuxcnc, Control::kFanuc, Control::kHaas, Control::kHeidenhain,
                    Control::kNct, Control::kSinumerik})
    if (name == control_name(k)) return c = k, true;
  return false;
}

const char* control_name(Control c) {
  switch (c) {
    case Control::kLinuxcnc:
      return "linuxcnc";
    case Control::kFanuc:
      return "fanuc";
    case Control::kHaas:
      return "haas";
    case Control::kHeidenhain:
      return "heidenhain";
    case Control::kNct:
      return "nct";
    case Control::kSinumerik:
      return "sinumerik";
  }
  return "?";
}

const char* machine_of(Control c) {
  switch (c) {
    case Control::kLinuxcnc:
      return "linuxcnc-lathe";
    case Control::kFanuc:
      return "fanuc-0i-t";
    case Control::kHaas:
      return "haas-st";
    case Control::kHeidenhain:
      return "heidenhain-pilot";
    case Control::kNct:
      return "nct-2000t";
    case Control::kSinumerik:
      return "sinumerik-840d";
  }
  return "?";
}

Dialect dialect_of(Control c) {
  return c == Control::kHaas  ? Dialect::kHaas
         : c == Control::kNct ? Dialect::kNct
                              : Dialect::kFanuc;
}

bool Differential::init(const std::string& source_dir, std::string& error, Control control,
                        const std::string& machine) {
  control_ = control;
  const std::string name = machine.empty() ? machine_of(control) : machine;
  if (!clpost::load_machine(name, {source_dir}, {}, clpost::shipped_controls(), machine_, error))
    return false;
  // Fanuc, Haas and NCT: IS-B, 0.001 mm and 0.0001 in; HEIDENHAIN: 1 µm, 0.0001 in
  // (docs/cl-meaning.md, "Inch output"; NCT 99M manual, "Specification and Value Range of
  // Coordinate Data"); SINUMERIK: what sinumerik-840d writes, 0.001 mm and 0.0001 in.
  if (control != Control::kLinuxcnc) resolution_ = {0.001, 0.0001};
  table_ = source_dir + "/tests/oracle/data/offsets.tbl";
  std::string templ = (std::filesystem::temp_directory_path() / "clpost-oracle-XXXXXX").string();
  if (!::mkdtemp(templ.data())) {
    error = "cannot make a temporary directory";
    return false;
  }
  dir_ = templ;
  return true;
}

Differential::~Differential() {
  if (!dir_.empty()) std::filesystem::remove_all(dir_);
}

Differential::Run Differential::run_rs274(const ProgramResult& r, bool block_delete) {
  const Output o = rs274(dir_, table_, "oracle.ngc", block_delete);
  Run run = compare_run(r, block_delete, canon_events(o.out),
                        o.exit_code == 0 ? "" : "rs274 error: " + first_error(o.err));
  run.exit_code = o.exit_code;
  run.err = o.err;
  return run;
}

Differential::Run Differential::run_reader(const ProgramResult& r, bool block_delete) {
  // HEIDENHAIN: the program's unit is control parameter 1, the machine's (heidenhain_reader.h).
  const ControlRun o = control_ == Control::kHeidenhain
                           ? heidenhain_events(r.nc, block_delete, machine_.default_units == "in")
                       : control_ == Control::kSinumerik
                           ? sinumerik_events(r.nc, block_delete)
                           : fanuc_events(r.nc, dialect_of(control_), block_delete);
  const std::string stop =
      o.error.empty() ? "" : std::string(control_name(control_)) + " error: " + o.error;
  Run run = compare_run(r, block_delete, o.events, stop);
  run.exit_code = o.error.empty() ? 0 : 1;
  if (!o.error.empty()) run.err = "NC line " + std::to_string(o.error_line) + ": " + o.error;
  return run;
}

// The model's events against `got`; `stop`: why the run stopped before the program's end ("" when
// it ran to it), the difference where the events stop lining up.
Differential::Run Differential::compare_run(const ProgramResult& r, bool block_delete,
                                            const std::vector<Event>& got,
                                            const std::string& stop) {
  Run run;
  std::vector<Event> want;
  for (size_t i = 0; i < r.model.size(); ++i)
    if (!block_delete || !r.model[i].skipped) want.push_back(r.model[i]), run.to_model.push_back(i);
  run.c = compare_events(want, got, block_delete, resolution_);
  run.events = got.size();
  if (stop.empty() || run.c.lined_up != got.size()) return run;
  std::vector<Found>& f = run.c.found;
  if (!f.empty() && f.back().d.field == "missing event") f.pop_back();
  Difference d;
  d.found = true;
  d.index = got.size();
  d.field = without_numbers(stop);
  d.detail = "the run stops after " + std::to_string(got.size()) + " events";
  d.have_model = got.size() < want.size();
  if (d.have_model) d.model = want[got.size()];
  d.klass = d.have_model ? class_of(d.field, d.model, block_delete) : d.field;
  f.push_back({d, d.have_model ? class_of(d.field, d.model, false) : d.field});
  return run;
}

namespace {

// Whether the run with block delete off shows the difference `f` of the run with it on: at the
// same CL event where both runs line up, else by its class.
bool also_without_block_delete(const Found& f, size_t model_index, const Differential::Run& off,
                               const std::vector<std::string>& classes) {
  if (model_index >= off.c.lined_up)
    return std::find(classes.begin(), classes.end(), f.plain) != classes.end();
  return std::any_of(off.c.found.begin(), off.c.found.end(), [&](const Found& g) {
    return g.d.index == model_index && g.d.field == f.d.field;
  });
}

}  // namespace

// Adds what `run` shows to `r`: every class once; with block delete on, only what the run with
// it off does not show (the ranges' own differences).
void Differential::add(ProgramResult& r, const Run& run, bool block_delete, const Run* off) {
  if (run.c.found.empty() && run.exit_code == 0) return;
  RunDifference d{block_delete, "", {}, ""};
  for (const Found& f : run.c.found) {
    const size_t at = f.d.index < run.to_model.size() ? run.to_model[f.d.index] : r.model.size();
    if (block_delete && off && also_without_block_delete(f, at, *off, r.classes)) continue;
    const std::string k = f.d.klass + (block_delete ? " (block delete on)" : "");
    if (d.klass.empty()) d.klass = k, d.first = f.d;
    if (std::find(r.classes.begin(), r.classes.end(), k) == r.classes.end()) r.classes.push_back(k);
  }
  if (d.klass.empty()) return;  // nothing of its own
  if (run.exit_code != 0)
    d.message = control_ == Control::kLinuxcnc
                    ? "rs274 exit status " + std::to_string(run.exit_code) + ": " + run.err
                    : run.err;
  if (!r.differs) r.klass = d.klass;
  r.differs = true;
  r.runs.push_back(std::move(d));
}

ProgramResult Differential::check(uint32_t seed) {
  ProgramResult r;
  r.seed = seed;
  r.control = control_;
  r.machine = machine_.name;
  r.cl = generate_program(seed, control_ == Control::kNct);  // NCT says TPI: G33 E
  const bool home = machine_.templates.count("home") > 0;
  ModelResult m = model_events(r.cl, {machine_.default_units == "in", machine_.max_rpm, home});
  r.model = std::move(m.events);
  if (!m.error.empty()) {
    r.differs = true;
    r.klass = "the model cannot read the generated program";
    r.classes = {r.klass};
    r.message = m.error;
    return r;
  }
  const std::string name = "seed-" + std::to_string(seed) + ".cl";
  clpost::PostedText p = clpost::post_text(r.cl, machine_, name);
  r.nc = p.program;
  if (p.diags.has_errors()) {
    r.message = p.diags.render_all();
    // A located error ("seed-N.cl:line:col: error: …") is the control refusing what the CL
    // asks; any other stop is a difference.
    const size_t at = r.message.find(": error: ");
    const size_t line = at == std::string::npos ? 0 : r.message.rfind('\n', at) + 1;
    r.refused =
        at != std::string::npos && r.message.compare(line, name.size() + 1, name + ":") == 0;
    r.differs = !r.refused;
    r.klass = "clpost error: " + without_numbers(first_post_error(r.message));
    r.classes = {r.klass};
    return r;
  }
  const bool optional = r.nc.find("\n/") != std::string::npos;
  if (control_ != Control::kLinuxcnc) {
    const Run off = run_reader(r, false);
    add(r, off, false, nullptr);
    if (optional) add(r, run_reader(r, true), true, &off);
    return r;
  }
  std::ofstream(dir_ + "/oracle.ngc", std::ios::binary) << r.nc;
  const Run off = run_rs274(r, false);
  add(r, off, false, nullptr);
  if (optional) add(r, run_rs274(r, true), true, &off);
  return r;
}

Summary Differential::run(uint32_t first, int count, double seconds) {
  Summary s;
  s.control = control_;
  s.machine = machine_.name;
  const auto start = std::chrono::steady_clock::now();
  auto elapsed = [&] {
    return std::chrono::duration<double>(std::chrono::steady_clock::now() - start).count();
  };
  for (uint32_t seed = first;
       (count <= 0 || s.programs < count) && (seconds <= 0 || elapsed() < seconds); ++seed) {
    ProgramResult r = check(seed);
    ++s.programs;
    if (r.refused && s.refusals[r.klass].programs++ == 0) s.refusals[r.klass].first_seed = seed;
    s.refused += r.refused ? 1 : 0;
    if (!r.differs) continue;
    ++s.differing;
    for (const std::string& k : r.classes)
      if (s.classes[k].programs++ == 0) s.classes[k].first_seed = seed;
    const auto first = s.classes.find(r.klass);
    if (first != s.classes.end() && first->second.first_seed == seed)
      s.firsts.push_back(std::move(r));
  }
  s.seconds = elapsed();
  return s;
}

}  // namespace oracle

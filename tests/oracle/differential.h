#pragma once
// The differential test: a generated CL program, posted by clpost on a control's machine (through
// the library, post_text()), run with block delete off and — when the program has a block to
// delete — on, and the run's events compared with the model's. LinuxCNC's programs run through
// its own interpreter (rs274); Fanuc's, Haas's and NCT's through the oracle's reader of their
// documented meanings (fanuc_reader.h), HEIDENHAIN DIN's through heidenhain_reader.h, SINUMERIK's
// through sinumerik_reader.h. The only place where the oracle touches clpost.
#include <cstdint>
#include <map>
#include <string>
#include <vector>

#include "compare.h"
#include "events.h"
#include "fanuc_reader.h"
#include "machine/machine.h"

namespace oracle {

// The controls the oracle runs programs on, and the machine each posts for.
enum class Control { kLinuxcnc, kFanuc, kHaas, kHeidenhain, kNct, kSinumerik };
// "linuxcnc", "fanuc", "haas", "heidenhain", "nct", "sinumerik"
bool control_named(const std::string& name, Control& c);
const char* control_name(Control c);
// linuxcnc-lathe, fanuc-0i-t, haas-st, heidenhain-pilot, nct-2000t, sinumerik-840d
const char* machine_of(Control c);
Dialect dialect_of(Control c);  // the Fanuc reader's dialect (kFanuc where it does not read)

// The first difference of one run.
struct RunDifference {
  bool block_delete = false;
  std::string klass;
  Difference first;     // when the events differ
  std::string message;  // rs274's errors
};

struct ProgramResult {
  uint32_t seed = 0;
  Control control = Control::kLinuxcnc;
  std::string machine;
  std::string cl, nc;
  std::vector<Event> model;
  bool differs = false;
  bool refused = false;              // clpost stopped with a located error (not a difference)
  std::string klass;                 // the class of its first difference, or of the refusal
  std::vector<std::string> classes;  // every class of difference it shows
  std::string message;               // clpost's errors, or the model's
  std::vector<RunDifference> runs;   // the runs that differ, block delete off first
};

struct ClassCount {
  int programs = 0;
  uint32_t first_seed = 0;
};

struct Summary {
  Control control = Control::kLinuxcnc;
  std::string machine;
  int programs = 0, differing = 0, refused = 0;
  double seconds = 0;
  std::map<std::string, ClassCount> classes;
  std::map<std::string, ClassCount> refusals;  // by clpost's message
  std::vector<ProgramResult> firsts;  // the first program whose first difference is of a class
};

class Differential {
 public:
  // `source_dir`: the source tree (machines, posts, tests/oracle/data/offsets.tbl). False (with
  // the reason in `error`) when the control's machine does not load.
  // `machine`: another shipped machine of the control than machine_of(control).
  bool init(const std::string& source_dir, std::string& error, Control control = Control::kLinuxcnc,
            const std::string& machine = "");
  ~Differential();

  ProgramResult check(uint32_t seed);
  // Seeds first, first + 1, … until `count` programs or `seconds` have run (0: no limit).
  Summary run(uint32_t first, int count, double seconds);

  // One rs274 run of the program and its comparison with the model.
  struct Run {
    Comparison c;
    std::vector<size_t> to_model;  // each compared event's index among all the model's events
    size_t events = 0;             // rs274's
    int exit_code = 0;
    std::string err;
  };

 private:
  Run run_rs274(const ProgramResult& r, bool block_delete);
  Run run_reader(const ProgramResult& r, bool block_delete);
  Run compare_run(const ProgramResult& r, bool block_delete, const std::vector<Event>& got,
                  const std::string& stop);
  void add(ProgramResult& r, const Run& run, bool block_delete, const Run* off);

  Control control_ = Control::kLinuxcnc;
  Resolution resolution_;
  clpost::Machine machine_;
  std::string table_, dir_;
};

bool rs274_installed();
// Everything needed to see a difference: seed, class, the CL and NC programs with line numbers,
// the model's and rs274's events.
std::string report(const ProgramResult& r);
std::string summary_text(const Summary& s);

}  // namespace oracle

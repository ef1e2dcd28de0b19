#pragma once
// Loading and validating machine definitions. A machine file `machines/<name>.yaml` names the
// post (control dialect) it `extends`, `posts/<post>.yaml`; the post's keys are read first, then
// the machine's, then command-line overrides (`--set key.path=value`). Every problem is a
// diagnostic `file.yaml:line:col: error: ...`.
#include <map>
#include <string>
#include <string_view>
#include <vector>

#include "machine/machine.h"

namespace clpost {

struct MachineInfo {
  std::string name;
  std::string description;
  std::string path;
};

// Where each key's value came from, by dotted path ("formats.X.decimals"): "FILE:LINE" of the
// post or machine file, or "--set". A key that is not in it has the Machine's default.
using KeyOrigins = std::map<std::string, std::string>;

// `name_or_path`: a shipped machine name (looked up as <dir>/machines/<name>.yaml in each of
// `data_dirs`, first match wins) or a path to a YAML file (contains '/' or ends in .yaml/.yml).
// On failure returns false and `errors` holds the rendered diagnostics. The machine's schema is
// that of `controls` (the set the program was given: the cli's are the registry's, a test may
// bring its own), and threading.cycle selects one of them.
bool load_machine(std::string_view name_or_path, const std::vector<std::string>& data_dirs,
                  const std::vector<std::string>& overrides, ControlSet controls, Machine& out,
                  std::string& errors, KeyOrigins* origins = nullptr);

// Applies one YAML document (a post or a machine file) on top of `m`. `file` names it in
// diagnostics; `text` is its content; its schema is m.controls' (threading.cycle selects one of
// them). Exposed for tests.
bool apply_machine_yaml(std::string_view file, std::string_view text, bool is_post, Machine& m,
                        std::string& errors, KeyOrigins* origins = nullptr);

// Every shipped machine in `data_dirs` (sorted by name; a name found twice: first dir wins).
std::vector<MachineInfo> list_machines(const std::vector<std::string>& data_dirs);

}  // namespace clpost

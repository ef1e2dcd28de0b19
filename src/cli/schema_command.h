#pragma once
// `clpost schema`: the declared schema of machine and post files (machine/machine_schema.h) as a
// JSON Schema (draft 2020-12) for editors and validators, or with --markdown as the tables of
// docs/machines.md.
#include <string>

namespace clpost {

// What a command prints and its exit status.
struct CommandOutput {
  int exit_code = 0;
  std::string out;
  std::string err;
};

CommandOutput schema_command(bool markdown);

}  // namespace clpost

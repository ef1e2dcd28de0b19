#include "cli/schema_command.h"

#include "controls/registry.h"
#include "machine/machine_schema.h"
#include "machine/schema_json.h"
#include "machine/schema_markdown.h"

namespace clpost {

CommandOutput schema_command(bool markdown) {
  CommandOutput r;
  // The schema of the shipped controls' machine files.
  const Schema s = schema(shipped_controls());
  r.out = markdown ? schema_markdown(s) : schema_json(s);
  return r;
}

}  // namespace clpost

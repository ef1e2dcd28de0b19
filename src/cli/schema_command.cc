#include "cli/schema_command.h"

#include "machine/schema_json.h"
#include "machine/schema_markdown.h"

namespace clpost {

CommandOutput schema_command(bool markdown) {
  CommandOutput r;
  r.out = markdown ? schema_markdown() : schema_json();
  return r;
}

}  // namespace clpost

#include "cli/schema_command.h"

#include "machine/schema_markdown.h"

namespace clpost {

CommandOutput schema_command(bool markdown) {
  CommandOutput r;
  if (markdown) r.out = schema_markdown();
  return r;
}

}  // namespace clpost

#pragma once
// The declared schema (machine_schema.h) as a JSON Schema, draft 2020-12, for editors (the YAML
// language server) and validators: `clpost schema` prints it. Generated, so it never drifts
// from the loader: it accepts what the loader accepts (text keys take any scalar, booleans also
// yes/no/on/off) and refuses unknown keys, codes, formats, templates and template fields.
#include <string>

namespace clpost {

struct Schema;  // machine_schema.h

std::string schema_json(const Schema& s);

}  // namespace clpost

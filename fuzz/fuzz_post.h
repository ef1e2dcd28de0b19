#pragma once
// What the fuzz targets share: posting CL text on a machine the way `clpost` does (post_file.cc),
// into memory.
#include <cstdio>
#include <string>
#include <string_view>
#include <vector>

#include "interpreter/interpreter.h"
#include "machine/machine.h"
#include "machine/machine_loader.h"
#include "planner/plan_format.h"
#include "reader/cl_reader.h"
#include "support/diagnostics.h"
#include "support/sink.h"
#include "writer/nc_program.h"

namespace clpost::fuzz {

// A shipped machine; aborts when it does not load (the fuzz run would be meaningless).
inline Machine shipped_machine(const char* name) {
  Machine m;
  std::string errors;
  if (!load_machine(name, {CLPOST_SOURCE_DIR}, {}, m, errors)) {
    std::fprintf(stderr, "fuzz: cannot load machine %s:\n%s", name, errors.c_str());
    std::abort();
  }
  return m;
}

// Reads CL text from `in` (a ClReader over memory or a FILE*) and posts it on `m`, like
// post_file(): the NC program, the rendered diagnostics and the thread plans as text and JSON.
// Returns the number of errors.
// (Any reader with ClReader's next(), gave_up() and line(): the binary CLDATA target passes its
// own.)
template <class Reader>
size_t post(Reader& reader, Diagnostics& diags, const Machine& m, PostOptions opts,
            std::string* nc_out = nullptr) {
  StringSink sink;
  std::vector<ThreadPlan> plans;
  LengthUnit units = LengthUnit::kMm;
  {
    NcProgram prog(m, sink);
    Interpreter interp(m, prog, diags, opts);
    interp.on_thread([&](const ThreadPlan& p) {
      if (plans.size() < 64) plans.push_back(p);
    });
    Statement st;
    while (reader.next(st)) interp.statement(st);
    if (interp.stats().statements == 0 && !diags.has_errors()) {
      diags.error({}, {}, "no CL statements in the file");
    } else if (!reader.gave_up()) {
      interp.end_of_input(reader.line());
    }
    units = interp.units();
  }
  std::string text = diags.render_all();
  text += plan_to_text("fuzz.cl", units, plans);
  text += plan_to_json("fuzz.cl", units, plans);
  if (nc_out != nullptr) *nc_out = std::move(sink.out);
  return diags.error_count();
}

}  // namespace clpost::fuzz
